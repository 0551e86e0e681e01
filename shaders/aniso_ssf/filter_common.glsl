// Shared by every depth filter of aniso_ssf: eye depth in r32f images (0 where
// no sprite covers the pixel), and one world-to-pixel kernel size rule: a
// kernel of u_sigma scene units at eye depth z spans u_sigma * u_focal_px / z
// pixels, its radius 2 sigma, at most u_max_radius pixels.
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform readonly image2D u_src;
layout(r32f, binding = 1) uniform writeonly image2D u_dst;
uniform float u_focal_px; // pixels per scene unit at eye depth 1
uniform float u_sigma;    // spatial sigma, scene units
uniform int u_max_radius;

#include "common/counters.glsl"
uint fs_taps = 0u; // in-image texels this invocation's kernel read (counters.glsl)
// After the invocation's one store: its taps and one texel written.
void fs_filter_done()
{
    FS_COUNT(FS_CNT_FILTER_TAPS, fs_taps);
    FS_COUNT(FS_CNT_TEXELS, 1);
}

float sigma_px(float z) { return max(u_sigma * u_focal_px / z, 1e-3); }
int radius_px(float z) { return min(int(ceil(2.0 * sigma_px(z))), u_max_radius); }
float depth_at(ivec2 q, ivec2 size)
{
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) return 0.0;
    fs_taps++;
    return imageLoad(u_src, q).x;
}
