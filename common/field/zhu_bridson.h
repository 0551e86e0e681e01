/* Zhu & Bridson's implicit surface ("Animating Sand as a Fluid", SIGGRAPH 2005,
 * section "Surface Reconstruction"; docs/DESIGN.md, "Units"):
 *
 *   phi(x) = |x - xbar(x)| - rbar(x),  xbar = sum_i w_i x_i,  rbar = sum_i w_i r_i,
 *   w_i = k(|x - x_i| / R) / sum_j k(|x - x_j| / R),  k(s) = max(0, 1 - s^2)^3,
 *
 * negative inside, the surface its zero level. R is the kernel radius (the paper:
 * twice the average particle spacing, 2 * 2r = 4r here). fluidsurf's particles share
 * one radius r, so rbar = r. Where no particle lies within R (sum k = 0) phi is
 * undefined; we take R - r there, the value a lone particle's phi reaches at
 * the edge of its support (outside). Shared by the reference's ray caster and the
 * mesh method's sampler. */
#ifndef FS_ZHU_BRIDSON_H
#define FS_ZHU_BRIDSON_H
#include "grid.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_ZB_RADIUS 4.0 /* R in multiples of r: twice the rest spacing 2r (the paper's value) */

/* Running sums over the particles within R of a point x, with y_i = x_i - x and
 * c_i = 6 (1 - s_i^2)^2 / R^2 (grad_x k_i = c_i y_i): K = sum k_i, m = sum k_i y_i,
 * g = sum c_i y_i, G = sum c_i y_i y_i^T (xx, yy, zz, xy, xz, yz). */
typedef struct fs_zb_sum {
    double K, m[3], g[3], G[6];
    size_t terms;
} fs_zb_sum;

/* k(s) of s^2 = q (0 for q >= 1). */
static inline double fs_zb_k(double q) { return q < 1 ? (1 - q) * (1 - q) * (1 - q) : 0; }

/* Adds the particle at y = x_i - x (inv_r2 = 1 / R^2); with grad 0 only K and m. */
static inline void fs_zb_add(fs_zb_sum *s, double y0, double y1, double y2, double inv_r2, int grad)
{
    double q = (y0 * y0 + y1 * y1 + y2 * y2) * inv_r2;
    if (q >= 1) return;
    double u = 1 - q, k = u * u * u;
    s->K += k;
    s->m[0] += k * y0, s->m[1] += k * y1, s->m[2] += k * y2;
    s->terms++;
    if (!grad) return;
    double c = 6 * u * u * inv_r2;
    s->g[0] += c * y0, s->g[1] += c * y1, s->g[2] += c * y2;
    s->G[0] += c * y0 * y0, s->G[1] += c * y1 * y1, s->G[2] += c * y2 * y2;
    s->G[3] += c * y0 * y1, s->G[4] += c * y0 * y2, s->G[5] += c * y1 * y2;
}

/* phi from the sums (R and r in scene units); grad (may be NULL) gets grad phi,
 * needing sums taken with grad on: grad phi = n - J^T n with n = (x - xbar) / |x - xbar|
 * and J = d xbar / dx = (G - ybar g^T) / K, ybar = m / K (0 where x = xbar or K = 0). */
double fs_zb_phi(const fs_zb_sum *s, double R, double r, float grad[3]);

/* phi at x over the particles of g (cell >= R: the 27 cells around x hold every
 * particle within R); grad as fs_zb_phi. Returns the particles within R. */
size_t fs_zb_eval(const fs_grid *g, double R, double r, const float x[3], double *phi, float grad[3]);

/* The largest |grad k_i| = 6 d (1 - d^2/R^2)^2 / R^2 for d in [d0, d1] (it peaks at R / sqrt 5). */
double fs_zb_dk_max(double d0, double d1, double R);

/* A Lipschitz bound of phi along a unit ray on [t, t+s], from the n particles
 * within R of it, each given by two floats (stride floats apart): its foot a on
 * the ray and its squared distance b from the ray's line. Where K > 0,
 * |grad phi| <= 1 + sum_i |x_i - xbar| |grad k_i| / K; on the stretch particle i
 * lies between dn_i and df_i of the ray, so |grad k_i| <= fs_zb_dk_max(dn_i, df_i),
 * K >= sum_i k(df_i / R) and |x_i - xbar| <= min(df_i, R) + D, D = max_i min(df_i, R)
 * (xbar is a convex combination of the particles within R). INFINITY when that
 * lower sum of K is 0 (K may vanish on the stretch: no bound). */
double fs_zb_lipschitz(const float *ab, size_t stride, int n, double t, double s, double R);

#ifdef __cplusplus
}
#endif
#endif
