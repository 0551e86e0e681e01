/* Plain particle files: raw float32 x y z little-endian triples (.raw, .xyz),
 * and CSV (comma, semicolon or whitespace separated; '#' starts a comment).
 * A CSV header is optional; when present, columns are found by name: x y z,
 * vx vy vz, r g b (or red green blue, taken as linear 0..1), phase. Without
 * one the first three columns are x y z. */
#include "particle_io.h"
#include "fs_error.h"
#include "bytes.h"
#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

int fs_read_raw(fs_particles *p, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    int rc = fstat(fileno(f), &st) == 0 ? FS_OK : fs_fail(FS_ERR_INPUT, "%s: cannot stat", path);
    if (!rc && st.st_size % 12 != 0)
        rc = fs_fail(FS_ERR_INPUT, "%s: size %lld is not a multiple of 12 bytes (float32 x y z)", path,
                     (long long)st.st_size);
    if (!rc) rc = fs_particles_alloc(p, (size_t)st.st_size / 12, 0);
    enum { CHUNK = 4096 };
    unsigned char buf[CHUNK * 12];
    for (size_t i = 0; !rc && i < p->n; i += CHUNK) {
        size_t m = p->n - i < CHUNK ? p->n - i : CHUNK;
        if (fread(buf, 12, m, f) != m) {
            rc = fs_fail(FS_ERR_INPUT, "%s: read error at particle %zu", path, i);
            break;
        }
        for (size_t k = 0; k < m; k++) {
            float v[3];
            for (int c = 0; c < 3; c++) {
                const unsigned char *b = buf + 12 * k + 4 * c;
                uint32_t u = fs_le32(b);
                memcpy(&v[c], &u, 4);
            }
            p->x[i + k] = v[0];
            p->y[i + k] = v[1];
            p->z[i + k] = v[2];
        }
    }
    fclose(f);
    if (rc) fs_particles_free(p);
    return rc;
}

enum { MAX_COLS = 64 };
enum { C_X, C_Y, C_Z, C_VX, C_VY, C_VZ, C_R, C_G, C_B, C_PHASE, C_COUNT };

/* Splits line in place into trimmed fields; returns the count (at most MAX_COLS). */
static int split_fields(char *line, char **field)
{
    char sep = strchr(line, ',') ? ',' : strchr(line, ';') ? ';' : 0;
    int n = 0;
    char *s = line;
    while (n < MAX_COLS) {
        while (*s == ' ' || *s == '\t') s++;
        if (!sep && !*s) break;
        field[n++] = s;
        char *end = sep ? strchr(s, sep) : s + strcspn(s, " \t");
        char *next = end && *end ? end + 1 : NULL;
        if (!end) end = s + strlen(s);
        char *t = end;
        while (t > s && (t[-1] == ' ' || t[-1] == '\t')) t--;
        *t = 0;
        if (!next) break;
        s = next;
    }
    return n;
}

static int parse_float(const char *s, float *v)
{
    char *end;
    if (!*s) return 0;
    *v = strtof(s, &end);
    return *end == 0;
}

/* Maps header names to columns; -1 where absent. Returns 1 if the line is a header. */
static int read_header(char **field, int n, int *col)
{
    static const char *const names[C_COUNT][3] = {
        {"x"}, {"y"}, {"z"}, {"vx"}, {"vy"}, {"vz"}, {"r", "red"}, {"g", "green"}, {"b", "blue"}, {"phase"},
    };
    int numeric = 1;
    float dummy;
    for (int i = 0; i < n; i++) numeric = numeric && parse_float(field[i], &dummy);
    for (int c = 0; c < C_COUNT; c++) col[c] = c < 3 && numeric ? c : -1;
    if (numeric) return 0;
    for (int i = 0; i < n; i++) {
        char *name = field[i];
        size_t len = strlen(name);
        if (len >= 2 && name[0] == '"' && name[len - 1] == '"') {
            name[len - 1] = 0;
            name++;
        }
        for (int c = 0; c < C_COUNT; c++)
            for (int k = 0; k < 3 && names[c][k]; k++)
                if (col[c] < 0 && strcasecmp(name, names[c][k]) == 0) col[c] = i;
    }
    return 1;
}

/* Loads the whole file with a terminating NUL. */
static int load_text(const char *path, char **out, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    int rc = fstat(fileno(f), &st) == 0 ? FS_OK : fs_fail(FS_ERR_INPUT, "%s: cannot stat", path);
    char *text = rc ? NULL : malloc((size_t)st.st_size + 1);
    if (!rc && !text) rc = fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    if (!rc && fread(text, 1, (size_t)st.st_size, f) != (size_t)st.st_size)
        rc = fs_fail(FS_ERR_INPUT, "%s: read error", path);
    fclose(f);
    if (rc) {
        free(text);
        return rc;
    }
    text[st.st_size] = 0;
    if (memchr(text, 0, (size_t)st.st_size)) {
        free(text);
        return fs_fail(FS_ERR_INPUT, "%s: binary data in a CSV file", path);
    }
    *out = text;
    *size = (size_t)st.st_size;
    return FS_OK;
}

/* A CSV file being read: its columns, and the rows stored so far. */
typedef struct csv_read {
    const char *path;
    fs_particles *p;
    int col[C_COUNT], have_cols, need;
    unsigned fields;
    size_t rows;
} csv_read;

/* The first line's columns (its names, or x, y, z and what follows when it is
 * data), and the arrays for max_rows rows; *is_header: the line holds names. */
static int take_columns(csv_read *c, char **field, int n, size_t max_rows, int *is_header)
{
    c->have_cols = 1;
    *is_header = read_header(field, n, c->col);
    if (c->col[C_X] < 0 || c->col[C_Y] < 0 || c->col[C_Z] < 0)
        return fs_fail(FS_ERR_INPUT, "%s: CSV header has no x, y, z columns", c->path);
    if (c->col[C_VX] >= 0 && c->col[C_VY] >= 0 && c->col[C_VZ] >= 0) c->fields |= FS_HAS_VELOCITY;
    if (c->col[C_R] >= 0 && c->col[C_G] >= 0 && c->col[C_B] >= 0) c->fields |= FS_HAS_COLOR;
    if (c->col[C_PHASE] >= 0) c->fields |= FS_HAS_PHASE;
    for (int k = 0; k < C_COUNT; k++)
        if (c->col[k] + 1 > c->need) c->need = c->col[k] + 1;
    return fs_particles_alloc(c->p, max_rows, c->fields);
}

/* A data line's n fields as the next particle. */
static int store_row(csv_read *c, char **field, int n, size_t lineno)
{
    fs_particles *p = c->p;
    size_t r = c->rows;
    if (n < c->need)
        return fs_fail(FS_ERR_INPUT, "%s: line %zu has %d columns, expected %d", c->path, lineno, n, c->need);
    float v[C_COUNT] = {0};
    for (int k = 0; k < C_COUNT; k++)
        if (c->col[k] >= 0 && !parse_float(field[c->col[k]], &v[k]))
            return fs_fail(FS_ERR_INPUT, "%s: line %zu: bad number '%.32s'", c->path, lineno, field[c->col[k]]);
    p->x[r] = v[C_X], p->y[r] = v[C_Y], p->z[r] = v[C_Z];
    if (c->fields & FS_HAS_VELOCITY) p->vx[r] = v[C_VX], p->vy[r] = v[C_VY], p->vz[r] = v[C_VZ];
    if (c->fields & FS_HAS_COLOR)
        for (int k = 0; k < 3; k++) p->color[3 * r + k] = v[C_R + k];
    if (c->fields & FS_HAS_PHASE) {
        if (!(v[C_PHASE] >= -2e9f && v[C_PHASE] <= 2e9f))
            return fs_fail(FS_ERR_INPUT, "%s: line %zu: phase out of range", c->path, lineno);
        p->phase[r] = (int32_t)v[C_PHASE];
    }
    c->rows++;
    return FS_OK;
}

/* Every line of text (LF-ended; '#' starts a comment) into c. */
static int read_lines(csv_read *c, char *text, size_t max_rows)
{
    char *field[MAX_COLS];
    size_t lineno = 0;
    int rc = FS_OK;
    for (char *line = text, *next; !rc && line; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = 0;
        lineno++;
        char *hash = strchr(line, '#');
        if (hash) *hash = 0;
        line[strcspn(line, "\r")] = 0;
        int n = split_fields(line, field), is_header = 0;
        if (n == 0 || (n == 1 && !field[0][0])) continue;
        if (!c->have_cols && ((rc = take_columns(c, field, n, max_rows, &is_header)) || is_header)) continue;
        rc = store_row(c, field, n, lineno);
    }
    return rc;
}

int fs_read_csv(fs_particles *p, const char *path)
{
    char *text = NULL;
    size_t size = 0;
    int rc = load_text(path, &text, &size);
    if (rc) return rc;
    /* Old Mac files end lines with a lone CR: make every line end in LF. */
    for (size_t i = 0; i < size; i++)
        if (text[i] == '\r' && text[i + 1] != '\n') text[i] = '\n';
    size_t max_rows = 1;
    for (size_t i = 0; i < size; i++) max_rows += text[i] == '\n';
    csv_read c = {.path = path, .p = p, .need = 3};
    rc = read_lines(&c, text, max_rows);
    free(text);
    if (rc) {
        fs_particles_free(p);
        return rc;
    }
    p->n = c.rows; /* arrays were sized for every line; the unused tail is harmless */
    return FS_OK;
}
