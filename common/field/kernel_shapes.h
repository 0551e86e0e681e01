/* The kernels of kernels.h without branches, for loops the compiler
 * vectorises: W(d, H) = fs_kernel_shape_c(f) * shape(d / H), each shape 0 for
 * q >= 1, equal to fs_kernel_w / C to float rounding. Used by the reference's
 * gathered sums and the mesh method's sampler. */
#ifndef FS_KERNEL_SHAPES_H
#define FS_KERNEL_SHAPES_H
#include "kernels.h"

/* max and min that compile to one instruction (fmaxf's NaN rules keep it a call). */
static inline float fs_maxf(float a, float b) { return a > b ? a : b; }
static inline float fs_minf(float a, float b) { return a < b ? a : b; }

static inline float fs_shape_cubic(float q)
{
    float t = fs_maxf(1.0f - q, 0.0f), inner = (6.0f * q - 6.0f) * q * q + 1.0f, outer = 2.0f * t * t * t;
    return q <= 0.5f ? inner : outer;
}
static inline float fs_shape_poly6(float q)
{
    float t = fs_maxf(1.0f - q * q, 0.0f);
    return t * t * t;
}
static inline float fs_shape_spiky(float q)
{
    float t = fs_maxf(1.0f - q, 0.0f);
    return t * t * t;
}
static inline float fs_shape_wyvill(float q)
{
    float a2 = fs_minf(q * q, 1.0f); /* the polynomial is 0 at a = 1 */
    return 1.0f + a2 * (-22.0f / 9.0f + a2 * (17.0f / 9.0f - a2 * (4.0f / 9.0f)));
}

/* The constant C of f's kernel at its support H. */
static inline float fs_kernel_shape_c(const fs_field *f)
{
    double H = f->H, H3 = H * H * H;
    switch (f->kernel) {
    case FS_KERNEL_POLY6: return (float)(315.0 / (64.0 * FS_PI) / H3);
    case FS_KERNEL_SPIKY: return (float)(15.0 / FS_PI / H3);
    case FS_KERNEL_WYVILL: return (float)(2835.0 / (736.0 * FS_PI) / H3);
    default: return (float)(8.0 / FS_PI / H3);
    }
}

#endif
