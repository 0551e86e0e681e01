/* Zhu & Bridson's phi (common/field/zhu_bridson.h) against an independent
 * double-precision sum of its formula, on analytic cases (r = 1, R = 4 = the
 * paper's twice the spacing 2r):
 *  - one particle: phi = |x - p| - r exactly, grad phi the unit radial vector;
 *  - a slab on the rest lattice (spacing 2r, top layer at z = 0): above a top site the
 *    zero sits at z* = r + zbar(z*) = 0.885 r (xbar lies 0.115 r below the top
 *    layer there), above a hollow at 0.860 r: the formula pulls the surface of a flat
 *    lattice 0.115-0.140 r inside the ideal face (outer centres + r). The test
 *    finds both roots with its own sum and requires fs_zb_eval to agree to 1e-5 r;
 *  - the gradient against central differences on a jittered lattice;
 *  - the Lipschitz bound fs_zb_lipschitz (what the reference's march steps on):
 *    on random stretches of random rays through a jittered lattice, phi sampled
 *    densely never changes faster than the bound, and it does change faster than
 *    1 somewhere (phi is not 1-Lipschitz, so a sphere tracer on |phi| would be unsafe).
 * Breaking the weights (k = (1 - s^2)^2, or s = |x - x_i| / (2R)) moves the slab's
 * zero by more than 0.01 r and fails the slab checks. */
#include "fs_test.h"
#include "grid.h"
#include "particles.h"
#include "zhu_bridson.h"
#include <math.h>
#include <stdlib.h>

#define RAD 1.0
#define KR 4.0

/* The formula on its own: k(s) = max(0, 1 - s^2)^3, s = |x - x_i| / R. */
static double indep_phi(const float *px, const float *py, const float *pz, size_t n, const double x[3])
{
    double K = 0, m[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        double d =
            sqrt((px[i] - x[0]) * (px[i] - x[0]) + (py[i] - x[1]) * (py[i] - x[1]) + (pz[i] - x[2]) * (pz[i] - x[2]));
        double s = d / KR, k = s < 1 ? pow(1 - s * s, 3) : 0;
        K += k, m[0] += k * px[i], m[1] += k * py[i], m[2] += k * pz[i];
    }
    if (!(K > 0)) return KR - RAD;
    double e[3] = {x[0] - m[0] / K, x[1] - m[1] / K, x[2] - m[2] / K};
    return sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) - RAD;
}

static double lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

/* nx x ny x nz lattice of spacing 2r, top layer at z = 0, centred in x and y; jittered by up to jit r. */
static void lattice(fs_particles *p, int nx, int ny, int nz, double jit, uint32_t seed)
{
    fs_particles_alloc(p, (size_t)nx * ny * nz, 0);
    size_t n = 0;
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < ny; j++)
            for (int k = 0; k < nz; k++, n++) {
                p->x[n] = (float)(2 * (i - nx / 2) + jit * (2 * lcg(&seed) - 1));
                p->y[n] = (float)(2 * (j - ny / 2) + jit * (2 * lcg(&seed) - 1));
                p->z[n] = (float)(-2 * k + jit * (2 * lcg(&seed) - 1));
            }
    p->radius = (float)RAD;
    fs_particles_bounds(p);
}

static double grid_phi(const fs_grid *g, double x, double y, double z)
{
    float q[3] = {(float)x, (float)y, (float)z};
    double phi;
    fs_zb_eval(g, KR, RAD, q, &phi, NULL);
    return phi;
}

/* The zero of the independent phi on the vertical through (x, y), between 0 and 2 r. */
static double indep_root(const fs_particles *p, double x, double y)
{
    double lo = 0, hi = 2;
    for (int i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi), q[3] = {x, y, mid};
        if (indep_phi(p->x, p->y, p->z, p->n, q) < 0) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static void one_particle(void)
{
    fs_particles p;
    fs_particles_alloc(&p, 1, 0);
    p.x[0] = 0.3f, p.y[0] = -0.2f, p.z[0] = 0.1f;
    fs_particles_bounds(&p);
    fs_grid g;
    fs_grid_build(&g, &p, (float)KR);
    float x[3] = {1.9f, 0.7f, -1.1f}, gr[3];
    double phi, d = sqrt(1.6 * 1.6 + 0.9 * 0.9 + 1.2 * 1.2);
    fs_zb_eval(&g, KR, RAD, x, &phi, gr);
    CHECK_NEAR(phi, d - RAD, 1e-6, "one particle: phi = |x - p| - r");
    CHECK_NEAR(gr[0], 1.6 / d, 1e-6, "one particle: grad x");
    CHECK_NEAR(gr[2], -1.2 / d, 1e-6, "one particle: grad z");
    float far[3] = {9, 0, 0};
    fs_zb_eval(&g, KR, RAD, far, &phi, NULL);
    CHECK_NEAR(phi, KR - RAD, 0, "no particle within R: R - r");
    fs_grid_free(&g);
    fs_particles_free(&p);
}

static void slab(void)
{
    fs_particles p;
    lattice(&p, 16, 16, 6, 0, 1);
    fs_grid g;
    fs_grid_build(&g, &p, (float)KR);
    double zs = indep_root(&p, 0, 0), zh = indep_root(&p, 1, 1);
    printf("slab: zero above a top site %.4f r, above a hollow %.4f r (ideal face: 1 r)\n", zs, zh);
    CHECK(fabs(zs - 0.8850) < 5e-4, "slab: the formula's zero above a site is %.4f r, 0.8850 expected", zs);
    CHECK(fabs(zh - 0.8602) < 5e-4, "slab: the formula's zero above a hollow is %.4f r, 0.8602 expected", zh);
    CHECK(fabs(grid_phi(&g, 0, 0, zs)) < 1e-5, "slab: phi(site column, z*) = %g", grid_phi(&g, 0, 0, zs));
    CHECK(fabs(grid_phi(&g, 1, 1, zh)) < 1e-5, "slab: phi(hollow column, z*) = %g", grid_phi(&g, 1, 1, zh));
    double q[3] = {0.37, -0.61, 0.5};
    CHECK_NEAR(grid_phi(&g, q[0], q[1], q[2]), indep_phi(p.x, p.y, p.z, p.n, q), 1e-5, "slab: phi at a point");
    CHECK(grid_phi(&g, 0, 0, -5) < 0, "slab: inside is negative");
    fs_grid_free(&g);
    fs_particles_free(&p);
}

static void gradient(void)
{
    fs_particles p;
    lattice(&p, 10, 10, 4, 0.4, 7);
    fs_grid g;
    fs_grid_build(&g, &p, (float)KR);
    uint32_t s = 99;
    double worst = 0;
    for (int i = 0; i < 200; i++) {
        float x[3] = {(float)(6 * lcg(&s) - 3), (float)(6 * lcg(&s) - 3), (float)(4 * lcg(&s) - 2.5)}, gr[3];
        double phi, h = 1e-3, e = 0;
        fs_zb_eval(&g, KR, RAD, x, &phi, gr);
        for (int a = 0; a < 3; a++) {
            double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
            xp[a] += h, xm[a] -= h;
            double fd = (indep_phi(p.x, p.y, p.z, p.n, xp) - indep_phi(p.x, p.y, p.z, p.n, xm)) / (2 * h);
            e = fmax(e, fabs(fd - gr[a]));
        }
        worst = fmax(worst, e);
    }
    printf("gradient: largest difference from central differences %.2e\n", worst);
    CHECK(worst < 2e-3, "analytic gradient off central differences by %g", worst);
    fs_grid_free(&g);
    fs_particles_free(&p);
}

/* Random rays through a jittered lattice; on stretches of 0.1, 0.5 and 2 r the
 * sampled phi changes no faster than fs_zb_lipschitz says. */
static void lipschitz(void)
{
    fs_particles p;
    lattice(&p, 8, 8, 3, 0.6, 3);
    uint32_t s = 5;
    double worst = 0, steepest = 0, lens[3] = {0.1, 0.5, 2.0};
    int checked = 0;
    float *ab = malloc(2 * p.n * sizeof *ab);
    for (int ray = 0; ray < 300; ray++) {
        double o[3] = {10 * lcg(&s) - 5, 10 * lcg(&s) - 5, 3 + 2 * lcg(&s)}, d[3], len;
        do {
            for (int a = 0; a < 3; a++) d[a] = 2 * lcg(&s) - 1;
            d[2] -= 0.8;
            len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        } while (len < 0.3);
        for (int a = 0; a < 3; a++) d[a] /= len;
        for (size_t i = 0; i < p.n; i++) { /* foot and squared distance from the ray line */
            double rel[3] = {p.x[i] - o[0], p.y[i] - o[1], p.z[i] - o[2]};
            double a = rel[0] * d[0] + rel[1] * d[1] + rel[2] * d[2];
            ab[2 * i] = (float)a;
            ab[2 * i + 1] = (float)fmax(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - a * a, 0);
        }
        double t = 10 * lcg(&s), sl = lens[ray % 3];
        double L = fs_zb_lipschitz(ab, 2, (int)p.n, t, sl, KR);
        if (!isfinite(L)) continue;
        double prev = 0;
        for (int k = 0; k <= 200; k++) {
            double u = t + sl * k / 200, x[3] = {o[0] + u * d[0], o[1] + u * d[1], o[2] + u * d[2]};
            double v = indep_phi(p.x, p.y, p.z, p.n, x);
            if (k) {
                double slope = fabs(v - prev) / (sl / 200);
                worst = fmax(worst, slope / L);
                steepest = fmax(steepest, slope);
            }
            prev = v;
        }
        checked++;
    }
    printf("lipschitz: %d stretches, steepest |dphi/dt| %.3f, largest slope / bound %.3f\n", checked, steepest, worst);
    CHECK(checked > 100, "only %d stretches had a bound", checked);
    CHECK(worst <= 1.0001, "phi changed %.4f times faster than its bound", worst);
    CHECK(steepest > 1.05, "phi never steeper than %.3f: the test does not reach where the weights vary", steepest);
    free(ab);
    fs_particles_free(&p);
}

int main(void)
{
    one_particle();
    slab();
    gradient();
    lipschitz();
    TEST_DONE();
}
