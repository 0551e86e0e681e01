/* Vector helpers on float[3] (and double[3] where a method sums in double),
 * written once for every layer. */
#ifndef FS_VEC3_H
#define FS_VEC3_H
#include <math.h>

static inline void fs_v3_sub(const float a[3], const float b[3], float o[3])
{
    o[0] = a[0] - b[0], o[1] = a[1] - b[1], o[2] = a[2] - b[2];
}
static inline float fs_v3_dot(const float a[3], const float b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline void fs_v3_cross(const float a[3], const float b[3], float o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static inline float fs_v3_len(const float a[3]) { return sqrtf(fs_v3_dot(a, a)); }
/* v scaled to unit length: 1; v left as it is when its length is 0 or NaN: 0. */
static inline int fs_v3_normalize(float v[3])
{
    float l = sqrtf(fs_v3_dot(v, v));
    if (!(l > 0)) return 0;
    v[0] /= l, v[1] /= l, v[2] /= l;
    return 1;
}
static inline double fs_v3d_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline double fs_v3d_len(const double a[3]) { return sqrt(fs_v3d_dot(a, a)); }
static inline void fs_v3d_cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

#endif
