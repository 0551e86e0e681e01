/* Laplacian and Taubin smoothing (mesh_smooth.h) over the mesh's edge graph,
 * kept as compressed rows of each vertex's distinct neighbours. */
#include "mesh_smooth.h"
#include "fs_error.h"
#include <stdlib.h>
#include <string.h>

typedef struct adjacency {
    size_t *start; /* nv + 1 */
    uint32_t *nbr;
} adjacency;

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Every triangle gives each corner its two other corners; duplicates (an edge
 * is shared by two triangles) are removed per row. */
static int build_adjacency(const fs_trimesh *m, adjacency *A)
{
    size_t nv = m->nv;
    A->start = calloc(nv + 1, sizeof *A->start);
    A->nbr = malloc((m->nt ? m->nt : 1) * 6 * sizeof *A->nbr);
    size_t *fill = calloc(nv + 1, sizeof *fill);
    if (!A->start || !A->nbr || !fill) { free(fill); return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for smoothing"); }
    for (size_t t = 0; t < 3 * m->nt; t++) A->start[m->tri[t] + 1] += 2;
    for (size_t v = 0; v < nv; v++) A->start[v + 1] += A->start[v];
    for (size_t t = 0; t < m->nt; t++)
        for (int c = 0; c < 3; c++) {
            uint32_t v = m->tri[3 * t + c];
            A->nbr[A->start[v] + fill[v]++] = m->tri[3 * t + (c + 1) % 3];
            A->nbr[A->start[v] + fill[v]++] = m->tri[3 * t + (c + 2) % 3];
        }
    /* sort and deduplicate each row, compacting in place */
    size_t w = 0;
    for (size_t v = 0; v < nv; v++) {
        size_t s0 = A->start[v], s1 = A->start[v + 1];
        qsort(A->nbr + s0, s1 - s0, sizeof *A->nbr, cmp_u32);
        A->start[v] = w;
        for (size_t s = s0; s < s1; s++)
            if (s == s0 || A->nbr[s] != A->nbr[s - 1]) A->nbr[w++] = A->nbr[s];
    }
    A->start[nv] = w;
    free(fill);
    return FS_OK;
}

/* out = in + f (mean of neighbours - in) for every vertex. */
static void pass(const adjacency *A, size_t nv, const float *in, float *out, float f)
{
    long n = (long)nv;
#pragma omp parallel for schedule(static)
    for (long v = 0; v < n; v++) {
        size_t s0 = A->start[v], s1 = A->start[v + 1];
        for (int a = 0; a < 3; a++) {
            float x = in[3 * v + a];
            if (s1 == s0) { out[3 * v + a] = x; continue; }
            double sum = 0;
            for (size_t s = s0; s < s1; s++) sum += in[3 * (size_t)A->nbr[s] + a];
            out[3 * v + a] = x + f * ((float)(sum / (double)(s1 - s0)) - x);
        }
    }
}

int fs_mesh_smooth(fs_trimesh *m, int kind, int iters)
{
    if (kind == FS_MESH_SMOOTH_OFF || iters <= 0 || !m->nv) return FS_OK;
    adjacency A = {0};
    float *tmp = malloc(m->nv * 3 * sizeof *tmp);
    int rc = tmp ? build_adjacency(m, &A) : fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for smoothing");
    for (int it = 0; !rc && it < iters; it++) {
        pass(&A, m->nv, m->pos, tmp, (float)FS_MESH_LAMBDA);
        if (kind == FS_MESH_SMOOTH_TAUBIN) pass(&A, m->nv, tmp, m->pos, (float)FS_MESH_MU);
        else memcpy(m->pos, tmp, m->nv * 3 * sizeof *tmp);
    }
    free(tmp);
    free(A.start);
    free(A.nbr);
    return rc;
}
