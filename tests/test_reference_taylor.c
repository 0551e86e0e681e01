/* The second-order step of the accelerated reference (methods/reference/
 * reference_taylor.c) against phi summed in double along random rays through
 * jittered lattices: the slope is phi's derivative, the curvature bound is at
 * least |phi''| on its stretch, phi stays on its side of iso over every proven
 * step, and it is across iso where the upper root says it must be. */
#include "fs_test.h"
#include "reference/reference.h"
#include <math.h>
#include <stdlib.h>

enum { NP = 400 };

typedef struct ray_set {
    float a[NP], b[NP], keep[NP];
    uint32_t slot[NP];
    near_soa N;
} ray_set;

static double urand(unsigned *s) { return (double)rand_r(s) / RAND_MAX; }

/* phi at local t in double, from the same feet and distances. */
static double phi_at(const fs_field *f, const near_soa *N, double t)
{
    double sum = 0;
    for (int j = 0; j < N->n; j++) {
        double u = N->a[j] - t;
        sum += fs_kernel_w(f->kernel, (float)sqrt(N->b[j] + u * u), f->H);
    }
    return sum * f->volume;
}

/* A lattice of spacing 2r jittered by up to `jit` r, cut by a random plane
 * near the origin, seen from a random line through the origin: feet and squared
 * distances of the particles within H of the line. */
static void make_ray(const fs_field *f, unsigned *seed, double jit, ray_set *S)
{
    double d[3] = {urand(seed) - 0.5, urand(seed) - 0.5, urand(seed) - 0.5}, l = 0;
    for (int k = 0; k < 3; k++) l += d[k] * d[k];
    for (int k = 0; k < 3; k++) d[k] /= sqrt(l);
    double o[3] = {urand(seed) * f->r, urand(seed) * f->r, urand(seed) * f->r}, m[3];
    for (int k = 0; k < 3; k++) m[k] = urand(seed) - 0.5;
    S->N = (near_soa){S->a, S->b, NULL, NULL, S->keep, S->slot, {0, 0, 0}, 0};
    for (int i = -6; i <= 6; i++)
        for (int j = -6; j <= 6; j++)
            for (int k = -6; k <= 6; k++) {
                double p[3] = {2 * f->r * i, 2 * f->r * j, 2 * f->r * k}, a = 0, b = 0;
                for (int x = 0; x < 3; x++) p[x] += jit * f->r * (2 * urand(seed) - 1) - o[x];
                if (p[0] * m[0] + p[1] * m[1] + p[2] * m[2] > 0) continue; /* the cut: a free surface */
                for (int x = 0; x < 3; x++) a += p[x] * d[x];
                for (int x = 0; x < 3; x++) b += (p[x] - a * d[x]) * (p[x] - a * d[x]);
                if (b < f->H * f->H && fabs(a) < 2 * f->H && S->N.n < NP) {
                    S->a[S->N.n] = (float)(a + 2 * f->H); /* local t from 0 to 4 H */
                    S->b[S->N.n++] = (float)b;
                }
            }
}

static void check_ray(const reference *R, const near_soa *N, unsigned *seed, int *proven, int *bracketed)
{
    const fs_field *f = &R->f;
    float len = 4 * f->H, M = fs_ref_curv_bound(R, N, 0, len);
    double h = 1e-3 * f->r, worst_curv = 0;
    for (int k = 0; k < 40; k++) { /* the slope and the curvature bound */
        double t = 0.5 * f->H + urand(seed) * 3 * f->H;
        float slope, phi = fs_ref_slope_sum(R, N, (float)t, &slope);
        double fd = (phi_at(f, N, t + h) - phi_at(f, N, t - h)) / (2 * h);
        double c2 = (phi_at(f, N, t + h) - 2 * phi_at(f, N, t) + phi_at(f, N, t - h)) / (h * h);
        CHECK(fabs(phi - phi_at(f, N, t)) < 1e-4, "phi %g vs %g", phi, phi_at(f, N, t));
        CHECK(fabs(slope - fd) < 1e-3 * (1 + fabs(fd)) / f->r, "slope %g vs %g", slope, fd);
        worst_curv = fmax(worst_curv, fabs(c2) / M);
    }
    CHECK(worst_curv <= 1.0, "|phi''| reaches %g of the curvature bound", worst_curv);
    double tc = -1; /* a crossing, for steps that start near it */
    for (double t = f->H; t < 3 * f->H && tc < 0; t += 0.01 * f->r)
        if ((phi_at(f, N, t) >= f->iso) != (phi_at(f, N, t + 0.01 * f->r) >= f->iso)) tc = t;
    for (int k = 0; k < 60; k++) { /* the proven steps and the bracket, from either side */
        float t =
            k < 40 || tc < 0 ? f->H + (float)urand(seed) * 2 * f->H : (float)(tc + (urand(seed) - 0.5) * 0.1 * f->r);
        float slope, g = fs_ref_slope_sum(R, N, t, &slope) - f->iso;
        float sg = g >= 0 ? 1.0f : -1.0f, lo, hi;
        fs_ref_taylor_steps(R, sg * g, sg * slope, M, &lo, &hi);
        lo = fminf(lo, len - t);
        for (int i = 1; i <= 200; i++) {
            double x = t + lo * i / 200.0;
            CHECK(sg * (phi_at(f, N, x) - f->iso) >= 0, "phi crosses iso at %g r inside a proven step of %g r",
                  (x - t) / f->r, lo / f->r);
        }
        *proven += lo > 0.1f * f->r;
        if (isfinite(hi) && t + hi < len) {
            CHECK(sg * (phi_at(f, N, t + hi) - f->iso) < 0, "phi not across iso at the upper root %g r", hi / f->r);
            (*bracketed)++;
        }
    }
}

int main(void)
{
    reference R = {0};
    R.f = (fs_field){0.025f, 0, FS_KERNEL_CUBIC, 0.1f, 0.6f};
    R.f.volume = 8 * R.f.r * R.f.r * R.f.r;
    CHECK(fs_ref_taylor_applies(&R), "the isotropic cubic spline takes the second-order step");
    unsigned seed = 7;
    int proven = 0, bracketed = 0;
    static ray_set S;
    for (int r = 0; r < 60; r++) {
        make_ray(&R.f, &seed, r % 3 == 0 ? 0.0 : 0.6, &S); /* a lattice, and jittered ones */
        check_ray(&R, &S.N, &seed, &proven, &bracketed);
    }
    /* one particle on the line: phi'' = V W''(0) there, the bound's worst case, met (h = 0.02 r: float phi) */
    float a1 = 0.2f, b1 = 0, k1 = 0, w1 = 1, keep1 = 1;
    uint32_t s1 = 0;
    near_soa one = {&a1, &b1, &k1, &w1, &keep1, &s1, {0, 0, 0}, 1};
    double h = 0.02 * R.f.r,
           c2 = (phi_at(&R.f, &one, a1 + h) - 2 * phi_at(&R.f, &one, a1) + phi_at(&R.f, &one, a1 - h)) / (h * h);
    float M1 = fs_ref_curv_bound(&R, &one, 0, 0.4f);
    CHECK(fabs(c2) <= M1 && fabs(c2) >= 0.99 * M1, "one particle: |phi''| %g against the bound %g", fabs(c2), M1);
    /* the bound must also be useful: long steps inside, and exits bracketed */
    printf("%d of 3600 steps proven longer than 0.1 r, %d brackets from the upper root\n", proven, bracketed);
    CHECK(proven > 1200 && bracketed > 200, "%d proven steps, %d brackets", proven, bracketed);
    R.f.kernel = FS_KERNEL_POLY6;
    CHECK(!fs_ref_taylor_applies(&R), "only the cubic spline's curvature bound is written");
    TEST_DONE();
}
