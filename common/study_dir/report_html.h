/* DIR/report.html: the interactive comparison page of a finished study folder
 * (README.md, "The comparison page"). One writer for compare, merge and
 * `fluidsurf report DIR`: it reads only the folder's files (the CSVs with their
 * provenance lines, report.md's label table, the PNGs' names) and embeds them in
 * the page as JSON beside the embedded script and style sheet (page/,
 * cmake/embed_report.cmake); the images are referenced by relative path. */
#ifndef FS_REPORT_HTML_H
#define FS_REPORT_HTML_H

/* Writes dir/report.html atomically. FS_ERR_INPUT, in one line, for a folder
 * that is not a finished study (no metrics.csv with a provenance line, or
 * another table without one). record: list it in dir's fluidsurf-outputs.txt
 * (outputs_list.h); the page is listed there anyway when the list exists. */
int fs_report_html_write(const char *dir, int record);

#endif
