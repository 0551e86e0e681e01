/* report.html from a study folder's files (report_html.h). The page's data is
 * the files' text, embedded as one JSON object; the script parses it, so the
 * numbers shown are the CSVs' own. */
#include "report_html.h"
#include "text_out.h"
#include "outputs_list.h"
#include "fs_error.h"
#include "output_file.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

extern const char fs_report_page_js[], fs_report_page_css[]; /* cmake/embed_report.cmake */

#define MAX_TEXT (256L << 20) /* a study's CSV larger than this is not one */

/* dir/name's whole text into *out (NUL-terminated); *out NULL when missing. */
static int slurp(const char *dir, const char *name, char **out)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f) return errno == ENOENT ? FS_OK : fs_fail(FS_ERR_INPUT, "%s: cannot read: %s", path, strerror(errno));
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (n < cap || cap >= (size_t)MAX_TEXT) break;
        char *b = realloc(buf, 2 * cap + 1);
        if (!b) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = b, cap *= 2;
    }
    int bad = ferror(f);
    fclose(f);
    if (!buf) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    if (bad || n >= (size_t)MAX_TEXT) {
        free(buf);
        return fs_fail(FS_ERR_INPUT, "%s: %s", path, bad ? "read failed" : "too large");
    }
    buf[n] = 0;
    *out = buf;
    return FS_OK;
}

/* A study table starts with fluidsurf's provenance line (study_tables.h). */
static int has_provenance(const char *text)
{
    return text && !strncmp(text, "# ", 2) && strstr(text, "commit=") && strchr(text, '\n');
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The folder's PNG names, sorted, as a JSON array. */
static int write_png_list(FILE *f, const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) return fs_fail(FS_ERR_INPUT, "%s: cannot list: %s", dir, strerror(errno));
    char **names = NULL;
    int n = 0, cap = 0, rc = FS_OK;
    for (struct dirent *e; (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".png") || e->d_name[0] == '.') continue;
        if (n == cap) {
            char **nn = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof *names);
            if (!nn) {
                rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
                break;
            }
            names = nn;
        }
        if (!(names[n] = strdup(e->d_name))) {
            rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
            break;
        }
        n++;
    }
    closedir(d);
    if (!rc && n > 1) qsort(names, n, sizeof *names, by_name); /* names is NULL when n == 0 */
    fputc('[', f);
    for (int i = 0; i < n; i++) {
        if (!rc) {
            if (i) fputc(',', f);
            fs_json_string(f, names[i]);
        }
        free(names[i]);
    }
    fputc(']', f);
    free(names);
    return rc;
}

static const char *const tables[] = {"metrics", "timings", "temporal", "counters"};
enum { NTABLES = 4 };

/* The page: the style sheet, the data, the script. */
static int write_page(FILE *f, const char *dir, char *const text[NTABLES], const char *report_md)
{
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self' file: data:; "
          "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n"
          "<title>fluidsurf study</title>\n<style>\n",
          f);
    fputs(fs_report_page_css, f);
    fputs(
        "</style>\n</head>\n<body>\n<div id=\"app\">This page needs JavaScript; the numbers are in metrics.csv.</div>\n"
        "<script id=\"fs-data\" type=\"application/json\">\n{",
        f);
    for (int t = 0; t < NTABLES; t++) {
        fprintf(f, "\"%s\":", tables[t]);
        if (text[t]) fs_json_string(f, text[t]);
        else fputs("null", f);
        fputs(",\n", f);
    }
    fputs("\"report_md\":", f);
    if (report_md) fs_json_string(f, report_md);
    else fputs("null", f);
    fputs(",\n\"pngs\":", f);
    int rc = write_png_list(f, dir);
    fputs("}\n</script>\n<script>\n", f);
    fputs(fs_report_page_js, f);
    fputs("</script>\n</body>\n</html>\n", f);
    return rc;
}

static int write_file(const char *dir, char *const text[NTABLES], const char *report_md, int record)
{
    char final[4200], list[4200];
    snprintf(final, sizeof final, "%s/report.html", dir);
    snprintf(list, sizeof list, "%s/%s", dir, FS_OUTPUTS_LIST);
    int rc = record || access(list, F_OK) == 0 ? fs_outputs_record(final) : FS_OK;
    static fs_output out;
    if (rc || (rc = fs_output_open(&out, final))) return rc;
    rc = write_page(out.f, dir, text, report_md);
    int crc = fs_output_close(&out, !rc);
    return rc ? rc : crc;
}

int fs_report_html_write(const char *dir, int record)
{
    char *text[NTABLES] = {0}, *md = NULL;
    int rc = FS_OK;
    for (int t = 0; t < NTABLES && !rc; t++) {
        char name[32];
        snprintf(name, sizeof name, "%s.csv", tables[t]);
        rc = slurp(dir, name, &text[t]);
        if (!rc && (t == 0 || text[t]) && !has_provenance(text[t]))
            rc = fs_fail(FS_ERR_INPUT, "%s: not a finished study (%s.csv %s)", dir, tables[t],
                         text[t] ? "has no provenance line" : "is missing");
    }
    if (!rc) rc = slurp(dir, "report.md", &md);
    if (!rc) rc = write_file(dir, text, md, record);
    for (int t = 0; t < NTABLES; t++) free(text[t]);
    free(md);
    return rc;
}
