/* Text fields written into CSV and JSON outputs, quoted once for every writer
 * (the study tables, counters.csv, diff --json, report.html's embedded data). */
#ifndef FS_TEXT_OUT_H
#define FS_TEXT_OUT_H
#include <stdio.h>

/* s as a CSV field: as it is, or in double quotes (quotes doubled) when it holds a
 * comma, a quote or a newline (RFC 4180). */
void fs_csv_text(FILE *f, const char *s);

/* s (NULL: "") as a JSON string: quotes, backslashes and control characters escaped,
 * and "</" as "<\/", so the text can sit inside an HTML <script> element. */
void fs_json_string(FILE *f, const char *s);

#endif
