/* Area-weighted vertex normals and their smoothing (mesh_normals.h). */
#include "mesh_normals.h"
#include "fs_error.h"
#include "mesh_adjacency.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void normalise(float *n)
{
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
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
