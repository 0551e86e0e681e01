/* Zhu & Bridson's phi and its gradient (zhu_bridson.h). */
#include "zhu_bridson.h"
#include "vec3.h"
#include <math.h>

double fs_zb_phi(const fs_zb_sum *s, double R, double r, float grad[3])
{
    if (grad) grad[0] = grad[1] = grad[2] = 0;
    if (!(s->K > 0)) return R - r;
    double yb[3] = {s->m[0] / s->K, s->m[1] / s->K, s->m[2] / s->K};
    double len = fs_v3d_len(yb);
    if (!grad || !(len > 0)) return len - r;
    double n[3] = {-yb[0] / len, -yb[1] / len, -yb[2] / len}, ybn = yb[0] * n[0] + yb[1] * n[1] + yb[2] * n[2];
    const double *G = s->G;
    double Gn[3] = {G[0] * n[0] + G[3] * n[1] + G[4] * n[2], G[3] * n[0] + G[1] * n[1] + G[5] * n[2],
                    G[4] * n[0] + G[5] * n[1] + G[2] * n[2]};
    for (int a = 0; a < 3; a++) grad[a] = (float)(n[a] - (Gn[a] - s->g[a] * ybn) / s->K);
    return len - r;
}

size_t fs_zb_eval(const fs_grid *g, double R, double r, const float x[3], double *phi, float grad[3])
{
    fs_zb_sum s = {0};
    double inv_r2 = 1 / (R * R);
    fs_grid_box b;
    fs_grid_box_around(&b, g, x);
    for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);)
        for (uint32_t sl = s0; sl < s1; sl++) {
            const float *p = g->pos4 + 4 * (size_t)sl;
            fs_zb_add(&s, (double)p[0] - x[0], (double)p[1] - x[1], (double)p[2] - x[2], inv_r2, grad != NULL);
        }
    *phi = fs_zb_phi(&s, R, r, grad);
    return s.terms;
}

double fs_zb_dk_max(double d0, double d1, double R)
{
    double pk = R / sqrt(5.0);
    if (d1 > R) d1 = R;
    if (d0 >= d1) d1 = d0;
    double d = d0 <= pk && pk <= d1 ? pk : d0, best = 0;
    for (int i = 0; i < 3; i++) {
        double e = i == 0 ? d : (i == 1 ? d0 : d1), q = e * e / (R * R);
        if (q >= 1) continue;
        double v = 6 * e * (1 - q) * (1 - q) / (R * R);
        best = v > best ? v : best;
    }
    return best;
}

/* See zhu_bridson.h and methods/reference/reference_zb.c for the derivation. */
double fs_zb_lipschitz(const float *ab, size_t stride, int n, double t, double s, double R)
{
    double R2 = R * R, kmin = 0, D = 0, sum = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int j = 0; j < n; j++) {
            const float *q = ab + (size_t)j * stride;
            double u0 = q[0] - t, u1 = q[0] - t - s, e = u0 < 0 ? u0 : (u1 > 0 ? u1 : 0);
            double near2 = q[1] + e * e, far2 = q[1] + fmax(u0 * u0, u1 * u1);
            if (near2 >= R2) continue;
            double df = sqrt(far2);
            if (pass == 0) { /* D and the lower bound of K first */
                D = fmax(D, fmin(df, R));
                kmin += fs_zb_k(far2 / R2);
            } else sum += (fmin(df, R) + D) * fs_zb_dk_max(sqrt(near2), df, R);
        }
    return kmin > 0 ? 1 + sum / kmin : INFINITY;
}
