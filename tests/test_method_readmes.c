/* The parameter help lives once, in each method's table; the READMEs' parameter
 * tables must agree with it. A parameter table is a Markdown table whose first
 * header cell is "parameter" or "name"; its rows name parameters in backticks in
 * the first cell, and the "default" column (else "ours") gives their defaults in
 * the same order: the next number for a number, the next on/off for a bool, the
 * next choice name for an enum. Every parameter must have a row, every named
 * one must exist, and each default must read as the table's (printed with %g).
 * The first part checks the checker on small texts, so it is known to fail. */
#include "fs_error.h"
#include "fs_test.h"
#include "method.h"
#include "builtin_methods.h"
#include <ctype.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAX_CELLS 16

/* Splits a table row "| a | b |" into trimmed cells (a '|' inside `code` does
 * not split); returns the count. Cells are written into buf. */
static int row_cells(const char *line, char *buf, size_t size, char *cells[MAX_CELLS])
{
    int n = 0, code = 0;
    size_t k = 0;
    if (*line++ != '|') return 0;
    cells[n] = buf;
    for (; *line && *line != '\n' && k + 1 < size; line++) {
        if (*line == '`') code = !code;
        if (*line == '|' && !code) {
            buf[k++] = 0;
            if (++n == MAX_CELLS) break;
            cells[n] = buf + k;
        } else buf[k++] = *line;
    }
    buf[k] = 0;
    for (int i = 0; i < n; i++) { /* trim; the text after the last '|' is not a cell */
        while (isspace((unsigned char)*cells[i])) cells[i]++;
        char *e = cells[i] + strlen(cells[i]);
        while (e > cells[i] && isspace((unsigned char)e[-1])) *--e = 0;
    }
    return n;
}

/* The next token of the default cell after *pos that fits def (see the top);
 * writes it formatted as fs_param_format would, or returns 0 when none is left. */
static int next_value(const fs_param_def *def, const char **pos, char *out, int size)
{
    for (const char *s = *pos; *s;) {
        const char *t = s;
        if (isdigit((unsigned char)*s) || (*s == '.' && isdigit((unsigned char)s[1]))) {
            char *end;
            double v = strtod(s, &end);
            *pos = s = end;
            if (def->type == FS_PARAM_FLOAT || def->type == FS_PARAM_INT) {
                snprintf(out, size, "%g", v);
                return 1;
            }
            continue;
        }
        if (!isalpha((unsigned char)*s) && *s != '_') {
            s++;
            continue;
        }
        while (isalnum((unsigned char)*s) || *s == '_') s++;
        *pos = s;
        char word[64];
        snprintf(word, sizeof word, "%.*s", (int)(s - t), t);
        int fits = def->type == FS_PARAM_BOOL ? !strcmp(word, "on") || !strcmp(word, "off")
            : def->type == FS_PARAM_ENUM      ? fs_param_choice(def, word) >= 0
                                              : 0;
        if (fits) {
            snprintf(out, size, "%s", word);
            return 1;
        }
    }
    return 0;
}

static int quiet; /* the checker's own cases fail on purpose: no messages */

/* Prints one problem of the README at where (unless quiet); returns 1. */
static int problem(const char *where, const char *fmt, ...)
{
    if (quiet) return 1;
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", where);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return 1;
}

/* Checks one row: its named parameters against the defaults cell. */
static int check_row(const fs_method *m, const char *names, const char *defaults, int *seen, const char *where)
{
    int bad = 0;
    const char *pos = defaults;
    for (const char *b = strchr(names, '`'); b; b = strchr(b + 1, '`')) {
        const char *e = strchr(b + 1, '`');
        if (!e) break;
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)(e - b - 1), b + 1);
        b = e;
        int i = fs_method_param_index(m, name);
        if (i < 0) {
            bad += problem(where, "`%s` is not a parameter of %s", name, m->name);
            continue;
        }
        if (seen[i]++) bad += problem(where, "`%s` has a second row", name);
        char want[64], got[64];
        fs_param_format(&m->params[i], m->params[i].def, want, sizeof want);
        if (!next_value(&m->params[i], &pos, got, sizeof got))
            bad += problem(where, "no default for `%s` in \"%s\" (the table's: %s)", name, defaults, want);
        else if (strcmp(got, want)) bad += problem(where, "`%s` defaults to %s, the README says %s", name, want, got);
    }
    return bad;
}

/* The default column of a parameter table's header, or -1 (not a parameter table). */
static int default_column(char **cells, int n)
{
    if (n < 2 || (strcasecmp(cells[0], "parameter") && strcasecmp(cells[0], "name"))) return -1;
    for (int i = 1; i < n; i++)
        if (strstr(cells[i], "default")) return i;
    for (int i = 1; i < n; i++)
        if (!strcmp(cells[i], "ours")) return i;
    return -1;
}

static const char *next_line(const char *line)
{
    line = strchr(line, '\n');
    return line && line[1] ? line + 1 : NULL;
}

/* Problems of README text against m's table (printed, naming where). */
static int check_text(const fs_method *m, const char *text, const char *where)
{
    int seen[FS_MAX_PARAMS] = {0}, bad = 0, in_table = 0, col = -1;
    char buf[4096], *cells[MAX_CELLS];
    for (const char *line = text; line; line = next_line(line)) {
        int n = row_cells(line, buf, sizeof buf, cells);
        if (n == 0) {
            in_table = 0;
            continue;
        }
        if (!in_table) {
            in_table = 1;
            col = default_column(cells, n);
            continue;
        } /* the header */
        if (col < 0 || !strncmp(cells[0], "---", 3)) continue;
        if (col < n) bad += check_row(m, cells[0], cells[col], seen, where);
    }
    for (int i = 0; i < m->nparams; i++)
        if (!seen[i]) bad += problem(where, "no row for `%s`", m->params[i].name);
    return bad;
}

/* spheres' two splat parameters (common/gl/gl_splat.h), right, for the checker's cases */
#define SPLAT_ROWS "| `splat` | — | raster | c |\n| `splat_large_px` | — | 0 | d |\n"

/* The checker itself: a right table passes, each kind of drift fails. */
static void checker(void)
{
    quiet = 1;
    const fs_method *m = fs_method_find("spheres");
    const char *head = "| parameter | paper | ours | meaning |\n|---|---|---|---|\n";
    const char *cases[][2] = {
        {"| `radius_scale` | 1 | 1.0 r | a |\n| `thickness` | — | on | b |\n" SPLAT_ROWS, "0"},
        {"| `radius_scale`, `thickness`, `splat`, `splat_large_px` | | 1, on, raster, 0 | a |\n", "0"},
        {"| `radius_scale` | 1 | 1.5 | a |\n| `thickness` | — | on | b |\n" SPLAT_ROWS, "1"}, /* wrong number */
        {"| `radius_scale` | 1 | 1 | a |\n| `thickness` | — | off | b |\n" SPLAT_ROWS, "1"},  /* wrong bool */
        {"| `radius_scale` | 1 | 1 | a |\n" SPLAT_ROWS, "1"},                                 /* missing row */
        {"| `radius_scale` | 1 | 1 | a |\n| `thickness` | | on | b |\n| `radius` | | 1 | |\n" SPLAT_ROWS,
         "1"},                                                                              /* unknown */
        {"| `radius_scale` | 1 | r | a |\n| `thickness` | — | on | b |\n" SPLAT_ROWS, "1"}, /* no value */
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        char text[1024];
        snprintf(text, sizeof text, "%s%s", head, cases[i][0]);
        int bad = check_text(m, text, "(checker case)");
        CHECK((bad > 0) == (cases[i][1][0] == '1'), "case %zu: %d problems", i, bad);
    }
    const fs_method *e = fs_method_find("aniso_ssf"); /* an enum's choice names; only `filter` has a row */
    int right = check_text(e, "| name | default |\n|---|---|\n| `filter` | `narrow` |\n", "(checker)");
    int wrong = check_text(e, "| name | default |\n|---|---|\n| `filter` | gaussian |\n", "(checker)");
    CHECK(right == e->nparams - 1 && wrong == right + 1, "enum: %d and %d problems", right, wrong);
    quiet = 0;
}

static char *read_all(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (text) text[fread(text, 1, (size_t)n, f)] = 0;
    fclose(f);
    return text;
}

int main(void)
{
    fs_methods_register_builtin();
    checker();
    for (int i = 0; i < fs_method_count(); i++) {
        const fs_method *m = fs_method_at(i);
        char path[1024];
        snprintf(path, sizeof path, "%s/methods/%s/README.md", FS_SOURCE_DIR, m->name);
        char *text = read_all(path);
        CHECK(text != NULL, "cannot read %s", path);
        if (!text) continue;
        int bad = check_text(m, text, path);
        printf("%s: %d parameters, %d problems\n", m->name, m->nparams, bad);
        CHECK(bad == 0, "%s: the README's parameter table disagrees with the method's (above)", m->name);
        free(text);
    }
    TEST_DONE();
}
