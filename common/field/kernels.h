/* SPH kernels, each defined by its support radius H and normalised so that it
 * integrates to 1 over 3D space (docs/DESIGN.md, Units). shaders/common/kernels.glsl
 * holds the same formulas and constants; tests/test_kernels checks they agree. */
#ifndef FS_KERNELS_H
#define FS_KERNELS_H
#include <math.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_PI 3.14159265358979323846

typedef enum { FS_KERNEL_CUBIC = 0, FS_KERNEL_POLY6, FS_KERNEL_SPIKY, FS_KERNEL_WYVILL, FS_KERNEL_COUNT } fs_kernel;

/* Cubic spline (Monaghan), support H: q = d/H,
 * W = 8/(pi H^3) * (6q^3 - 6q^2 + 1) for q <= 1/2, 16/(pi H^3) (1-q)^3 for q <= 1. */
static inline float fs_cubic_w(float d, float H)
{
    float q = d / H, s = (float)(8.0 / FS_PI) / (H * H * H);
    if (q <= 0.5f) return s * (6.0f * q * q * q - 6.0f * q * q + 1.0f);
    if (q < 1.0f) {
        float t = 1.0f - q;
        return 2.0f * s * t * t * t;
    }
    return 0.0f;
}
/* dW/dd (<= 0). */
static inline float fs_cubic_dw(float d, float H)
{
    float q = d / H, s = (float)(8.0 / FS_PI) / (H * H * H * H);
    if (q <= 0.5f) return s * (18.0f * q * q - 12.0f * q);
    if (q < 1.0f) {
        float t = 1.0f - q;
        return -6.0f * s * t * t;
    }
    return 0.0f;
}

/* Poly6 (Mueller et al. 2003): 315/(64 pi H^9) (H^2 - d^2)^3. */
static inline float fs_poly6_w(float d, float H)
{
    if (d >= H) return 0.0f;
    float t = H * H - d * d, H3 = H * H * H;
    return (float)(315.0 / (64.0 * FS_PI)) / (H3 * H3 * H3) * t * t * t;
}
static inline float fs_poly6_dw(float d, float H)
{
    if (d >= H) return 0.0f;
    float t = H * H - d * d, H3 = H * H * H;
    return -6.0f * d * (float)(315.0 / (64.0 * FS_PI)) / (H3 * H3 * H3) * t * t;
}

/* Spiky (Desbrun & Gascuel / Mueller 2003): 15/(pi H^6) (H - d)^3; its gradient
 * is the one SPH normal estimates use (xiao2017 eq. 2). */
static inline float fs_spiky_w(float d, float H)
{
    if (d >= H) return 0.0f;
    float t = H - d, H3 = H * H * H;
    return (float)(15.0 / FS_PI) / (H3 * H3) * t * t * t;
}
static inline float fs_spiky_dw(float d, float H)
{
    if (d >= H) return 0.0f;
    float t = H - d, H3 = H * H * H;
    return -(float)(45.0 / FS_PI) / (H3 * H3) * t * t;
}

/* Wyvill & Trotman's soft-object function (iwasaki2006 eq. 1), a = d/H:
 * 1 - 4/9 a^6 + 17/9 a^4 - 22/9 a^2, renormalised in 3D: the integral of the
 * bracket over the unit ball is 736 pi / 2835, so C = 2835 / (736 pi H^3). */
static inline float fs_wyvill_w(float d, float H)
{
    if (d >= H) return 0.0f;
    float a2 = (d * d) / (H * H);
    float p = 1.0f + a2 * (-22.0f / 9.0f + a2 * (17.0f / 9.0f - a2 * (4.0f / 9.0f)));
    return (float)(2835.0 / (736.0 * FS_PI)) / (H * H * H) * p;
}
static inline float fs_wyvill_dw(float d, float H)
{
    if (d >= H) return 0.0f;
    float a2 = (d * d) / (H * H);
    float dp = -44.0f / 9.0f + a2 * (68.0f / 9.0f - a2 * (24.0f / 9.0f)); /* d/da of p, divided by a */
    return (float)(2835.0 / (736.0 * FS_PI)) / (H * H * H) * dp * d / (H * H);
}

static inline float fs_kernel_w(fs_kernel k, float d, float H)
{
    switch (k) {
    case FS_KERNEL_POLY6: return fs_poly6_w(d, H);
    case FS_KERNEL_SPIKY: return fs_spiky_w(d, H);
    case FS_KERNEL_WYVILL: return fs_wyvill_w(d, H);
    default: return fs_cubic_w(d, H);
    }
}
static inline float fs_kernel_dw(fs_kernel k, float d, float H)
{
    switch (k) {
    case FS_KERNEL_POLY6: return fs_poly6_dw(d, H);
    case FS_KERNEL_SPIKY: return fs_spiky_dw(d, H);
    case FS_KERNEL_WYVILL: return fs_wyvill_dw(d, H);
    default: return fs_cubic_dw(d, H);
    }
}
/* An upper bound of |dW/dd| over [0, H], used for safe ray-march steps. */
float fs_kernel_max_dw(fs_kernel k, float H);
const char *fs_kernel_name(fs_kernel k);
/* Returns -1 for an unknown name. */
int fs_kernel_from_name(const char *name);

/* The scalar field of docs/DESIGN.md: phi(x) = sum_j V W(|x - p_j|, H). */
typedef struct fs_field {
    float r;      /* particle radius */
    float volume; /* V = volume_scale * (2r)^3 */
    fs_kernel kernel;
    float H;   /* support radius, scene units */
    float iso; /* iso value on the phi scale */
} fs_field;

#ifdef __cplusplus
}
#endif
#endif
