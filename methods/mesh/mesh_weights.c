/* splashsurf's smoothing weights (mesh_weights.h), over the neighbour grid:
 * the 27 cells around a point hold every particle within H (cell >= H). */
#include "mesh_weights.h"
#include "mesh_shepard.h"
#include "fs_error.h"
#include <stdlib.h>

float fs_mesh_weight_of_count(double n, double norm)
{
    double x = n / norm;
    x = x < 0 ? 0 : (x > 1 ? 1 : x);
    return (float)(x * x * x * (10 + x * (-15 + 6 * x)));
}

/* The weighted neighbour count of each sorted slot (the particle itself excluded). */
static void particle_counts(const fs_grid *g, float H, float *n, uint64_t *terms)
{
    long np = (long)g->n;
    float H2 = H * H;
    uint64_t t = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : t)
    for (long s = 0; s < np; s++) {
        const float *x = g->pos4 + 4 * (size_t)s;
        int c[3];
        for (int a = 0; a < 3; a++) c[a] = fs_grid_coord(g, a, x[a]);
        double sum = 0;
        for (int k = c[2] - 1; k <= c[2] + 1; k++)
            for (int j = c[1] - 1; j <= c[1] + 1; j++)
                for (int i = c[0] - 1, ie; i <= c[0] + 1; i = ie + 1) {
                    uint32_t s0, s1;
                    ie = fs_grid_row_run(g, i, c[0] + 1, j, k, &s0, &s1);
                    for (uint32_t o = s0; o < s1; o++) {
                        if (o == (uint32_t)s) continue;
                        const float *y = g->pos4 + 4 * (size_t)o;
                        float d[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]},
                              d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                        if (d2 >= H2) continue;
                        sum += 1 - d2 / H2;
                        t++;
                    }
                }
        n[s] = (float)sum;
    }
    *terms += t;
}

static float count_of(const void *n, uint32_t slot, int a)
{
    (void)a;
    return ((const float *)n)[slot];
}

/* Shepard interpolation of the counts at x with the scene's kernel (0 where no
 * particle is within H). */
static double interpolate(const fs_grid *g, const fs_field *f, const float *n, const float x[3], uint64_t *terms)
{
    double mean;
    fs_mesh_shepard(g, f, x, count_of, n, 1, &mean, terms);
    return mean;
}

int fs_mesh_weights(const fs_trimesh *m, const fs_grid *g, const fs_field *f, double norm, float *w, uint64_t *terms)
{
    float *n = malloc((g->n ? g->n : 1) * sizeof *n);
    if (!n) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the smoothing weights");
    uint64_t t = 0;
    particle_counts(g, f->H, n, &t);
    long nv = (long)m->nv;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : t)
    for (long v = 0; v < nv; v++) {
        uint64_t tv = 0;
        w[v] = fs_mesh_weight_of_count(interpolate(g, f, n, m->pos + 3 * v, &tv), norm);
        t += tv;
    }
    free(n);
    if (terms) *terms += t;
    return FS_OK;
}
