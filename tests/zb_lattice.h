/* Particle sets on the 2r lattice for the Zhu & Bridson tests (test_mesh_zb,
 * test_reference_zb), written once: sites (i, j, k) in [-8, 8]^3 that keep()
 * accepts, at r = ZB_R; and the independent phi both check against. */
#ifndef FS_ZB_LATTICE_H
#define FS_ZB_LATTICE_H
#include "particles.h"
#include <math.h>

#define ZB_R 0.025

static inline void zb_lattice(fs_particles *p, int (*keep)(int, int, int))
{
    size_t n = 0;
    for (int pass = 0; pass < 2; pass++) {
        if (pass) fs_particles_alloc(p, n, 0), n = 0;
        for (int i = -8; i <= 8; i++)
            for (int j = -8; j <= 8; j++)
                for (int k = -8; k <= 8; k++) {
                    if (!keep(i, j, k)) continue;
                    if (pass)
                        p->x[n] = (float)(2 * ZB_R * i), p->y[n] = (float)(2 * ZB_R * j),
                        p->z[n] = (float)(2 * ZB_R * k);
                    n++;
                }
    }
    p->radius = (float)ZB_R;
    fs_particles_bounds(p);
}
/* A slab 16 x 16 x 6 sites, top face at z = 0, and a ball of radius about 5.2 sites. */
static inline int zb_slab_site(int i, int j, int k) { return i >= -8 && i < 8 && j >= -8 && j < 8 && k <= 0 && k > -6; }
static inline int zb_ball_site(int i, int j, int k) { return 4 * (i * i + j * j + k * k) <= 108; }

/* phi of Zhu & Bridson at x, summed over every particle in double (no grid), with
 * kernel radius kr and r = ZB_R: the tests' independent value. */
static inline double zb_indep_phi(const fs_particles *p, const double x[3], double kr)
{
    double K = 0, m[3] = {0, 0, 0};
    for (size_t i = 0; i < p->n; i++) {
        double e[3] = {p->x[i] - x[0], p->y[i] - x[1], p->z[i] - x[2]};
        double s = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) / kr, k = s < 1 ? pow(1 - s * s, 3) : 0;
        K += k, m[0] += k * p->x[i], m[1] += k * p->y[i], m[2] += k * p->z[i];
    }
    if (!(K > 0)) return kr - ZB_R;
    double e[3] = {x[0] - m[0] / K, x[1] - m[1] / K, x[2] - m[2] / K};
    return sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) - ZB_R;
}

#endif
