/* raycast_pca's maths on the CPU: the Jacobi eigen-solver against matrices
 * with known eigen-systems, and the basic / PCA / blend normals of 3.3 on
 * point sets with a known plane (a flat patch, a jittered half-space lattice). */
#include "eigen3.h"
#include "kernels.h"
#include "fs_test.h"
#include "raycast_pca/pca_normal.h"
#include <stdlib.h>

/* Checks A v_k = l_k v_k, |v_k| = 1, v_j . v_k = 0 and ascending order. */
static void check_eigen(const double a[9], const char *what)
{
    double l[3], v[9];
    int sweeps = fs_eigen3_sym(a, l, v);
    double worst = 0;
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < 3; i++) {
            double av = 0;
            for (int j = 0; j < 3; j++) av += a[3 * i + j] * v[3 * k + j];
            worst = fmax(worst, fabs(av - l[k] * v[3 * k + i]));
        }
        for (int j = 0; j < 3; j++) {
            double dot = 0;
            for (int i = 0; i < 3; i++) dot += v[3 * k + i] * v[3 * j + i];
            worst = fmax(worst, fabs(dot - (j == k)));
        }
    }
    CHECK(worst < 1e-10, "%s: residual %g", what, worst);
    CHECK(l[0] <= l[1] && l[1] <= l[2], "%s: eigenvalues not ascending %g %g %g", what, l[0], l[1], l[2]);
    CHECK(sweeps < 16, "%s: no convergence", what);
}

static void jacobi(void)
{
    double diag[9] = {3, 0, 0, 0, -1, 0, 0, 0, 2}, l[3], v[9];
    fs_eigen3_sym(diag, l, v);
    CHECK_NEAR(l[0], -1, 1e-12, "diag l0");
    CHECK_NEAR(l[1], 2, 1e-12, "diag l1");
    CHECK_NEAR(l[2], 3, 1e-12, "diag l2");
    CHECK_NEAR(fabs(v[1]), 1, 1e-12, "diag: eigenvector of -1 is the y axis");
    /* Q diag(1, 2, 5) Q^T with a rotation Q whose columns are the eigenvectors. */
    double c = cos(0.7), s = sin(0.7), c2 = cos(-0.4), s2 = sin(-0.4);
    double q[9] = {c, -s, 0, s, c, 0, 0, 0, 1}, p[9] = {1, 0, 0, 0, c2, -s2, 0, s2, c2}, Q[9] = {0}, A[9] = {0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) Q[3 * i + j] += q[3 * i + k] * p[3 * k + j];
    const double lam[3] = {5, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++) A[3 * i + j] += Q[3 * i + k] * lam[k] * Q[3 * j + k];
    fs_eigen3_sym(A, l, v);
    CHECK_NEAR(l[0], 1, 1e-12, "rotated l0");
    CHECK_NEAR(l[1], 2, 1e-12, "rotated l1");
    CHECK_NEAR(l[2], 5, 1e-12, "rotated l2");
    double dot = v[0] * Q[1] + v[1] * Q[4] + v[2] * Q[7]; /* eigenvalue 1 belongs to column 1 of Q */
    CHECK_NEAR(fabs(dot), 1, 1e-12, "rotated: eigenvector of the smallest eigenvalue");
    check_eigen(A, "rotated");
    double twice[9] = {2, 1, 1, 1, 2, 1, 1, 1, 2}; /* eigenvalues 1, 1, 4 */
    fs_eigen3_sym(twice, l, v);
    CHECK_NEAR(l[0], 1, 1e-12, "repeated l0");
    CHECK_NEAR(l[2], 4, 1e-12, "repeated l2");
    check_eigen(twice, "repeated");
    double zero[9] = {0};
    check_eigen(zero, "zero");
    srand(7);
    for (int t = 0; t < 200; t++) {
        double m[9];
        for (int i = 0; i < 3; i++)
            for (int j = i; j < 3; j++) m[3 * i + j] = m[3 * j + i] = rand() / (double)RAND_MAX * 2 - 1;
        check_eigen(m, "random");
    }
}

static float frand(unsigned *st)
{
    *st = *st * 1664525u + 1013904223u;
    return (*st >> 8) / 16777216.0f * 2 - 1;
}

/* A tilted plane patch of points (jittered within the plane): PCA finds its normal. */
static void flat_patch(void)
{
    float nrm[3] = {0.36f, 0.48f, 0.8f}; /* unit */
    float t1[3] = {0.8f, -0.6f, 0},
          t2[3] = {nrm[1] * t1[2] - nrm[2] * t1[1], nrm[2] * t1[0] - nrm[0] * t1[2], nrm[0] * t1[1] - nrm[1] * t1[0]};
    float pts[3 * 121], x[3] = {0.05f * nrm[0], 0.05f * nrm[1], 0.05f * nrm[2]}; /* query above the plane */
    unsigned st = 3;
    int n = 0;
    for (int i = -5; i <= 5; i++)
        for (int j = -5; j <= 5; j++, n++) {
            float a = 0.05f * (i + 0.2f * frand(&st)), b = 0.05f * (j + 0.2f * frand(&st));
            for (int k = 0; k < 3; k++) pts[3 * n + k] = a * t1[k] + b * t2[k];
        }
    float p[3], out[3];
    CHECK(rpca_pca_normal(x, pts, n, 0.15f, 10, p), "PCA undefined on a plane patch");
    double dot = p[0] * nrm[0] + p[1] * nrm[1] + p[2] * nrm[2];
    CHECK_NEAR(fabs(dot), 1, 1e-5, "PCA normal of a flat patch");
    rpca_normal_opts o = {RPCA_NORMALS_PCA, 0.15f, 10, 0, 0.5f, 10, 0.998f};
    CHECK(rpca_normal(x, pts, n, &o, out) == 1, "PCA mode used PCA");
    CHECK(out[0] * nrm[0] + out[1] * nrm[1] + out[2] * nrm[2] > 0.99999, "signed like the basic normal (outwards)");
    /* Too few neighbours or a line of points: the basic normal. */
    o.min_neighbors = 1000;
    float b[3];
    rpca_basic_normal(x, pts, n, 0.15f, b);
    CHECK(rpca_normal(x, pts, n, &o, out) == 0 && out[0] == b[0] && out[1] == b[1] && out[2] == b[2],
          "too few neighbours: falls back to the basic normal");
    float line[3 * 9];
    for (int i = 0; i < 9; i++) {
        line[3 * i] = 0.02f * (i - 4);
        line[3 * i + 1] = 0;
        line[3 * i + 2] = 0;
    }
    float xl[3] = {0, 0.05f, 0};
    CHECK(!rpca_pca_normal(xl, line, 9, 0.15f, 3, p), "collinear points: singular covariance refused");
}

/* Query on the top of a jittered solid lattice (the fluid case): PCA beats the
 * gradient, and the blend weight follows eq. 6. */
static void half_space(void)
{
    enum { N = 15 };
    static float pts[3 * N * N * 6];
    unsigned st = 11;
    int n = 0;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            for (int k = 0; k < 6; k++, n++) {
                pts[3 * n] = 2 * (i - N / 2) + 0.1f * frand(&st);
                pts[3 * n + 1] = 2 * (j - N / 2) + 0.1f * frand(&st);
                pts[3 * n + 2] = -2 * k + 0.1f * frand(&st);
            }
    float x[3] = {0.3f, -0.4f, 0.6f}, b[3], p[3], out[3];
    rpca_basic_normal(x, pts, n, 6, b);
    CHECK(rpca_pca_normal(x, pts, n, 6, 10, p), "PCA defined on a half-space");
    double eb = acos(fmin(1, b[2])) * 180 / FS_PI, ep = acos(fmin(1, fabs(p[2]))) * 180 / FS_PI;
    printf("half-space: basic off by %.3f deg, PCA by %.3f deg\n", eb, ep);
    CHECK(ep < 1.0, "PCA normal of a half-space off by %g deg", ep);
    CHECK(b[2] > 0.9, "basic normal points out of the fluid (%g)", b[2]);
    rpca_normal_opts o = {RPCA_NORMALS_BLEND, 6, 10, 0, 0.5f, 10, 0.998f};
    CHECK(rpca_normal(x, pts, n, &o, out) == 1 && out[2] > 0.99, "blend of a half-space faces up");
    float u[3] = {0, 0, 1}, v[3] = {0, sinf(0.3f), cosf(0.3f)};
    CHECK_NEAR(rpca_blend_weight(&o, u, u), 1, 0, "eq. 6: identical normals give w = 1");
    CHECK_NEAR(rpca_blend_weight(&o, u, v), expf(10 * (cosf(0.3f) - 0.998f)), 1e-6, "eq. 6 at 17 deg");
    o.fixed_weight = 1;
    CHECK_NEAR(rpca_blend_weight(&o, u, v), 0.5, 0, "fixed w");
}

int main(void)
{
    jacobi();
    flat_patch();
    half_space();
    TEST_DONE();
}
