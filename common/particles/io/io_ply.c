/* PLY point clouds: ascii, binary_little_endian and binary_big_endian readers,
 * binary little-endian writer. Only the "vertex" element is read: x y z
 * (float or double), optional vx vy vz, red green blue (8-bit /255, 16-bit
 * /65535, float as is), phase; every other scalar property (normals, ids,
 * densities...) as a point array of one component (particle_arrays.h), which
 * the writer writes back (a point array of k components as NAME_0 ... NAME_k-1);
 * list properties are skipped. */
#include "particle_io.h"
#include "fs_error.h"
#include "particle_arrays.h"
#include "output_file.h"
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

enum { T_NONE, T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 };
enum { FMT_ASCII, FMT_LE, FMT_BE };
enum { MAX_ELEMS = 16, MAX_PROPS = 64 };

typedef struct {
    char name[32];
    int type, count_type; /* count_type != T_NONE: a list */
} ply_prop;
typedef struct {
    char name[32];
    unsigned long long count;
    int nprops;
    ply_prop props[MAX_PROPS];
} ply_elem;

/* Buffered reader over a FILE: binary values and ascii tokens both come from here. */
typedef struct {
    FILE *f;
    size_t pos, len;
    unsigned long long consumed;
    unsigned char buf[1 << 16];
} breader;

static const unsigned char *br_need(breader *r, size_t n)
{
    if (r->len - r->pos < n) {
        memmove(r->buf, r->buf + r->pos, r->len - r->pos);
        r->len -= r->pos;
        r->pos = 0;
        r->len += fread(r->buf + r->len, 1, sizeof r->buf - r->len, r->f);
        if (r->len < n) return NULL;
    }
    const unsigned char *at = r->buf + r->pos;
    r->pos += n;
    r->consumed += n;
    return at;
}

/* Reads one header line (without "\n" or "\r\n"); 0 at end of file or on an over-long line. */
static int br_line(breader *r, char *line, size_t size)
{
    size_t k = 0;
    for (;;) {
        const unsigned char *c = br_need(r, 1);
        if (!c) return 0;
        if (*c == '\n') break;
        if (k + 1 >= size) return 0;
        line[k++] = (char)*c;
    }
    if (k && line[k - 1] == '\r') k--;
    line[k] = 0;
    return 1;
}

/* Next byte without consuming it; -1 at end of file. */
static int br_peek(breader *r)
{
    if (r->pos == r->len) {
        r->pos = 0;
        r->len = fread(r->buf, 1, sizeof r->buf, r->f);
    }
    return r->pos < r->len ? r->buf[r->pos] : -1;
}

static int is_space(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/* Next whitespace-separated token; 0 at end of file or when it does not fit. */
static int br_token(breader *r, char *tok, size_t size)
{
    int c;
    while ((c = br_peek(r)) >= 0 && is_space(c)) br_need(r, 1);
    if (c < 0) return 0;
    size_t k = 0;
    while ((c = br_peek(r)) >= 0 && !is_space(c)) {
        if (k + 1 >= size) return 0; /* no valid number is this long */
        tok[k++] = (char)c;
        br_need(r, 1);
    }
    tok[k] = 0;
    return 1;
}

static int type_from_name(const char *s)
{
    static const struct {
        const char *name;
        int type;
    } t[] = {
        {"char", T_I8},   {"int8", T_I8},     {"uchar", T_U8},   {"uint8", T_U8},
        {"short", T_I16}, {"int16", T_I16},   {"ushort", T_U16}, {"uint16", T_U16},
        {"int", T_I32},   {"int32", T_I32},   {"uint", T_U32},   {"uint32", T_U32},
        {"float", T_F32}, {"float32", T_F32}, {"double", T_F64}, {"float64", T_F64},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        if (strcmp(s, t[i].name) == 0) return t[i].type;
    return T_NONE;
}

static size_t type_size(int t)
{
    static const size_t s[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
    return s[t];
}

/* Reads one value of type t; 0 on end of data or (ascii) a malformed number. */
static int read_value(breader *r, int fmt, int t, double *v)
{
    if (fmt == FMT_ASCII) {
        char tok[64], *end;
        if (!br_token(r, tok, sizeof tok)) return 0;
        *v = strtod(tok, &end);
        return end != tok && *end == 0;
    }
    size_t n = type_size(t);
    const unsigned char *b = br_need(r, n);
    if (!b) return 0;
    unsigned char le[8];
    for (size_t k = 0; k < n; k++) le[k] = fmt == FMT_LE ? b[k] : b[n - 1 - k];
    uint64_t u = 0;
    for (size_t k = 0; k < n; k++) u |= (uint64_t)le[k] << (8 * k);
    switch (t) {
    case T_I8: *v = (int8_t)u; break;
    case T_U8: *v = (uint8_t)u; break;
    case T_I16: *v = (int16_t)u; break;
    case T_U16: *v = (uint16_t)u; break;
    case T_I32: *v = (int32_t)u; break;
    case T_U32: *v = (uint32_t)u; break;
    case T_F32: {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, 4);
        *v = f;
        break;
    }
    default: {
        double d;
        memcpy(&d, &u, 8);
        *v = d;
        break;
    }
    }
    return 1;
}

/* Reads one property (a scalar, or a list whose items are discarded). */
static int read_prop(breader *r, int fmt, const ply_prop *pr, double *v)
{
    if (pr->count_type == T_NONE) return read_value(r, fmt, pr->type, v);
    double cnt, item;
    /* a float count may read as NaN, which passes any comparison test: !(in range) */
    if (!read_value(r, fmt, pr->count_type, &cnt) || !(cnt >= 0 && cnt <= 1e9)) return 0;
    for (long k = 0; k < (long)cnt; k++)
        if (!read_value(r, fmt, pr->type, &item)) return 0;
    *v = 0;
    return 1;
}

static int parse_header(breader *r, const char *path, int *fmt, ply_elem *el, int *nel, float *radius)
{
    char line[1024];
    if (!br_line(r, line, sizeof line) || strcmp(line, "ply") != 0)
        return fs_fail(FS_ERR_INPUT, "%s: not a PLY file (bad magic)", path);
    *fmt = -1;
    *nel = 0;
    for (;;) {
        if (!br_line(r, line, sizeof line)) return fs_fail(FS_ERR_INPUT, "%s: PLY header has no end_header", path);
        char a[64], b[64], c[64], d[64];
        int k = sscanf(line, "%63s %63s %63s %63s", a, b, c, d);
        if (k <= 0) continue;
        if (strcmp(a, "end_header") == 0) break;
        if (strcmp(a, "comment") == 0) {
            if (k >= 3 && strcmp(b, "radius") == 0) *radius = strtof(c, NULL);
        } else if (strcmp(a, "obj_info") == 0) {
        } else if (strcmp(a, "format") == 0 && k >= 2) {
            *fmt = strcmp(b, "ascii") == 0               ? FMT_ASCII
                : strcmp(b, "binary_little_endian") == 0 ? FMT_LE
                : strcmp(b, "binary_big_endian") == 0    ? FMT_BE
                                                         : -1;
            if (*fmt < 0) return fs_fail(FS_ERR_INPUT, "%s: unknown PLY format '%s'", path, b);
        } else if (strcmp(a, "element") == 0 && k == 3) {
            if (*nel == MAX_ELEMS) return fs_fail(FS_ERR_INPUT, "%s: too many PLY elements", path);
            ply_elem *e = &el[(*nel)++];
            memset(e, 0, sizeof *e);
            char *end;
            errno = 0;
            e->count = strtoull(c, &end, 10);
            if (*end || c[0] == '-' || errno) return fs_fail(FS_ERR_INPUT, "%s: bad PLY element count '%s'", path, c);
            snprintf(e->name, sizeof e->name, "%.31s", b);
        } else if (strcmp(a, "property") == 0 && k >= 3 && *nel > 0) {
            ply_elem *e = &el[*nel - 1];
            if (e->nprops == MAX_PROPS) return fs_fail(FS_ERR_INPUT, "%s: too many PLY properties", path);
            ply_prop *pr = &e->props[e->nprops++];
            int list = strcmp(b, "list") == 0;
            if (list && k < 4) return fs_fail(FS_ERR_INPUT, "%s: bad PLY header line '%s'", path, line);
            pr->count_type = list ? type_from_name(c) : T_NONE;
            pr->type = type_from_name(list ? d : b);
            if (list) sscanf(line, "%*s %*s %*s %*s %31s", pr->name);
            else snprintf(pr->name, sizeof pr->name, "%.31s", c);
            if (pr->type == T_NONE || (list && pr->count_type == T_NONE) || !pr->name[0])
                return fs_fail(FS_ERR_INPUT, "%s: bad PLY property line '%s'", path, line);
        } else {
            return fs_fail(FS_ERR_INPUT, "%s: bad PLY header line '%s'", path, line);
        }
    }
    if (*fmt < 0) return fs_fail(FS_ERR_INPUT, "%s: PLY header has no format line", path);
    return FS_OK;
}

static int find_prop(const ply_elem *e, const char *const *names)
{
    for (int i = 0; i < e->nprops; i++)
        for (const char *const *n = names; *n; n++)
            if (e->props[i].count_type == T_NONE && strcmp(e->props[i].name, *n) == 0) return i;
    return -1;
}

/* The point array type that holds PLY type t's values. */
static fs_array_type array_type_of(int t)
{
    return t == T_F32 ? FS_ARRAY_F32 : t == T_F64 ? FS_ARRAY_F64 : t == T_U32 ? FS_ARRAY_U32 : FS_ARRAY_I32;
}

/* Every scalar property of v not in used[] (a property index or -1) as a point
 * array of p; arr[k] gets property k's array, or NULL. The pointers are taken once
 * every array is added: each add may move p->arrays. */
static int add_others(const ply_elem *v, const int *used, int nused, fs_particles *p, fs_point_array **arr)
{
    int index[MAX_PROPS];
    for (int k = 0; k < v->nprops; k++) {
        int taken = v->props[k].count_type != T_NONE;
        for (int u = 0; u < nused; u++) taken |= used[u] == k;
        index[k] = -1;
        if (taken || p->narrays == FS_MAX_POINT_ARRAYS) continue;
        fs_point_array *a;
        int rc = fs_particles_add_array(p, v->props[k].name, 1, array_type_of(v->props[k].type), &a);
        if (rc) return rc;
        index[k] = p->narrays - 1;
    }
    for (int k = 0; k < v->nprops; k++) arr[k] = index[k] >= 0 ? &p->arrays[index[k]] : NULL;
    return FS_OK;
}

/* The vertex properties fluidsurf uses (indices, -1 when absent) and the colour scale. */
typedef struct vertex_props {
    int x, y, z, vx, vy, vz, r, g, b, ph, has_v, has_c;
    double cscale[3];
} vertex_props;

static int vertex_props_of(const ply_elem *v, const char *path, vertex_props *vp)
{
    static const char *const nx[] = {"x", NULL}, *const ny[] = {"y", NULL}, *const nz[] = {"z", NULL},
                             *const nvx[] = {"vx", NULL}, *const nvy[] = {"vy", NULL}, *const nvz[] = {"vz", NULL},
                             *const nr[] = {"red", "r", "diffuse_red", NULL},
                             *const ng[] = {"green", "g", "diffuse_green", NULL},
                             *const nb[] = {"blue", "b", "diffuse_blue", NULL}, *const nph[] = {"phase", NULL};
    vp->x = find_prop(v, nx), vp->y = find_prop(v, ny), vp->z = find_prop(v, nz);
    vp->vx = find_prop(v, nvx), vp->vy = find_prop(v, nvy), vp->vz = find_prop(v, nvz);
    vp->r = find_prop(v, nr), vp->g = find_prop(v, ng), vp->b = find_prop(v, nb), vp->ph = find_prop(v, nph);
    if (vp->x < 0 || vp->y < 0 || vp->z < 0)
        return fs_fail(FS_ERR_INPUT, "%s: PLY vertex element lacks x, y or z", path);
    vp->has_v = vp->vx >= 0 && vp->vy >= 0 && vp->vz >= 0, vp->has_c = vp->r >= 0 && vp->g >= 0 && vp->b >= 0;
    for (int k = 0; k < 3; k++) {
        int t = vp->has_c ? v->props[k == 0 ? vp->r : k == 1 ? vp->g : vp->b].type : T_F32;
        vp->cscale[k] = t == T_U8 ? 1.0 / 255 : t == T_U16 ? 1.0 / 65535 : 1.0;
    }
    return FS_OK;
}

/* Reads past the elements before the vertex element (index vi). */
static int skip_before(breader *r, const char *path, int fmt, const ply_elem *el, int vi)
{
    double val;
    for (int e = 0; e < vi; e++)
        if (el[e].count && !el[e].nprops) /* nothing to read: a count no data backs */
            return fs_fail(FS_ERR_INPUT, "%s: PLY element '%s' has %llu records but no properties", path, el[e].name,
                           el[e].count);
    for (int e = 0; e < vi; e++)
        for (unsigned long long i = 0; i < el[e].count; i++)
            for (int k = 0; k < el[e].nprops; k++)
                if (!read_prop(r, fmt, &el[e].props[k], &val))
                    return fs_fail(FS_ERR_INPUT, "%s: truncated or malformed PLY element '%s'", path, el[e].name);
    return FS_OK;
}

/* Refuses a vertex count the rest of the file cannot hold, before allocating for it. */
static int check_count(const breader *r, const char *path, int fmt, const ply_elem *v, unsigned long long file_size)
{
    unsigned long long left = file_size > r->consumed ? file_size - r->consumed : 0, min_record = 0;
    for (int k = 0; k < v->nprops; k++)
        min_record +=
            fmt == FMT_ASCII ? 2 : type_size(v->props[k].count_type ? v->props[k].count_type : v->props[k].type);
    if (v->count > (fmt == FMT_ASCII ? left + 1 : left) / min_record)
        return fs_fail(FS_ERR_INPUT, "%s: truncated PLY: header says %llu vertices but only %llu bytes of data follow",
                       path, v->count, left);
    return FS_OK;
}

/* Particle i from its property values val. */
static int store_vertex(fs_particles *p, size_t i, const double *val, const vertex_props *vp, int nprops,
                        fs_point_array *const *other, const char *path)
{
    p->x[i] = (float)val[vp->x], p->y[i] = (float)val[vp->y], p->z[i] = (float)val[vp->z];
    if (vp->has_v) p->vx[i] = (float)val[vp->vx], p->vy[i] = (float)val[vp->vy], p->vz[i] = (float)val[vp->vz];
    if (vp->has_c) {
        p->color[3 * i] = (float)(val[vp->r] * vp->cscale[0]);
        p->color[3 * i + 1] = (float)(val[vp->g] * vp->cscale[1]);
        p->color[3 * i + 2] = (float)(val[vp->b] * vp->cscale[2]);
    }
    if (vp->ph >= 0) {
        if (!(val[vp->ph] >= INT32_MIN && val[vp->ph] <= INT32_MAX))
            return fs_fail(FS_ERR_INPUT, "%s: PLY vertex %zu: phase out of range", path, i);
        p->phase[i] = (int32_t)val[vp->ph];
    }
    for (int k = 0; k < nprops; k++)
        if (other[k]) fs_point_array_set(other[k], i, val[k]);
    return FS_OK;
}

/* Reads the vertex element into p; elements before it are skipped. */
static int read_body(breader *r, const char *path, int fmt, const ply_elem *el, int nel, unsigned long long file_size,
                     fs_particles *p)
{
    int vi = -1;
    for (int i = 0; i < nel && vi < 0; i++)
        if (strcmp(el[i].name, "vertex") == 0) vi = i;
    if (vi < 0) return fs_fail(FS_ERR_INPUT, "%s: PLY file has no vertex element", path);
    const ply_elem *v = &el[vi];
    vertex_props vp = {0};
    int rc = vertex_props_of(v, path, &vp);
    if (!rc) rc = skip_before(r, path, fmt, el, vi);
    if (!rc) rc = check_count(r, path, fmt, v, file_size);
    unsigned fields =
        (vp.has_v ? FS_HAS_VELOCITY : 0) | (vp.has_c ? FS_HAS_COLOR : 0) | (vp.ph >= 0 ? FS_HAS_PHASE : 0);
    if (!rc) rc = fs_particles_alloc(p, (size_t)v->count, fields);
    fs_point_array *other[MAX_PROPS];
    const int used[] = {vp.x,
                        vp.y,
                        vp.z,
                        vp.has_v ? vp.vx : -1,
                        vp.has_v ? vp.vy : -1,
                        vp.has_v ? vp.vz : -1,
                        vp.has_c ? vp.r : -1,
                        vp.has_c ? vp.g : -1,
                        vp.has_c ? vp.b : -1,
                        vp.ph};
    if (!rc) rc = add_others(v, used, sizeof used / sizeof *used, p, other);
    double val[MAX_PROPS];
    for (size_t i = 0; !rc && i < p->n; i++) {
        for (int k = 0; k < v->nprops; k++)
            if (!read_prop(r, fmt, &v->props[k], &val[k]))
                return fs_fail(FS_ERR_INPUT, "%s: truncated or malformed PLY data at vertex %zu of %zu", path, i, p->n);
        rc = store_vertex(p, i, val, &vp, v->nprops, other, path);
    }
    return rc;
}

int fs_read_ply(fs_particles *p, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    breader *r = calloc(1, sizeof *r);
    ply_elem *el = calloc(MAX_ELEMS, sizeof *el);
    int rc = r && el ? FS_OK : fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    if (!rc && fstat(fileno(f), &st) != 0) rc = fs_fail(FS_ERR_INPUT, "%s: cannot stat: %s", path, strerror(errno));
    int fmt = FMT_ASCII, nel = 0;
    float radius = 0;
    if (!rc) {
        r->f = f;
        rc = parse_header(r, path, &fmt, el, &nel, &radius);
    }
    if (!rc) rc = read_body(r, path, fmt, el, nel, (unsigned long long)st.st_size, p);
    if (!rc) p->radius = radius > 0 ? radius : 0;
    if (rc) fs_particles_free(p);
    free(el);
    free(r);
    fclose(f);
    return rc;
}

/* ---- writer: binary little endian ---- */

/* A 4- or 8-byte value at v, little-endian. */
static unsigned char *put_le(unsigned char *b, const void *v, size_t n)
{
    uint64_t u;
    uint32_t u4;
    if (n == 8) memcpy(&u, v, 8);
    else memcpy(&u4, v, 4), u = u4;
    for (size_t k = 0; k < n; k++) b[k] = (unsigned char)(u >> (8 * k));
    return b + n;
}

static unsigned char *put_le32(unsigned char *b, float f) { return put_le(b, &f, 4); }

/* The header; returns the bytes of one vertex record. */
static size_t write_header(FILE *f, const fs_particles *p, unsigned fields)
{
    static const char *const ply_type[] = {"float", "double", "int", "uint"};
    size_t record = 12;
    fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment written by fluidsurf\n");
    if (p->radius > 0) fprintf(f, "comment radius %.9g\n", p->radius);
    fprintf(f, "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n", p->n);
    if (fields & FS_HAS_VELOCITY) fprintf(f, "property float vx\nproperty float vy\nproperty float vz\n"), record += 12;
    if (fields & FS_HAS_COLOR)
        fprintf(f, "property float red\nproperty float green\nproperty float blue\n"), record += 12;
    if (fields & FS_HAS_PHASE) fprintf(f, "property int phase\n"), record += 4;
    for (int i = 0; i < p->narrays; i++) {
        const fs_point_array *a = &p->arrays[i];
        char name[64];
        fs_array_safe_name(a->name, name);
        for (int c = 0; c < a->ncomp; c++) {
            if (a->ncomp == 1) fprintf(f, "property %s %s\n", ply_type[a->type], name);
            else fprintf(f, "property %s %s_%d\n", ply_type[a->type], name, c);
        }
        record += (size_t)a->ncomp * fs_array_type_size(a->type);
    }
    fprintf(f, "end_header\n");
    return record;
}

/* Particle i's record at w; returns its end. */
static unsigned char *put_record(unsigned char *w, const fs_particles *p, unsigned fields, size_t i)
{
    w = put_le32(put_le32(put_le32(w, p->x[i]), p->y[i]), p->z[i]);
    if (fields & FS_HAS_VELOCITY) w = put_le32(put_le32(put_le32(w, p->vx[i]), p->vy[i]), p->vz[i]);
    for (int k = 0; fields & FS_HAS_COLOR && k < 3; k++) w = put_le32(w, p->color[3 * i + k]);
    if (fields & FS_HAS_PHASE) w = put_le(w, &p->phase[i], 4);
    for (int a = 0; a < p->narrays; a++) {
        const fs_point_array *arr = &p->arrays[a];
        size_t sz = fs_array_type_size(arr->type), nc = (size_t)arr->ncomp;
        for (size_t c = 0; c < nc; c++) w = put_le(w, (const char *)arr->data + (i * nc + c) * sz, sz);
    }
    return w;
}

int fs_write_ply(const fs_particles *p, const char *path)
{
    fs_output out;
    int rc = fs_output_open(&out, path);
    if (rc) return rc;
    unsigned fields = fs_particles_fields(p);
    size_t record = write_header(out.f, p, fields);
    enum { CHUNK = 1024 };
    unsigned char *buf = malloc(CHUNK * record), *w = buf;
    if (!buf) {
        fs_output_close(&out, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    }
    int ok = 1;
    for (size_t i = 0; ok && i < p->n; i++) {
        w = put_record(w, p, fields, i);
        if ((i + 1) % CHUNK == 0 || i + 1 == p->n) {
            ok = fwrite(buf, 1, (size_t)(w - buf), out.f) == (size_t)(w - buf);
            w = buf;
        }
    }
    free(buf);
    return fs_output_close(&out, ok);
}
