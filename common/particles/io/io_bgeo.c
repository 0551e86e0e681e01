/* Houdini classic BGEO (version 5, as partio writes it), gzip-compressed or not.
 * Layout: "Bgeo" 'V' int32 version, 8 int32 counts, point attribute definitions,
 * then per point x y z w (float32) and its attribute values, all big-endian.
 * Primitive/detail data after the points is ignored on reading. Read: v, Cd,
 * phase, pscale (the first point's as the radius), and every numeric point
 * attribute but v, Cd and phase as a point array (particle_arrays.h; string
 * attributes are not kept); written back as float or int32 attributes. */
#include "particle_io.h"
#include "fs_error.h"
#include "particle_arrays.h"
#include "output_file.h"
#include "bytes.h"
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

enum { BGEO_FLOAT = 0, BGEO_INT = 1, BGEO_INDEX = 4, BGEO_VECTOR = 5 };

/* Decompresses the whole file (gzread also passes plain files through). */
static int load_gz(const char *path, unsigned char **out, size_t *out_size)
{
    gzFile gz = gzopen(path, "rb");
    if (!gz) return fs_fail(FS_ERR_INPUT, "%s: cannot open", path);
    size_t cap = 1 << 20, size = 0;
    unsigned char *buf = malloc(cap);
    int rc = buf ? FS_OK : fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    while (!rc) {
        if (cap - size < (1u << 20)) {
            unsigned char *nb = cap > SIZE_MAX / 2 ? NULL : realloc(buf, cap * 2);
            if (!nb) {
                rc = fs_fail(FS_ERR_RUNTIME, "%s: out of memory decompressing", path);
                break;
            }
            buf = nb;
            cap *= 2;
        }
        int got = gzread(gz, buf + size, 1u << 20);
        int err;
        const char *msg = gzerror(gz, &err);
        if (got < 0 || (err != Z_OK && err != Z_STREAM_END)) {
            rc = fs_fail(FS_ERR_INPUT, "%s: corrupt or truncated gzip data (%s)", path, msg);
            break;
        }
        if (got == 0) break;
        size += (size_t)got;
    }
    if (gzclose(gz) != Z_OK && !rc) rc = fs_fail(FS_ERR_INPUT, "%s: truncated gzip data", path);
    if (rc) {
        free(buf);
        return rc;
    }
    *out = buf;
    *out_size = size;
    return FS_OK;
}

typedef struct {
    const unsigned char *p;
    size_t left;
} cursor;

static int take(cursor *c, size_t n, const unsigned char **at)
{
    if (c->left < n) return 0;
    *at = c->p;
    c->p += n;
    c->left -= n;
    return 1;
}
static float be32f(const unsigned char *b)
{
    uint32_t u = fs_be32(b);
    float f;
    memcpy(&f, &u, 4);
    return f;
}
static int rd_u16(cursor *c, unsigned *v)
{
    const unsigned char *b;
    if (!take(c, 2, &b)) return 0;
    *v = (unsigned)b[0] << 8 | b[1];
    return 1;
}
static int rd_i32(cursor *c, int32_t *v)
{
    const unsigned char *b;
    if (!take(c, 4, &b)) return 0;
    *v = (int32_t)fs_be32(b);
    return 1;
}

typedef struct {
    char name[64];
    unsigned size;
    int32_t type;
    size_t offset;
} bgeo_attr;

/* Finds an attribute of `size` 4-byte float components by any of the given names; -1 if none. */
static int find_attr(const bgeo_attr *a, int n, unsigned size, int want_int, const char *const *names)
{
    for (int i = 0; i < n; i++) {
        int is_int = a[i].type == BGEO_INT;
        int is_float = a[i].type == BGEO_FLOAT || a[i].type == BGEO_VECTOR;
        if (a[i].size != size || (want_int ? !is_int : !is_float)) continue;
        for (const char *const *nm = names; *nm; nm++)
            if (strcmp(a[i].name, *nm) == 0) return i;
    }
    return -1;
}

/* The header: magic, version 5, the counts; npoints and nattr, the number of
 * point attribute definitions that follow. */
static int read_header(cursor *c, const char *path, int32_t *npoints, int32_t *nattr)
{
    const unsigned char *b;
    if (c->left >= 4 && c->p[0] == 0x7f && c->p[1] == 'N')
        return fs_fail(FS_ERR_INPUT, "%s: Houdini 12+ binary JSON geometry is not supported, only classic BGEO V5",
                       path);
    if (!take(c, 5, &b) || memcmp(b, "BgeoV", 5) != 0)
        return fs_fail(FS_ERR_INPUT, "%s: not a BGEO file (bad magic)", path);
    int32_t h[9]; /* version, points, prims, point groups, prim groups, point/vertex/prim/detail attribs */
    for (int i = 0; i < 9; i++)
        if (!rd_i32(c, &h[i])) return fs_fail(FS_ERR_INPUT, "%s: truncated BGEO header", path);
    if (h[0] != 5) return fs_fail(FS_ERR_INPUT, "%s: unsupported BGEO version %d (only 5)", path, (int)h[0]);
    for (int i = 1; i < 9; i++)
        if (h[i] < 0) return fs_fail(FS_ERR_INPUT, "%s: negative count %d in BGEO header", path, (int)h[i]);
    *npoints = h[1];
    *nattr = h[5];
    /* Vertex attribute definitions would sit between the point attributes and the points. */
    if (h[6] != 0) return fs_fail(FS_ERR_INPUT, "%s: BGEO vertex attributes are not supported", path);
    /* Each definition takes at least 8 bytes: reject counts the file cannot hold before allocating. */
    if ((size_t)*nattr > c->left / 8)
        return fs_fail(FS_ERR_INPUT, "%s: BGEO header claims %d point attributes, more than the file holds", path,
                       (int)*nattr);
    return FS_OK;
}

/* Skips the string table of an index attribute: a count, then u16-length strings. */
static int skip_string_table(cursor *c, const char *path, const bgeo_attr *a)
{
    const unsigned char *b;
    int32_t nstr;
    if (!rd_i32(c, &nstr) || nstr < 0)
        return fs_fail(FS_ERR_INPUT, "%s: bad string table of BGEO attribute '%s'", path, a->name);
    for (int32_t k = 0; k < nstr; k++) {
        unsigned slen;
        if (!rd_u16(c, &slen) || !take(c, slen, &b))
            return fs_fail(FS_ERR_INPUT, "%s: truncated string table of BGEO attribute '%s'", path, a->name);
    }
    return FS_OK;
}

/* Point attribute definition i: name, size, type, then its defaults (or string
 * table); a's values sit at offset *record in a point, which it then extends. */
static int read_attr_def(cursor *c, const char *path, int32_t i, bgeo_attr *a, size_t *record)
{
    unsigned len, asize;
    const unsigned char *name, *b;
    if (!rd_u16(c, &len) || !take(c, len, &name) || !rd_u16(c, &asize) || !rd_i32(c, &a->type))
        return fs_fail(FS_ERR_INPUT, "%s: truncated BGEO attribute definition %d", path, (int)i);
    size_t keep = len < sizeof a->name ? len : sizeof a->name - 1;
    memcpy(a->name, name, keep);
    a->size = asize;
    a->offset = *record;
    *record += (size_t)asize * 4; /* every supported type stores 4 bytes per component */
    int32_t type = a->type;
    if (type == BGEO_FLOAT || type == BGEO_INT || type == BGEO_VECTOR) {
        if (!take(c, (size_t)asize * 4, &b)) /* default values */
            return fs_fail(FS_ERR_INPUT, "%s: truncated defaults of BGEO attribute '%s'", path, a->name);
        return FS_OK;
    }
    if (type == BGEO_INDEX) return skip_string_table(c, path, a);
    return fs_fail(FS_ERR_INPUT, "%s: BGEO attribute '%s' has unknown type %d", path, a->name, (int)type);
}

/* The attributes read per point (indices into the definitions, -1 if absent). */
typedef struct point_attrs {
    int v, cd, phase, pscale;
} point_attrs;

/* Finds the attributes the particles keep; returns the fields they fill. */
static unsigned find_point_attrs(const bgeo_attr *attrs, int n, point_attrs *pa)
{
    static const char *const vel_names[] = {"v", "velocity", NULL}, *const cd_names[] = {"Cd", NULL},
                             *const phase_names[] = {"phase", NULL}, *const pscale_names[] = {"pscale", NULL};
    pa->v = find_attr(attrs, n, 3, 0, vel_names);
    pa->cd = find_attr(attrs, n, 3, 0, cd_names);
    pa->phase = find_attr(attrs, n, 1, 1, phase_names);
    pa->pscale = find_attr(attrs, n, 1, 0, pscale_names);
    return (pa->v >= 0 ? FS_HAS_VELOCITY : 0) | (pa->cd >= 0 ? FS_HAS_COLOR : 0) | (pa->phase >= 0 ? FS_HAS_PHASE : 0);
}

/* Particle i from its point record r. */
static void read_point(fs_particles *p, size_t i, const unsigned char *r, const bgeo_attr *attrs, const point_attrs *pa)
{
    p->x[i] = be32f(r);
    p->y[i] = be32f(r + 4);
    p->z[i] = be32f(r + 8);
    if (pa->v >= 0) {
        const unsigned char *v = r + attrs[pa->v].offset;
        p->vx[i] = be32f(v);
        p->vy[i] = be32f(v + 4);
        p->vz[i] = be32f(v + 8);
    }
    if (pa->cd >= 0)
        for (int k = 0; k < 3; k++) p->color[3 * i + k] = be32f(r + attrs[pa->cd].offset + 4 * k);
    if (pa->phase >= 0) p->phase[i] = (int32_t)fs_be32(r + attrs[pa->phase].offset);
    if (pa->pscale >= 0 && i == 0) p->radius = be32f(r + attrs[pa->pscale].offset);
}

/* Every numeric attribute but v, Cd and phase as a point array of p, filled from
 * the n points of `record` bytes at r. */
static int read_others(fs_particles *p, const unsigned char *r, size_t record, const bgeo_attr *attrs, int nattr,
                       const point_attrs *pa)
{
    for (int i = 0; i < nattr && p->narrays < FS_MAX_POINT_ARRAYS; i++) {
        const bgeo_attr *at = &attrs[i];
        if (i == pa->v || i == pa->cd || i == pa->phase || at->type == BGEO_INDEX || !at->size ||
            at->size > FS_MAX_ARRAY_COMPONENTS)
            continue;
        fs_point_array *a;
        int rc =
            fs_particles_add_array(p, at->name, (int)at->size, at->type == BGEO_INT ? FS_ARRAY_I32 : FS_ARRAY_F32, &a);
        if (rc) return rc;
        for (size_t k = 0; k < p->n * at->size; k++) {
            const unsigned char *b = r + (k / at->size) * record + at->offset + 4 * (k % at->size);
            fs_point_array_set(a, k, at->type == BGEO_INT ? (double)(int32_t)fs_be32(b) : (double)be32f(b));
        }
    }
    return FS_OK;
}

/* The n points of `record` bytes each at the cursor. */
static int read_points(fs_particles *p, const cursor *c, const bgeo_attr *attrs, int nattr, size_t n, size_t record)
{
    point_attrs pa;
    unsigned fields = find_point_attrs(attrs, nattr, &pa);
    int rc = fs_particles_alloc(p, n, fields);
    if (rc) return rc;
    for (size_t i = 0; i < n; i++) read_point(p, i, c->p + i * record, attrs, &pa);
    return read_others(p, c->p, record, attrs, nattr, &pa);
}

static int parse_bgeo(fs_particles *p, const char *path, const unsigned char *data, size_t size)
{
    cursor c = {data, size};
    int32_t npoints = 0, nattr = 0;
    int rc = read_header(&c, path, &npoints, &nattr);
    if (rc) return rc;
    bgeo_attr *attrs = calloc(nattr ? (size_t)nattr : 1, sizeof *attrs);
    if (!attrs) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    size_t record = 16; /* x y z w */
    for (int32_t i = 0; i < nattr && !rc; i++) rc = read_attr_def(&c, path, i, &attrs[i], &record);
    if (!rc && (size_t)npoints > c.left / record)
        rc = fs_fail(FS_ERR_INPUT, "%s: truncated BGEO: header says %d points of %zu bytes but only %zu bytes follow",
                     path, (int)npoints, record, c.left);
    if (!rc) rc = read_points(p, &c, attrs, nattr, (size_t)npoints, record);
    free(attrs);
    return rc;
}

int fs_read_bgeo(fs_particles *p, const char *path)
{
    unsigned char *data = NULL;
    size_t size = 0;
    int rc = load_gz(path, &data, &size);
    if (rc) return rc;
    rc = parse_bgeo(p, path, data, size);
    free(data);
    if (rc) fs_particles_free(p);
    return rc;
}

/* ---- writer ---- */

static unsigned char *put32(unsigned char *b, uint32_t v)
{
    b[0] = (unsigned char)(v >> 24);
    b[1] = (unsigned char)(v >> 16);
    b[2] = (unsigned char)(v >> 8);
    b[3] = (unsigned char)v;
    return b + 4;
}
static unsigned char *putf(unsigned char *b, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return put32(b, u);
}

/* Appends one attribute definition: name, component count, type, default values. */
static unsigned char *put_attr(unsigned char *b, const char *name, unsigned size, int type, float def)
{
    size_t len = strlen(name);
    *b++ = (unsigned char)(len >> 8);
    *b++ = (unsigned char)len;
    memcpy(b, name, len);
    b += len;
    *b++ = (unsigned char)(size >> 8);
    *b++ = (unsigned char)size;
    b = put32(b, (uint32_t)type);
    for (unsigned k = 0; k < size; k++) b = type == BGEO_INT ? put32(b, 0) : putf(b, def);
    return b;
}

/* What a point record holds besides x y z w. */
typedef struct bgeo_out {
    int has_v, has_c, has_ph, has_r; /* has_r: a constant pscale from the radius */
    size_t record;                   /* bytes of a point */
} bgeo_out;

/* The header and the attribute definitions into a malloc'ed buffer (*len bytes). */
static unsigned char *put_header(const fs_particles *p, bgeo_out *o, size_t *len)
{
    unsigned fields = fs_particles_fields(p);
    o->has_v = !!(fields & FS_HAS_VELOCITY), o->has_c = !!(fields & FS_HAS_COLOR);
    o->has_ph = !!(fields & FS_HAS_PHASE), o->has_r = p->radius > 0.0f && !fs_particles_array(p, "pscale");
    o->record = 16 + 12 * (o->has_v + o->has_c) + 4 * (o->has_ph + o->has_r);
    size_t size = 64 + 4 * 96;
    for (int i = 0; i < p->narrays; i++) size += 80 + 4 * (size_t)p->arrays[i].ncomp;
    unsigned char *head = malloc(size), *b = head;
    if (!head) return NULL;
    memcpy(b, "BgeoV", 5);
    b += 5;
    int32_t counts[9] = {5, (int32_t)p->n, 0, 0, 0, o->has_v + o->has_c + o->has_ph + o->has_r + p->narrays, 0, 0, 0};
    for (int i = 0; i < 9; i++) b = put32(b, (uint32_t)counts[i]);
    if (o->has_v) b = put_attr(b, "v", 3, BGEO_VECTOR, 0.0f);
    if (o->has_c) b = put_attr(b, "Cd", 3, BGEO_FLOAT, 1.0f);
    if (o->has_ph) b = put_attr(b, "phase", 1, BGEO_INT, 0.0f);
    if (o->has_r) b = put_attr(b, "pscale", 1, BGEO_FLOAT, p->radius);
    for (int i = 0; i < p->narrays; i++) {
        const fs_point_array *a = &p->arrays[i];
        int is_int = a->type == FS_ARRAY_I32 || a->type == FS_ARRAY_U32;
        b = put_attr(b, a->name, (unsigned)a->ncomp, is_int ? BGEO_INT : BGEO_FLOAT, 0.0f);
        o->record += 4 * (size_t)a->ncomp;
    }
    *len = (size_t)(b - head);
    return head;
}

/* Particle i's record at w (ints as int32, floats as float32); returns its end. */
static unsigned char *put_point(unsigned char *w, const fs_particles *p, const bgeo_out *o, size_t i)
{
    w = putf(putf(putf(putf(w, p->x[i]), p->y[i]), p->z[i]), 1.0f);
    if (o->has_v) w = putf(putf(putf(w, p->vx[i]), p->vy[i]), p->vz[i]);
    for (int k = 0; o->has_c && k < 3; k++) w = putf(w, p->color[3 * i + k]);
    if (o->has_ph) w = put32(w, (uint32_t)p->phase[i]);
    if (o->has_r) w = putf(w, p->radius);
    for (int a = 0; a < p->narrays; a++) {
        const fs_point_array *arr = &p->arrays[a];
        int is_int = arr->type == FS_ARRAY_I32 || arr->type == FS_ARRAY_U32;
        for (size_t c = 0, nc = (size_t)arr->ncomp; c < nc; c++) {
            double v = fs_point_array_get(arr, i * nc + c);
            w = is_int ? put32(w, (uint32_t)(int64_t)v) : putf(w, (float)v);
        }
    }
    return w;
}

int fs_write_bgeo(const fs_particles *p, const char *path)
{
    if (p->n > INT32_MAX) return fs_fail(FS_ERR_INPUT, "%s: too many particles for BGEO (%zu)", path, p->n);
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    bgeo_out o;
    size_t len = 0;
    unsigned char *head = put_header(p, &o, &len);
    enum { CHUNK = 1024 };
    unsigned char *buf = head ? malloc(CHUNK * o.record) : NULL, *w = buf;
    gzFile gz = buf ? gzopen(tmp, "wb6") : NULL;
    int ok = gz && gzwrite(gz, head, (unsigned)len) == (int)len;
    for (size_t i = 0; ok && i < p->n; i++) {
        w = put_point(w, p, &o, i);
        if ((i + 1) % CHUNK == 0 || i + 1 == p->n) {
            ok = gzwrite(gz, buf, (unsigned)(w - buf)) == (int)(w - buf);
            w = buf;
        }
    }
    static const unsigned char tail[2] = {0x00, 0xff}; /* "begin extra" / "end extra" markers */
    ok = ok && gzwrite(gz, tail, 2) == 2;
    if (gz && gzclose(gz) != Z_OK) ok = 0;
    int oom = !buf;
    free(head), free(buf);
    if (!ok) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, oom ? "%s: out of memory writing BGEO" : "%s: error writing BGEO data", path);
    }
    return fs_output_end(path, tmp, 1);
}
