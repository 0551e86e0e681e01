/* compare's temporal measures (compare_temporal.h). */
#include "compare_temporal.h"

#include <math.h>
#include <stddef.h>

static int covers(const fs_gbuffer *g, size_t i) { return g->coverage[i] >= 0.5f; }

/* The angle of a chord of length len on the unit sphere, in degrees. */
static double chord_angle_deg(double len)
{
    double h = len / 2;
    return 2 * asin(h > 1 ? 1 : h) * 180 / M_PI;
}

double cmp_normal_change(const fs_gbuffer *a, const fs_gbuffer *b)
{
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)a->w * a->h; i++) {
        if (!covers(a, i) || !covers(b, i)) continue;
        const float *p = a->normal + 3 * i, *q = b->normal + 3 * i;
        double d = p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
        sum += acos(d > 1 ? 1 : d < -1 ? -1 : d) * 180 / M_PI;
        n++;
    }
    return n ? sum / n : NAN;
}

cmp_temporal_error cmp_temporal_error_of(const fs_gbuffer *m0, const fs_gbuffer *m1, const fs_gbuffer *r0,
                                         const fs_gbuffer *r1, float radius)
{
    double nsum = 0, dsum = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)m0->w * m0->h; i++) {
        if (!covers(m0, i) || !covers(m1, i) || !covers(r0, i) || !covers(r1, i)) continue;
        double len2 = 0;
        for (int c = 0; c < 3; c++) {
            size_t k = 3 * i + c;
            double v = ((double)m1->normal[k] - m0->normal[k]) - ((double)r1->normal[k] - r0->normal[k]);
            len2 += v * v;
        }
        nsum += chord_angle_deg(sqrt(len2));
        dsum += fabs(((double)m1->depth[i] - m0->depth[i]) - ((double)r1->depth[i] - r0->depth[i]));
        n++;
    }
    cmp_temporal_error e = {NAN, NAN};
    if (n) e.normal_deg = nsum / n, e.depth_r = dsum / n / radius;
    return e;
}
