/* Laplacian, Taubin and weighted Laplacian smoothing (mesh_smooth.h) over the
 * mesh's edge graph (mesh_adjacency.h). */
#include "mesh_smooth.h"
#include "fs_error.h"
#include "mesh_adjacency.h"
#include <stdlib.h>
#include <string.h>

/* out = in + f_v (mean of neighbours - in) for every vertex, f_v = f w[v]
 * (w NULL: f). */
static void pass(const fs_mesh_adjacency *A, size_t nv, const float *in, float *out, float f, const float *w)
{
    long n = (long)nv;
#pragma omp parallel for schedule(static)
    for (long v = 0; v < n; v++) {
        size_t s0 = A->start[v], s1 = A->start[v + 1];
        float fv = w ? f * w[v] : f;
        for (int a = 0; a < 3; a++) {
            float x = in[3 * v + a];
            if (s1 == s0) {
                out[3 * v + a] = x;
                continue;
            }
            double sum = 0;
            for (size_t s = s0; s < s1; s++) sum += in[3 * (size_t)A->nbr[s] + a];
            out[3 * v + a] = x + fv * ((float)(sum / (double)(s1 - s0)) - x);
        }
    }
}

int fs_mesh_smooth(fs_trimesh *m, int kind, int iters, const float *w)
{
    if (kind == FS_MESH_SMOOTH_OFF || iters <= 0 || !m->nv) return FS_OK;
    if (kind == FS_MESH_SMOOTH_WEIGHTED && !w)
        return fs_fail(FS_ERR_RUNTIME, "mesh: weighted smoothing without weights");
    fs_mesh_adjacency A = {0};
    float *tmp = malloc(m->nv * 3 * sizeof *tmp);
    int rc = tmp ? fs_mesh_adjacency_build(m, &A) : fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for smoothing");
    for (int it = 0; !rc && it < iters; it++) {
        if (kind == FS_MESH_SMOOTH_WEIGHTED) pass(&A, m->nv, m->pos, tmp, (float)FS_MESH_WEIGHTED_BETA, w);
        else pass(&A, m->nv, m->pos, tmp, (float)FS_MESH_LAMBDA, NULL);
        if (kind == FS_MESH_SMOOTH_TAUBIN) pass(&A, m->nv, tmp, m->pos, (float)FS_MESH_MU, NULL);
        else memcpy(m->pos, tmp, m->nv * 3 * sizeof *tmp);
    }
    free(tmp);
    fs_mesh_adjacency_free(&A);
    return rc;
}
