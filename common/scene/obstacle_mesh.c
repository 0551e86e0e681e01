/* OBJ meshes as obstacles (obstacle_mesh.h). Plain loops over the triangles behind a
 * bounding-box test: the solids of a scene are small (a few thousand triangles). */
#include "obstacle_mesh.h"
#include "fs_error.h"
#include "vec3.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct mesh_entry {
    char *path;
    fs_mesh_solid m;
} mesh_entry;
/* reachable until exit: every scene copy shares its mesh. Each entry has its own
 * allocation, so growing the list moves no mesh a scene points at. */
static mesh_entry **loaded;
static int nloaded;

typedef struct obj_reader {
    const char *path;
    float *v;
    int nv, capv;
    float *tri;
    int ntri, capt;
} obj_reader;

static int grow(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap) return 1;
    int c = *cap ? *cap : 64;
    while (c < need) c *= 2;
    void *q = realloc(*p, (size_t)c * elem);
    if (!q) return 0;
    *p = q;
    *cap = c;
    return 1;
}

/* One "f" line's vertex reference ("7", "7/1", "7//3", "-2"): the 0-based index, or -1. */
static int vertex_ref(const char *tok, int nv)
{
    char *end;
    long k = strtol(tok, &end, 10);
    if (end == tok || (*end && *end != '/')) return -1;
    if (k < 0) k += nv + 1;
    return k >= 1 && k <= nv ? (int)k - 1 : -1;
}

static int add_triangle(obj_reader *r, int a, int b, int c)
{
    if (r->ntri >= FS_MESH_MAX_TRIANGLES)
        return fs_fail(FS_ERR_INPUT, "%s: more than %d triangles", r->path, FS_MESH_MAX_TRIANGLES);
    if (!grow((void **)&r->tri, &r->capt, r->ntri + 1, 9 * sizeof(float)))
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", r->path);
    int idx[3] = {a, b, c};
    for (int k = 0; k < 3; k++) memcpy(r->tri + 9 * r->ntri + 3 * k, r->v + 3 * idx[k], 3 * sizeof(float));
    r->ntri++;
    return FS_OK;
}

static int read_line(obj_reader *r, char *line, int lineno)
{
    char *save, *tok = strtok_r(line, " \t\r\n", &save);
    if (!tok || tok[0] == '#') return FS_OK;
    if (!strcmp(tok, "v")) {
        if (!grow((void **)&r->v, &r->capv, r->nv + 1, 3 * sizeof(float)))
            return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", r->path);
        for (int k = 0; k < 3; k++) {
            char *t = strtok_r(NULL, " \t\r\n", &save), *end;
            double x = t ? strtod(t, &end) : 0;
            if (!t || *end || !isfinite(x) || fabs(x) > 1e30)
                return fs_fail(FS_ERR_INPUT, "%s: line %d: a vertex needs 3 finite numbers", r->path, lineno);
            r->v[3 * r->nv + k] = (float)x;
        }
        r->nv++;
    } else if (!strcmp(tok, "f")) {
        int first = -1, prev = -1, n = 0;
        for (char *t; (t = strtok_r(NULL, " \t\r\n", &save)); n++) {
            int k = vertex_ref(t, r->nv);
            if (k < 0)
                return fs_fail(FS_ERR_INPUT, "%s: line %d: face vertex '%s' is not one of the %d vertices so far",
                               r->path, lineno, t, r->nv);
            int rc = n >= 2 ? add_triangle(r, first, prev, k) : FS_OK;
            if (rc) return rc;
            if (!n) first = k;
            prev = k;
        }
        if (n < 3) return fs_fail(FS_ERR_INPUT, "%s: line %d: a face needs at least 3 vertices", r->path, lineno);
    }
    return FS_OK;
}

static int read_obj(const char *path, fs_mesh_solid *m)
{
    FILE *f = fopen(path, "r");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot read the mesh file", path);
    obj_reader r = {path, NULL, 0, 0, NULL, 0, 0};
    char line[4096];
    int rc = FS_OK;
    for (int lineno = 1; !rc && fgets(line, sizeof line, f); lineno++) rc = read_line(&r, line, lineno);
    fclose(f);
    free(r.v);
    if (!rc && !r.ntri) rc = fs_fail(FS_ERR_INPUT, "%s: no faces (an OBJ mesh of \"v\" and \"f\" lines)", path);
    if (rc) {
        free(r.tri);
        return rc;
    }
    m->ntri = r.ntri;
    m->tri = r.tri;
    for (int a = 0; a < 3; a++) {
        m->lo[a] = INFINITY;
        m->hi[a] = -INFINITY;
    }
    for (int i = 0; i < 3 * r.ntri; i++)
        for (int a = 0; a < 3; a++) {
            m->lo[a] = fminf(m->lo[a], r.tri[3 * i + a]);
            m->hi[a] = fmaxf(m->hi[a], r.tri[3 * i + a]);
        }
    return FS_OK;
}

int fs_mesh_solid_load(const char *path, const fs_mesh_solid **out)
{
    for (int i = 0; i < nloaded; i++)
        if (!strcmp(loaded[i]->path, path)) {
            *out = &loaded[i]->m;
            return FS_OK;
        }
    fs_mesh_solid m;
    int rc = read_obj(path, &m);
    if (rc) return rc;
    mesh_entry **grown = realloc(loaded, (size_t)(nloaded + 1) * sizeof *loaded);
    mesh_entry *e = malloc(sizeof *e);
    char *copy = strdup(path);
    if (grown) loaded = grown;
    if (!grown || !e || !copy) {
        free(copy), free(e), free(m.tri);
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    }
    e->path = copy;
    e->m = m;
    e->m.path = copy;
    loaded[nloaded++] = e;
    *out = &e->m;
    return FS_OK;
}

/* Moeller-Trumbore: t of the hit of org + t dir with triangle q, or -1. */
static float ray_triangle(const float *q, const float org[3], const float dir[3])
{
    float e1[3], e2[3], pv[3], tv[3], qv[3];
    fs_v3_sub(q + 3, q, e1);
    fs_v3_sub(q + 6, q, e2);
    fs_v3_cross(dir, e2, pv);
    float det = fs_v3_dot(e1, pv);
    if (fabsf(det) < 1e-20f) return -1;
    float inv = 1.0f / det;
    fs_v3_sub(org, q, tv);
    float u = fs_v3_dot(tv, pv) * inv;
    if (u < 0 || u > 1) return -1;
    fs_v3_cross(tv, e1, qv);
    float v = fs_v3_dot(dir, qv) * inv;
    if (v < 0 || u + v > 1) return -1;
    return fs_v3_dot(e2, qv) * inv;
}

/* Squared distance from p to triangle q (the closest point by regions, Ericson 5.1.5). */
static float point_triangle2(const float *q, const float p[3])
{
    const float *a = q, *b = q + 3, *c = q + 6;
    float ab[3], ac[3], ap[3], bp[3], cp[3], x[3];
    fs_v3_sub(b, a, ab);
    fs_v3_sub(c, a, ac);
    fs_v3_sub(p, a, ap);
    float d1 = fs_v3_dot(ab, ap), d2 = fs_v3_dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return fs_v3_dot(ap, ap);
    fs_v3_sub(p, b, bp);
    float d3 = fs_v3_dot(ab, bp), d4 = fs_v3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return fs_v3_dot(bp, bp);
    fs_v3_sub(p, c, cp);
    float d5 = fs_v3_dot(ab, cp), d6 = fs_v3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return fs_v3_dot(cp, cp);
    float vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4, s, t;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        s = d1 / (d1 - d3);
        t = 0;
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        s = 0;
        t = d2 / (d2 - d6);
    } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        s = 1 - t;
    } else {
        float den = 1.0f / (va + vb + vc);
        s = vb * den;
        t = vc * den;
    }
    for (int k = 0; k < 3; k++) x[k] = a[k] + s * ab[k] + t * ac[k] - p[k];
    return fs_v3_dot(x, x);
}

float fs_mesh_solid_distance(const fs_mesh_solid *m, const float p[3])
{
    /* An odd axis-skewed direction, so that the parity ray rarely grazes an edge. */
    static const float DIR[3] = {0.5773f, 0.5774f, 0.5775f};
    float d2 = INFINITY;
    int crossings = 0;
    for (int i = 0; i < m->ntri; i++) {
        const float *q = m->tri + 9 * i;
        d2 = fminf(d2, point_triangle2(q, p));
        crossings += ray_triangle(q, p, DIR) > 0;
    }
    return crossings & 1 ? -sqrtf(d2) : sqrtf(d2);
}

/* Whether the ray can reach the bounds before tmax (slab test). */
static int hits_bounds(const fs_mesh_solid *m, const float org[3], const float dir[3], float tmax)
{
    float t0 = 0, t1 = tmax;
    for (int a = 0; a < 3; a++) {
        if (fabsf(dir[a]) < 1e-12f) {
            if (org[a] < m->lo[a] || org[a] > m->hi[a]) return 0;
            continue;
        }
        float inv = 1.0f / dir[a], u = (m->lo[a] - org[a]) * inv, v = (m->hi[a] - org[a]) * inv;
        t0 = fmaxf(t0, fminf(u, v));
        t1 = fminf(t1, fmaxf(u, v));
    }
    return t0 <= t1;
}

int fs_mesh_solid_hit(const fs_mesh_solid *m, const float org[3], const float dir[3], float tmin, float tmax, float *t,
                      float n[3])
{
    if (!hits_bounds(m, org, dir, tmax)) return 0;
    int best = -1;
    for (int i = 0; i < m->ntri; i++) {
        float ti = ray_triangle(m->tri + 9 * i, org, dir);
        if (ti > tmin && ti < tmax) {
            tmax = ti;
            best = i;
        }
    }
    if (best < 0) return 0;
    const float *q = m->tri + 9 * best;
    float e1[3], e2[3];
    fs_v3_sub(q + 3, q, e1);
    fs_v3_sub(q + 6, q, e2);
    fs_v3_cross(e1, e2, n);
    float l = sqrtf(fs_v3_dot(n, n)), s = fs_v3_dot(n, dir) > 0 ? -1.0f : 1.0f;
    for (int k = 0; k < 3; k++) n[k] *= s / l;
    *t = tmax;
    return 1;
}
