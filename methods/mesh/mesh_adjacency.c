/* The mesh's edge graph (mesh_adjacency.h). */
#include "mesh_adjacency.h"
#include "fs_error.h"
#include <stdlib.h>

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Every triangle gives each corner its two other corners; duplicates (an edge
 * is shared by two triangles) are removed per row. */
int fs_mesh_adjacency_build(const fs_trimesh *m, fs_mesh_adjacency *A)
{
    size_t nv = m->nv;
    A->start = calloc(nv + 1, sizeof *A->start);
    A->nbr = malloc((m->nt ? m->nt : 1) * 6 * sizeof *A->nbr);
    size_t *fill = calloc(nv + 1, sizeof *fill);
    if (!A->start || !A->nbr || !fill) {
        free(fill);
        fs_mesh_adjacency_free(A);
        return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for smoothing");
    }
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

void fs_mesh_adjacency_free(fs_mesh_adjacency *A)
{
    free(A->start);
    free(A->nbr);
    A->start = NULL;
    A->nbr = NULL;
}
