/* Area-weighted vertex normals and their smoothing (mesh_normals.h). */
#include "mesh_normals.h"
#include "fs_error.h"
#include "mesh_adjacency.h"
#include "vec3.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void normalise(float *n)
{
    float len = fs_v3_len(n);
    for (int a = 0; a < 3; a++) n[a] = len > 0 ? n[a] / len : 0;
}

/* Each triangle adds its cross product (twice its area times its unit normal)
 * to its corners; serial, so the sums do not depend on the thread count. */
static void area_weighted(fs_trimesh *m)
{
    memset(m->nrm, 0, m->nv * 3 * sizeof *m->nrm);
    for (size_t t = 0; t < m->nt; t++) {
        const uint32_t *c = m->tri + 3 * t;
        const float *a = m->pos + 3 * (size_t)c[0], *b = m->pos + 3 * (size_t)c[1], *d = m->pos + 3 * (size_t)c[2];
        float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        float x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        for (int k = 0; k < 3; k++)
            for (int e = 0; e < 3; e++) m->nrm[3 * (size_t)c[k] + e] += x[e];
    }
    for (size_t v = 0; v < m->nv; v++) normalise(m->nrm + 3 * v);
}

int fs_mesh_normals_smoothed(fs_trimesh *m, int iters)
{
    m->nrm = malloc((m->nv ? m->nv : 1) * 3 * sizeof *m->nrm);
    if (!m->nrm) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for %zu normals", m->nv);
    area_weighted(m);
    if (iters <= 0 || !m->nv) return FS_OK;
    fs_mesh_adjacency A = {0};
    float *tmp = malloc(m->nv * 3 * sizeof *tmp);
    int rc = tmp ? fs_mesh_adjacency_build(m, &A) : fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for normals");
    long nv = (long)m->nv;
    for (int it = 0; !rc && it < iters; it++) {
#pragma omp parallel for schedule(static)
        for (long v = 0; v < nv; v++) {
            float *o = tmp + 3 * v;
            size_t s0 = A.start[v], s1 = A.start[v + 1];
            if (s1 == s0) {
                memcpy(o, m->nrm + 3 * v, 3 * sizeof *o);
                continue;
            } /* no neighbours: kept */
            o[0] = o[1] = o[2] = 0;
            for (size_t s = s0; s < s1; s++)
                for (int a = 0; a < 3; a++) o[a] += m->nrm[3 * (size_t)A.nbr[s] + a];
            normalise(o);
        }
        memcpy(m->nrm, tmp, m->nv * 3 * sizeof *tmp);
    }
    free(tmp);
    fs_mesh_adjacency_free(&A);
    if (rc) {
        free(m->nrm);
        m->nrm = NULL;
    }
    return rc;
}

static int is_unit(const float *n)
{
    float len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    return fabsf(len2 - 1) < 1e-3f; /* false for NaN too */
}

/* A vertex whose normal needs repair: its faces' summed cross products and the
 * largest one (twice a face's area times its unit normal). */
typedef struct bad_vertex {
    float sum[3], big[3], big_len2;
} bad_vertex;

/* slot[v]: v's entry in bad, or UINT32_MAX when its normal is sound. */
static void gather_faces(const fs_trimesh *m, const uint32_t *slot, bad_vertex *bad)
{
    for (size_t t = 0; t < m->nt; t++) {
        const uint32_t *c = m->tri + 3 * t;
        if (slot[c[0]] == UINT32_MAX && slot[c[1]] == UINT32_MAX && slot[c[2]] == UINT32_MAX) continue;
        const float *a = m->pos + 3 * (size_t)c[0], *b = m->pos + 3 * (size_t)c[1], *d = m->pos + 3 * (size_t)c[2];
        float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        float x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        float len2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        for (int k = 0; k < 3; k++) {
            if (slot[c[k]] == UINT32_MAX) continue;
            bad_vertex *e = bad + slot[c[k]];
            for (int i = 0; i < 3; i++) e->sum[i] += x[i];
            if (len2 > e->big_len2) memcpy(e->big, x, sizeof x), e->big_len2 = len2;
        }
    }
}

/* The faces' mean, else the field's, else the largest face's normal. */
static void repair_one(const fs_trimesh *m, size_t v, const bad_vertex *e, fs_mesh_field_normal field, const void *ctx)
{
    float *n = m->nrm + 3 * v;
    memcpy(n, e->sum, 3 * sizeof *n);
    normalise(n);
    if (is_unit(n)) return;
    if (field && field(ctx, m->pos + 3 * v, n) && is_unit(n)) return;
    memcpy(n, e->big, 3 * sizeof *n);
    normalise(n);
}

int fs_mesh_normals_repair(fs_trimesh *m, fs_mesh_field_normal field, const void *ctx, size_t *repaired)
{
    size_t nbad = 0;
    for (size_t v = 0; v < m->nv; v++) nbad += !is_unit(m->nrm + 3 * v);
    if (repaired) *repaired = nbad;
    if (!nbad) return FS_OK;
    uint32_t *slot = malloc(m->nv * sizeof *slot);
    bad_vertex *bad = calloc(nbad, sizeof *bad);
    if (!slot || !bad) {
        free(slot), free(bad);
        return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory repairing %zu normals", nbad);
    }
    size_t k = 0;
    for (size_t v = 0; v < m->nv; v++) slot[v] = is_unit(m->nrm + 3 * v) ? UINT32_MAX : (uint32_t)k++;
    gather_faces(m, slot, bad);
    for (size_t v = 0; v < m->nv; v++)
        if (slot[v] != UINT32_MAX) repair_one(m, v, bad + slot[v], field, ctx);
    free(slot), free(bad);
    return FS_OK;
}
