/* The second-order step of the accelerated march (README.md, step 11), on
 * either side of the surface. Inside a liquid the monotone-kernel lower bound
 * proves almost nothing (reference_interior.c says why) and the Lipschitz step
 * |g| / L is about step_min; near a crossing the doubling trials start again
 * from step_min. Along the ray, phi(t) = V sum_j W(sqrt(b_j + (t - a_j)^2)) has
 *   |phi''(t)| <= M = V sum_j max(|W''(d_j)|, |W'(d_j)/d_j|)
 * (the second derivative of each term is a convex combination of the two),
 * with d_j the particle's nearest distance to the stretch: for the cubic
 * spline the max is at most 12 C (1 - d/H) / H^2 (reference_interior.c). So
 * from a sample h = g or -g >= 0 (the march's side) with slope h1,
 *   h + h1 s - M s^2 / 2 <= (side) <= h + h1 s + M s^2 / 2:
 * the lower bound proves the side up to its root, and the upper one's first
 * root is a point where phi must be across iso; the side's slope stays
 * below h1 + M s < 0 before that root (it lies before the vertex -h1 / M),
 * so exactly one crossing lies between. Deep inside the steps are about
 * sqrt(2 h / M) (~r / 2 in a lattice liquid); near a crossing they close in
 * on it like Newton's steps and the upper root brackets it. */
#include "reference.h"
#include <math.h>

/* Relative margins over the float error of the sums (n terms of at most ~1):
 * they only shorten the proven step and lengthen the bracket. */
#define FS_TAYLOR_EPS 2e-4f

int fs_ref_taylor_applies(const reference *R) { return R->inv == NULL && R->f.kernel == FS_KERNEL_CUBIC; }

/* One build for AVX2 machines, one for any x86-64, as reference_fast.c's field_sum. */
#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx2", "default")))
#endif
float fs_ref_slope_sum(const reference *R, const near_soa *N, float t, float *slope)
{
    const float *restrict a = N->a, *restrict b = N->b;
    float inv_h = 1.0f / R->f.H, sum = 0, sl = 0;
    int n = N->n;
#pragma omp simd reduction(+ : sum, sl)
    for (int j = 0; j < n; j++) {
        float u = a[j] - t, q = sqrtf(b[j] + u * u) * inv_h, tq = fs_maxf(1.0f - q, 0.0f);
        float w_in = (6.0f * q - 6.0f) * q * q + 1.0f, w_out = 2.0f * tq * tq * tq;
        /* w'(q) / q: 18 q - 12 inside, -6 (1 - q)^2 / q outside (q > 0.5 there) */
        float wd_in = 18.0f * q - 12.0f, wd_out = -6.0f * tq * tq / fs_maxf(q, 0.5f);
        sum += q <= 0.5f ? w_in : w_out;
        sl -= (q <= 0.5f ? wd_in : wd_out) * u; /* d/dt W = C w'(q) / q (t - a) / H^2 */
    }
    float c = fs_kernel_shape_c(&R->f) * R->f.volume;
    *slope = sl * c * inv_h * inv_h;
    return sum * c;
}

float fs_ref_curv_bound(const reference *R, const near_soa *N, float u0, float u1)
{
    const float *restrict a = N->a, *restrict b = N->b;
    float inv_h = 1.0f / R->f.H, sum = 0;
    int n = N->n;
#pragma omp simd reduction(+ : sum)
    for (int j = 0; j < n; j++) {
        float e = a[j] - fs_minf(fs_maxf(a[j], u0), u1); /* foot outside [u0, u1] */
        sum += fs_maxf(1.0f - sqrtf(b[j] + e * e) * inv_h, 0.0f);
    }
    return (1.0f + FS_TAYLOR_EPS) * 12.0f * fs_kernel_shape_c(&R->f) * R->f.volume * inv_h * inv_h * sum;
}

/* The largest s >= 0 with h + h1 s - M s^2 / 2 >= 0 on [0, s] (h >= 0). */
static float root_down(float h, float h1, float M)
{
    if (h <= 0) return 0;
    float D = sqrtf(h1 * h1 + 2.0f * M * h);
    return h1 >= 0 ? (h1 + D) / M : 2.0f * h / (D - h1); /* the stable form of each */
}

/* The smallest s >= 0 with h + h1 s + M s^2 / 2 <= 0 (h >= 0), INFINITY when none. */
static float root_up(float h, float h1, float M)
{
    float D2 = h1 * h1 - 2.0f * M * h;
    if (h1 >= 0 || D2 < 0) return INFINITY;
    return 2.0f * h / (sqrtf(D2) - h1);
}

void fs_ref_taylor_steps(const reference *R, float g, float g1, float M, float *lo, float *hi)
{
    float dg = FS_TAYLOR_EPS * R->f.iso, dg1 = FS_TAYLOR_EPS * (fabsf(g1) + M * R->f.r);
    *lo = root_down(g - dg, g1 - dg1, M);
    *hi = root_up(g + dg, g1 + dg1, M);
}
