/* Legacy VTK (.vtk) particle files, read and written by our own code in every
 * build. VTK 9.1's legacy readers crash on malformed files of a hundred bytes
 * (its cell-array, string and structured-grid paths; docs/DESIGN.md, "Bad
 * input"), and a particle file needs only a small part of the format: the
 * POINTS and the point arrays. So the file is mapped and walked here, every
 * count checked against the bytes left before anything is allocated; cells and
 * other sections are skipped by their declared sizes.
 *
 * Read: DATASET POLYDATA or UNSTRUCTURED_GRID, ASCII or BINARY (big-endian),
 * versions 2.0 to 5.1 (5.x cells as OFFSETS + CONNECTIVITY). Kept: POINTS, and
 * from POINT_DATA or FIELD data the arrays named like a velocity (3
 * components), a colour (3; unsigned char scaled by 1/255) and "phase" (1);
 * every other point array (one value tuple per point) as a point array of its
 * own (particle_arrays.h), up to FS_MAX_POINT_ARRAYS of them.
 * Written: version 3.0 binary UNSTRUCTURED_GRID, one vertex cell per particle,
 * its point arrays as FIELD data after the known ones. */
#include "particle_io.h"
#include "fs_error.h"
#include "particle_arrays.h"
#include "output_file.h"
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct vtk_in {
    const char *path;
    const unsigned char *b;
    size_t n, pos;
    int binary;
} vtk_in;

/* An array kept for the particles: values as double, ncomp per tuple. */
typedef struct vtk_array {
    double *v;
    long long tuples;
    int ncomp, scale_uchar;
} vtk_array;

/* A point array fluidsurf does not use, kept as it is. */
typedef struct vtk_other {
    char name[64];
    fs_array_type type;
    vtk_array a;
} vtk_other;

typedef struct vtk_set {
    vtk_array pts, vel, col, phase;
    int nother;
    vtk_other other[FS_MAX_POINT_ARRAYS];
} vtk_set;

/* The token as printable text for a message (at most 32 characters). */
static const char *shown(const char *tok)
{
    static _Thread_local char s[40];
    size_t k = 0;
    for (; tok[k] && k < 32; k++) s[k] = isprint((unsigned char)tok[k]) ? tok[k] : '?';
    s[k] = 0;
    return s;
}

static void skip_space(vtk_in *in)
{
    while (in->pos < in->n && isspace(in->b[in->pos])) in->pos++;
}

/* Next whitespace-separated token into tok; 0 at the end of the file. */
static int token(vtk_in *in, char *tok, size_t size)
{
    skip_space(in);
    size_t k = 0;
    while (in->pos < in->n && !isspace(in->b[in->pos])) {
        if (k + 1 < size) tok[k++] = (char)in->b[in->pos];
        in->pos++;
    }
    tok[k] = 0;
    return k > 0;
}

/* Skips to the start of the next line (binary data starts there). */
static void next_line(vtk_in *in)
{
    while (in->pos < in->n && in->b[in->pos] != '\n') in->pos++;
    if (in->pos < in->n) in->pos++;
}

/* A count token: a non-negative integer below 2^62. */
static int count(vtk_in *in, const char *what, long long *out)
{
    char tok[64], *end;
    if (!token(in, tok, sizeof tok))
        return fs_fail(FS_ERR_INPUT, "%s: truncated VTK file: %s has no count", in->path, what);
    errno = 0;
    long long v = strtoll(tok, &end, 10);
    if (*end || errno || v < 0 || v > (1LL << 62))
        return fs_fail(FS_ERR_INPUT, "%s: bad VTK count '%s' for %s", in->path, shown(tok), what);
    *out = v;
    return FS_OK;
}

static size_t type_size(const char *t)
{
    static const struct {
        const char *name;
        size_t size;
    } types[] = {
        {"float", 4},          {"double", 8},       {"int", 4},           {"unsigned_int", 4}, {"short", 2},
        {"unsigned_short", 2}, {"char", 1},         {"unsigned_char", 1}, {"long", 8},         {"unsigned_long", 8},
        {"vtkIdType", 8},      {"vtktypeint64", 8}, {"vtktypeuint64", 8}, {"vtktypeint32", 4}, {"vtktypeuint32", 4},
    };
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcasecmp(t, types[i].name) == 0) return types[i].size;
    return 0;
}

/* How a binary value of a type is decoded: decided once per array, not per value. */
typedef enum { VTK_FLOAT, VTK_DOUBLE, VTK_UNSIGNED, VTK_SIGNED } vtk_kind;

static vtk_kind binary_kind(const char *t)
{
    if (strcasecmp(t, "float") == 0) return VTK_FLOAT;
    if (strcasecmp(t, "double") == 0) return VTK_DOUBLE;
    if (strncasecmp(t, "unsigned", 8) == 0 || strncasecmp(t, "vtktypeuint", 11) == 0) return VTK_UNSIGNED;
    return VTK_SIGNED;
}

/* One binary big-endian value of kind `kind` (size sz) at p. */
static double binary_value(const unsigned char *p, vtk_kind kind, size_t sz)
{
    uint64_t u = 0;
    for (size_t k = 0; k < sz; k++) u = u << 8 | p[k];
    if (kind == VTK_FLOAT) {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, 4);
        return f;
    }
    if (kind == VTK_DOUBLE) {
        double d;
        memcpy(&d, &u, 8);
        return d;
    }
    if (kind == VTK_UNSIGNED) return (double)u;
    int shift = (int)(64 - 8 * sz); /* sign-extend */
    return (double)((int64_t)(u << shift) >> shift);
}

/* Reads (keep != NULL) or skips count values of type t: binary big-endian, or
 * ASCII numbers. Refuses a count the rest of the file cannot hold before it
 * allocates: sz bytes a value in binary, 2 (a digit and a separator) in ASCII. */
static int values(vtk_in *in, long long cnt, const char *t, const char *what, double **keep)
{
    size_t sz = type_size(t);
    if (!sz) return fs_fail(FS_ERR_INPUT, "%s: unknown VTK data type '%s' in %s", in->path, shown(t), what);
    if (in->binary) next_line(in);
    size_t left = in->n - in->pos, each = in->binary ? sz : 2;
    if ((unsigned long long)cnt > (left + (in->binary ? 0 : 1)) / each)
        return fs_fail(FS_ERR_INPUT, "%s: truncated VTK file: %s declares %lld values but only %zu bytes follow",
                       in->path, what, cnt, left);
    double *v = NULL;
    if (keep) {
        v = malloc((cnt ? (size_t)cnt : 1) * sizeof *v);
        if (!v) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for %lld VTK values", in->path, cnt);
    }
    if (in->binary) {
        vtk_kind kind = binary_kind(t);
        for (long long i = 0; v && i < cnt; i++) v[i] = binary_value(in->b + in->pos + (size_t)i * sz, kind, sz);
        in->pos += (size_t)cnt * sz;
    } else {
        char tok[64], *end;
        for (long long i = 0; i < cnt; i++) {
            double x = token(in, tok, sizeof tok) ? strtod(tok, &end) : 0;
            if (!tok[0] || *end) {
                free(v);
                return fs_fail(FS_ERR_INPUT, "%s: bad or missing VTK value %lld of %lld in %s", in->path, i, cnt, what);
            }
            if (v) v[i] = x;
        }
    }
    if (keep) *keep = v;
    return FS_OK;
}

static int name_is(const char *name, const char *const *names)
{
    for (; *names; names++)
        if (strcasecmp(name, *names) == 0) return 1;
    return 0;
}

/* The particle array an attribute of this name and shape fills, or NULL. */
static vtk_array *slot_for(vtk_set *s, const char *name, int ncomp)
{
    static const char *const vel[] = {"velocity", "velocities", "vel", "v", NULL};
    static const char *const col[] = {"color", "colors", "colour", "Cd", "rgb", NULL};
    static const char *const ph[] = {"phase", NULL};
    if (ncomp == 3 && name_is(name, vel) && !s->vel.v) return &s->vel;
    if (ncomp == 3 && name_is(name, col) && !s->col.v) return &s->col;
    if (ncomp == 1 && name_is(name, ph) && !s->phase.v) return &s->phase;
    return NULL;
}

/* The point array type that holds VTK type t's values (64-bit integers as float64). */
static fs_array_type array_type_of(const char *t)
{
    if (!strcasecmp(t, "float")) return FS_ARRAY_F32;
    if (!strcasecmp(t, "unsigned_int") || !strcasecmp(t, "vtktypeuint32")) return FS_ARRAY_U32;
    if (type_size(t) <= 4 && strcasecmp(t, "double")) return FS_ARRAY_I32;
    return FS_ARRAY_F64;
}

/* The slot of a point array that fluidsurf does not use: the next free one, or NULL. */
static vtk_array *other_slot(vtk_set *s, const char *name, const char *t)
{
    if (s->nother == FS_MAX_POINT_ARRAYS) return NULL;
    vtk_other *o = &s->other[s->nother++];
    snprintf(o->name, sizeof o->name, "%s", name);
    o->type = array_type_of(t);
    return &o->a;
}

/* An array of tuples x ncomp values; kept when tuples is the point count: in the
 * slot its name fills, else as a point array of its own. */
static int array(vtk_in *in, vtk_set *s, const char *name, int ncomp, long long tuples, const char *t, const char *what,
                 int points_data)
{
    if (ncomp <= 0 || ncomp > 1024) return fs_fail(FS_ERR_INPUT, "%s: bad VTK component count in %s", in->path, what);
    if (tuples > (1LL << 62) / ncomp) return fs_fail(FS_ERR_INPUT, "%s: VTK %s is too large", in->path, what);
    int per_point = points_data && s->pts.v && tuples == s->pts.tuples && type_size(t);
    vtk_array *slot = per_point ? slot_for(s, name, ncomp) : NULL;
    if (per_point && !slot) slot = other_slot(s, name, t);
    double *v = NULL;
    int rc = values(in, tuples * ncomp, t, what, slot ? &v : NULL);
    if (rc || !slot) return rc;
    *slot = (vtk_array){v, tuples, ncomp, strcasecmp(t, "unsigned_char") == 0};
    return FS_OK;
}

/* FIELD name k: k arrays "name ncomp ntuples type" and their values. */
static int field(vtk_in *in, vtk_set *s)
{
    char name[256], type[64];
    long long k, ncomp, tuples;
    if (!token(in, name, sizeof name)) return fs_fail(FS_ERR_INPUT, "%s: truncated VTK FIELD", in->path);
    int rc = count(in, "FIELD", &k);
    for (long long i = 0; !rc && i < k; i++) {
        if (!token(in, name, sizeof name)) return fs_fail(FS_ERR_INPUT, "%s: truncated VTK FIELD array", in->path);
        rc = count(in, "FIELD array components", &ncomp);
        if (!rc) rc = count(in, "FIELD array tuples", &tuples);
        if (!rc && !token(in, type, sizeof type)) rc = fs_fail(FS_ERR_INPUT, "%s: truncated VTK FIELD array", in->path);
        if (!rc && ncomp > 1024) rc = fs_fail(FS_ERR_INPUT, "%s: bad VTK component count in FIELD", in->path);
        if (!rc) rc = array(in, s, name, (int)ncomp, tuples, type, "FIELD array", 1);
    }
    return rc;
}

/* Cells: legacy "n size" then size ints, or 5.x "OFFSETS t ... CONNECTIVITY t ...". */
static int cells(vtk_in *in, const char *kw)
{
    long long n, size;
    int rc = count(in, kw, &n);
    if (!rc) rc = count(in, kw, &size);
    if (rc) return rc;
    size_t save = in->pos;
    char tok[64], type[64];
    if (token(in, tok, sizeof tok) && strcasecmp(tok, "OFFSETS") == 0) {
        if (!token(in, type, sizeof type)) return fs_fail(FS_ERR_INPUT, "%s: truncated VTK OFFSETS", in->path);
        rc = values(in, n, type, "OFFSETS", NULL);
        if (!rc &&
            !(token(in, tok, sizeof tok) && strcasecmp(tok, "CONNECTIVITY") == 0 && token(in, type, sizeof type)))
            rc = fs_fail(FS_ERR_INPUT, "%s: VTK %s: OFFSETS without CONNECTIVITY", in->path, kw);
        return rc ? rc : values(in, size, type, "CONNECTIVITY", NULL);
    }
    in->pos = save;
    return values(in, size, "int", kw, NULL);
}

/* One attribute of POINT_DATA or CELL_DATA (kw already read). */
static int attribute(vtk_in *in, vtk_set *s, const char *kw, long long tuples, int points_data)
{
    char name[256], type[64], tok[64];
    long long nc = 1;
    if (!token(in, name, sizeof name)) return fs_fail(FS_ERR_INPUT, "%s: truncated VTK %s", in->path, kw);
    if (strcasecmp(kw, "LOOKUP_TABLE") == 0) { /* name size, then RGBA per entry */
        int rc = count(in, kw, &nc);
        return rc ? rc : values(in, 4 * nc, in->binary ? "unsigned_char" : "float", kw, NULL);
    }
    if (strcasecmp(kw, "COLOR_SCALARS") == 0) { /* name ncomp: floats in ASCII, bytes in binary */
        int rc = count(in, kw, &nc);
        return rc ? rc
                  : array(in, s, name, nc > 1024 ? -1 : (int)nc, tuples, in->binary ? "unsigned_char" : "float", kw,
                          points_data);
    }
    if (strcasecmp(kw, "TEXTURE_COORDINATES") == 0 && count(in, kw, &nc)) return FS_ERR_INPUT;
    if (!token(in, type, sizeof type)) return fs_fail(FS_ERR_INPUT, "%s: truncated VTK %s", in->path, kw);
    if (strcasecmp(kw, "SCALARS") == 0) { /* name type [ncomp] [LOOKUP_TABLE name] */
        size_t save = in->pos;
        char *end;
        if (token(in, tok, sizeof tok) && (nc = strtoll(tok, &end, 10), !*end)) save = in->pos;
        else nc = 1;
        in->pos = save;
        if (token(in, tok, sizeof tok) && strcasecmp(tok, "LOOKUP_TABLE") == 0) token(in, tok, sizeof tok);
        else in->pos = save;
        if (nc < 1 || nc > 4) return fs_fail(FS_ERR_INPUT, "%s: VTK SCALARS with %lld components", in->path, nc);
    } else if (strcasecmp(kw, "VECTORS") == 0 || strcasecmp(kw, "NORMALS") == 0) {
        nc = 3;
    } else if (strcasecmp(kw, "TENSORS") == 0) {
        nc = 9;
    } else if (strcasecmp(kw, "TENSORS6") == 0) {
        nc = 6;
    } else if (strcasecmp(kw, "TEXTURE_COORDINATES") != 0) {
        return fs_fail(FS_ERR_INPUT, "%s: unknown VTK section '%s'", in->path, shown(kw));
    }
    if (nc < 1 || nc > 1024) return fs_fail(FS_ERR_INPUT, "%s: bad VTK component count in %s", in->path, kw);
    return array(in, s, name, (int)nc, tuples, type, kw, points_data);
}

static int header(vtk_in *in)
{
    static const char magic[] = "# vtk DataFile Version";
    if (in->n < sizeof magic - 1 || memcmp(in->b, magic, sizeof magic - 1) != 0)
        return fs_fail(FS_ERR_INPUT, "%s: not a legacy VTK file (bad magic)", in->path);
    next_line(in);
    next_line(in); /* the title */
    char tok[64], kind[64];
    if (!token(in, tok, sizeof tok)) return fs_fail(FS_ERR_INPUT, "%s: truncated VTK header", in->path);
    in->binary = strcasecmp(tok, "BINARY") == 0;
    if (!in->binary && strcasecmp(tok, "ASCII") != 0)
        return fs_fail(FS_ERR_INPUT, "%s: VTK file is neither ASCII nor BINARY", in->path);
    if (!token(in, tok, sizeof tok) || strcasecmp(tok, "DATASET") != 0 || !token(in, kind, sizeof kind))
        return fs_fail(FS_ERR_INPUT, "%s: VTK file has no DATASET line", in->path);
    if (strcasecmp(kind, "POLYDATA") != 0 && strcasecmp(kind, "UNSTRUCTURED_GRID") != 0)
        return fs_fail(FS_ERR_INPUT, "%s: VTK DATASET %s holds no particles (POLYDATA or UNSTRUCTURED_GRID are read)",
                       in->path, shown(kind));
    return FS_OK;
}

/* The sections after the header, in any order. */
static int sections(vtk_in *in, vtk_set *s)
{
    char kw[64], type[64];
    long long n, tuples = -1; /* tuples: of the current POINT_DATA / CELL_DATA block */
    int points_data = 0, rc = FS_OK;
    while (!rc && token(in, kw, sizeof kw)) {
        if (strcasecmp(kw, "POINTS") == 0) {
            if (s->pts.v) return fs_fail(FS_ERR_INPUT, "%s: VTK file has two POINTS sections", in->path);
            rc = count(in, "POINTS", &n);
            if (!rc && !token(in, type, sizeof type))
                rc = fs_fail(FS_ERR_INPUT, "%s: truncated VTK POINTS line", in->path);
            if (!rc && n > (1LL << 60))
                rc = fs_fail(FS_ERR_INPUT, "%s: VTK POINTS count %lld is too large", in->path, n);
            if (!rc) rc = values(in, 3 * n, type, "POINTS", &s->pts.v);
            s->pts.tuples = n, s->pts.ncomp = 3;
        } else if (strcasecmp(kw, "POINT_DATA") == 0 || strcasecmp(kw, "CELL_DATA") == 0) {
            points_data = strcasecmp(kw, "POINT_DATA") == 0;
            rc = count(in, kw, &tuples);
            if (!rc && points_data && (!s->pts.v || tuples != s->pts.tuples))
                rc = fs_fail(FS_ERR_INPUT, "%s: VTK POINT_DATA %lld does not match POINTS %lld", in->path, tuples,
                             s->pts.v ? s->pts.tuples : 0);
        } else if (strcasecmp(kw, "FIELD") == 0) {
            rc = field(in, s);
        } else if (name_is(kw,
                           (const char *const[]){"VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS", "CELLS", NULL})) {
            rc = cells(in, kw);
        } else if (strcasecmp(kw, "CELL_TYPES") == 0) {
            rc = count(in, kw, &n);
            if (!rc) rc = values(in, n, "int", kw, NULL);
        } else if (strcasecmp(kw, "METADATA") == 0) { /* lines up to an empty one */
            next_line(in);
            while (in->pos < in->n && in->b[in->pos] != '\n' && in->b[in->pos] != '\r') next_line(in);
        } else if (tuples >= 0) {
            rc = attribute(in, s, kw, tuples, points_data);
        } else {
            rc = fs_fail(FS_ERR_INPUT, "%s: unknown VTK section '%s'", in->path, shown(kw));
        }
    }
    if (!rc && !s->pts.v) rc = fs_fail(FS_ERR_INPUT, "%s: VTK file has no POINTS", in->path);
    return rc;
}

/* The point arrays fluidsurf does not use into p, in the file's order. */
static int others_to_particles(const vtk_set *s, fs_particles *p)
{
    for (int i = 0; i < s->nother; i++) {
        const vtk_other *o = &s->other[i];
        fs_point_array *a;
        int rc = fs_particles_add_array(p, o->name, o->a.ncomp, o->type, &a);
        if (rc) return rc;
        for (size_t k = 0; k < p->n * (size_t)o->a.ncomp; k++) fs_point_array_set(a, k, o->a.v[k]);
    }
    return FS_OK;
}

/* Moves the kept arrays into p. */
static int to_particles(const vtk_set *s, const char *path, fs_particles *p)
{
    unsigned fields =
        (s->vel.v ? FS_HAS_VELOCITY : 0) | (s->col.v ? FS_HAS_COLOR : 0) | (s->phase.v ? FS_HAS_PHASE : 0);
    int rc = fs_particles_alloc(p, (size_t)s->pts.tuples, fields);
    if (rc) return rc;
    double cs = s->col.scale_uchar ? 1.0 / 255.0 : 1.0;
    for (size_t i = 0; i < p->n; i++) {
        p->x[i] = (float)s->pts.v[3 * i], p->y[i] = (float)s->pts.v[3 * i + 1], p->z[i] = (float)s->pts.v[3 * i + 2];
        if (s->vel.v)
            p->vx[i] = (float)s->vel.v[3 * i], p->vy[i] = (float)s->vel.v[3 * i + 1],
            p->vz[i] = (float)s->vel.v[3 * i + 2];
        for (int k = 0; s->col.v && k < 3; k++) p->color[3 * i + k] = (float)(s->col.v[3 * i + k] * cs);
        if (s->phase.v) {
            double v = s->phase.v[i];
            if (!(v >= INT32_MIN && v <= INT32_MAX))
                return fs_fail(FS_ERR_INPUT, "%s: phase of point %zu out of range", path, i);
            p->phase[i] = (int32_t)v;
        }
    }
    return others_to_particles(s, p);
}

int fs_read_vtk(fs_particles *p, const char *path)
{
    int fd = open(path, O_RDONLY);
    if (fd < 0) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    int rc =
        fstat(fd, &st) == 0 && st.st_size > 0 ? FS_OK : fs_fail(FS_ERR_INPUT, "%s: empty or unreadable file", path);
    void *map = rc ? MAP_FAILED : mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (!rc && map == MAP_FAILED) rc = fs_fail(FS_ERR_INPUT, "%s: cannot map: %s", path, strerror(errno));
    if (rc) return rc;
    vtk_in in = {path, map, (size_t)st.st_size, 0, 0};
    vtk_set *s = calloc(1, sizeof *s);
    rc = s ? header(&in) : fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    if (!rc) rc = sections(&in, s);
    if (!rc) rc = to_particles(s, path, p);
    munmap(map, (size_t)st.st_size);
    if (s) {
        free(s->pts.v), free(s->vel.v), free(s->col.v), free(s->phase.v);
        for (int i = 0; i < s->nother; i++) free(s->other[i].a.v);
    }
    free(s);
    if (rc) fs_particles_free(p);
    return rc;
}

/* ---- writer: version 3.0 binary (big-endian), one vertex cell per particle ---- */

typedef struct be_writer {
    FILE *f;
    int ok;
    size_t len;
    unsigned char buf[1 << 16];
} be_writer;

static void be_flush(be_writer *w)
{
    if (w->ok && w->len && fwrite(w->buf, 1, w->len, w->f) != w->len) w->ok = 0;
    w->len = 0;
}

static void be_u32(be_writer *w, uint32_t v)
{
    if (w->len + 4 > sizeof w->buf) be_flush(w);
    for (int k = 3; k >= 0; k--) w->buf[w->len++] = (unsigned char)(v >> (8 * k));
}

static void be_f32(be_writer *w, float x)
{
    uint32_t u;
    memcpy(&u, &x, 4);
    be_u32(w, u);
}

static void be_u64(be_writer *w, uint64_t v)
{
    be_u32(w, (uint32_t)(v >> 32));
    be_u32(w, (uint32_t)v);
}

static void be_text(be_writer *w, const char *s)
{
    be_flush(w);
    if (w->ok && fputs(s, w->f) < 0) w->ok = 0;
}

/* The point arrays as FIELD data: "name ncomp n type", big-endian values. */
static void write_others(be_writer *w, const fs_particles *p)
{
    static const char *const vtk_type[] = {"float", "double", "int", "unsigned_int"};
    char line[256], name[64];
    snprintf(line, sizeof line, "FIELD FieldData %d\n", p->narrays);
    be_text(w, line);
    for (int i = 0; i < p->narrays; i++) {
        const fs_point_array *a = &p->arrays[i];
        fs_array_safe_name(a->name, name);
        snprintf(line, sizeof line, "%s %d %zu %s\n", name, a->ncomp, p->n, vtk_type[a->type]);
        be_text(w, line);
        size_t nv = p->n * (size_t)a->ncomp;
        for (size_t k = 0; k < nv; k++) {
            if (a->type == FS_ARRAY_F32) be_f32(w, ((const float *)a->data)[k]);
            else if (a->type == FS_ARRAY_F64) {
                uint64_t u;
                memcpy(&u, (const double *)a->data + k, 8);
                be_u64(w, u);
            } else be_u32(w, ((const uint32_t *)a->data)[k]);
        }
        be_text(w, "\n");
    }
}

static void write_body(be_writer *w, const fs_particles *p)
{
    char line[256];
    size_t n = p->n;
    unsigned fields = fs_particles_fields(p);
    snprintf(line, sizeof line,
             "# vtk DataFile Version 3.0\nfluidsurf particles\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS %zu float\n",
             n);
    be_text(w, line);
    for (size_t i = 0; i < n; i++) be_f32(w, p->x[i]), be_f32(w, p->y[i]), be_f32(w, p->z[i]);
    snprintf(line, sizeof line, "\nCELLS %zu %zu\n", n, 2 * n);
    be_text(w, line);
    for (size_t i = 0; i < n; i++) be_u32(w, 1), be_u32(w, (uint32_t)i);
    snprintf(line, sizeof line, "\nCELL_TYPES %zu\n", n);
    be_text(w, line);
    for (size_t i = 0; i < n; i++) be_u32(w, 1); /* VTK_VERTEX */
    be_text(w, "\n");
    if (fields || p->narrays) {
        snprintf(line, sizeof line, "POINT_DATA %zu\n", n);
        be_text(w, line);
    }
    if (fields & FS_HAS_VELOCITY) {
        be_text(w, "VECTORS velocity float\n");
        for (size_t i = 0; i < n; i++) be_f32(w, p->vx[i]), be_f32(w, p->vy[i]), be_f32(w, p->vz[i]);
        be_text(w, "\n");
    }
    if (fields & FS_HAS_COLOR) {
        be_text(w, "SCALARS color float 3\nLOOKUP_TABLE default\n");
        for (size_t i = 0; i < 3 * n; i++) be_f32(w, p->color[i]);
        be_text(w, "\n");
    }
    if (fields & FS_HAS_PHASE) {
        be_text(w, "SCALARS phase int 1\nLOOKUP_TABLE default\n");
        for (size_t i = 0; i < n; i++) be_u32(w, (uint32_t)p->phase[i]);
        be_text(w, "\n");
    }
    if (p->narrays) write_others(w, p);
    be_flush(w);
}

int fs_write_vtk(const fs_particles *p, const char *path)
{
    if (p->n > INT32_MAX / 2) return fs_fail(FS_ERR_INPUT, "%s: too many particles for legacy VTK (%zu)", path, p->n);
    be_writer *w = malloc(sizeof *w);
    if (!w) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    fs_output out;
    int rc = fs_output_open(&out, path);
    if (!rc) {
        w->f = out.f, w->ok = 1, w->len = 0;
        write_body(w, p);
        rc = fs_output_close(&out, w->ok);
    }
    free(w);
    return rc;
}
