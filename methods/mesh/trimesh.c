/* Small helpers of fs_trimesh (trimesh.h). */
#include "trimesh.h"
#include <stdlib.h>
#include <string.h>

void fs_trimesh_free(fs_trimesh *m)
{
    free(m->pos);
    free(m->nrm);
    free(m->tri);
    free(m->vel);
    free(m->col);
    memset(m, 0, sizeof *m);
}

double fs_trimesh_volume6(const fs_trimesh *m)
{
    double v = 0;
    long nt = (long)m->nt;
#pragma omp parallel for reduction(+ : v) schedule(static)
    for (long t = 0; t < nt; t++) {
        const float *a = m->pos + 3 * (size_t)m->tri[3 * t], *b = m->pos + 3 * (size_t)m->tri[3 * t + 1],
                    *c = m->pos + 3 * (size_t)m->tri[3 * t + 2];
        v += (double)a[0] * ((double)b[1] * c[2] - (double)b[2] * c[1]) +
            (double)a[1] * ((double)b[2] * c[0] - (double)b[0] * c[2]) +
            (double)a[2] * ((double)b[0] * c[1] - (double)b[1] * c[0]);
    }
    return v;
}

void fs_trimesh_flip(fs_trimesh *m)
{
    for (size_t t = 0; t < m->nt; t++) {
        uint32_t s = m->tri[3 * t + 1];
        m->tri[3 * t + 1] = m->tri[3 * t + 2];
        m->tri[3 * t + 2] = s;
    }
}
