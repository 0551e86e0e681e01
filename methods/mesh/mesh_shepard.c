/* Shepard interpolation over the neighbour grid (mesh_shepard.h). */
#include "mesh_shepard.h"
#include "vec3.h"
#include <math.h>

void fs_mesh_shepard(const fs_grid *g, const fs_field *f, const float x[3], fs_shepard_value value, const void *ctx,
                     int k, double *out, uint64_t *terms)
{
    double num[4] = {0, 0, 0, 0}, den = 0;
    uint64_t t = 0;
    fs_grid_box b;
    fs_grid_box_around(&b, g, x);
    for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);)
        for (uint32_t s = s0; s < s1; s++) {
            const float *y = g->pos4 + 4 * (size_t)s;
            float d[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
            float r = fs_v3_len(d);
            if (r >= f->H) continue;
            double W = fs_kernel_w(f->kernel, r, f->H);
            for (int a = 0; a < k; a++) num[a] += W * value(ctx, s, a);
            den += W;
            t++;
        }
    for (int a = 0; a < k; a++) out[a] = den > 0 ? num[a] / den : 0;
    if (terms) *terms += t;
}
