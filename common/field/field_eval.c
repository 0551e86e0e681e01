/* phi and grad phi at one point (field_eval.h): the 27 cells around x hold
 * every particle within reach, because the grid's cell is at least the reach. */
#include "field_eval.h"
#include "vec3.h"

size_t fs_field_eval_at(const fs_field_eval *e, const float x[3], float *phi, float grad[3])
{
    const fs_grid *g = e->ak ? &e->ak->grid : e->g;
    float H = e->f.H, reach = e->ak ? e->ak->reach : H, V = e->f.volume;
    double s = 0, gr[3] = {0, 0, 0};
    size_t terms = 0;
    fs_grid_box b;
    fs_grid_box_around(&b, g, x);
    for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);)
        for (uint32_t sl = s0; sl < s1; sl++) {
            const float *p = g->pos4 + 4 * (size_t)sl;
            float d[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]}, u[3], w = 1;
            if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= reach * reach) continue;
            if (e->ak) { /* u = A^-1 d; grad of W(|u|)/det A is W'(|u|)/|u| A^-T u / det A */
                const float *M = e->ak->inv + 9 * (size_t)sl;
                for (int a = 0; a < 3; a++) u[a] = M[3 * a] * d[0] + M[3 * a + 1] * d[1] + M[3 * a + 2] * d[2];
                w = e->ak->wscale[sl];
            } else
                for (int a = 0; a < 3; a++) u[a] = d[a];
            float r = fs_v3_len(u);
            if (r >= H) continue;
            terms++;
            s += V * w * fs_kernel_w(e->f.kernel, r, H);
            if (!(r > 0)) continue;
            float dw = V * w * fs_kernel_dw(e->f.kernel, r, H) / r;
            if (e->ak) {
                const float *M = e->ak->inv + 9 * (size_t)sl; /* symmetric: A^-T u = A^-1 u */
                for (int a = 0; a < 3; a++) gr[a] += dw * (M[3 * a] * u[0] + M[3 * a + 1] * u[1] + M[3 * a + 2] * u[2]);
            } else
                for (int a = 0; a < 3; a++) gr[a] += dw * u[a];
        }
    *phi = (float)s;
    for (int a = 0; a < 3; a++) grad[a] = (float)gr[a];
    return terms;
}
