/* The study's temporal measures (study_temporal.h). */
#include "study_temporal.h"

#include "obstacle_mask.h"
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

static int covers(const fs_gbuffer *g, size_t i) { return g->coverage[i] >= 0.5f; }

/* The angle of a chord of length len on the unit sphere, in degrees. */
static double chord_angle_deg(double len)
{
    double h = len / 2;
    return 2 * asin(h > 1 ? 1 : h) * 180 / M_PI;
}

double fs_study_normal_change(const fs_gbuffer *a, const fs_gbuffer *b)
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

fs_study_temporal_error fs_study_temporal_error_of(const fs_gbuffer *m0, const fs_gbuffer *m1, const fs_gbuffer *r0,
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
    fs_study_temporal_error e = {NAN, NAN};
    if (n) e.normal_deg = nsum / n, e.depth_r = dsum / n / radius;
    return e;
}

void fs_study_temporal_add(const fs_scene *s, const fs_gbuffer *a, const fs_gbuffer *b, const fs_gbuffer *ra,
                           const fs_gbuffer *rb, fs_study_temporal_sums *t)
{
    int with_ref = ra && rb, ng = with_ref ? 4 : 2;
    const fs_gbuffer *g[4] = {a, b, ra, rb};
    fs_gbuffer v[4];
    size_t n = (size_t)a->w * a->h;
    float *cov = s->obstacles.n ? malloc(4 * n * sizeof *cov) : NULL;
    if (cov && !fs_obstacle_hide(s, &s->camera, with_ref ? g + 2 : g, 2, g, ng, v, cov))
        for (int k = 0; k < ng; k++) g[k] = &v[k];
    double d = fs_study_normal_change(g[0], g[1]);
    if (isfinite(d)) t->change += d, t->n_change++;
    if (with_ref) {
        fs_study_temporal_error e = fs_study_temporal_error_of(g[0], g[1], g[2], g[3], s->radius);
        if (isfinite(e.normal_deg)) t->err_normal += e.normal_deg, t->err_depth += e.depth_r, t->n_err++;
    }
    free(cov);
}

void fs_study_temporal_means(const fs_study_temporal_sums *t, double *change, double *err_deg, double *err_depth_r)
{
    *change = t->n_change ? t->change / t->n_change : NAN;
    *err_deg = t->n_err ? t->err_normal / t->n_err : NAN;
    *err_depth_r = t->n_err ? t->err_depth / t->n_err : NAN;
}
