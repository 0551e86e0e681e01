#version 450 core
// Separable Gaussian of the depth (Mueller et al. 2007 style, xu2022 eq. 1):
// one 1D pass along u_axis over covered pixels, weights renormalised.
#include "aniso_ssf/filter_common.glsl"
uniform int u_axis; // 0: along x, 1: along y, 2: 2D
ivec2 axis_dir() { return u_axis == 0 ? ivec2(1, 0) : (u_axis == 1 ? ivec2(0, 1) : ivec2(0)); }

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_src);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_src, px).x;
    if (z <= 0.0) { imageStore(u_dst, px, vec4(0.0)); fs_filter_done(); return; }
    ivec2 dir = axis_dir();
    float sp = sigma_px(z), sum = 0.0, wsum = 0.0;
    int rad = radius_px(z);
    for (int k = -rad; k <= rad; k++) {
        float zq = depth_at(px + k * dir, size);
        if (zq <= 0.0) continue;
        float w = exp(-float(k * k) / (2.0 * sp * sp));
        sum += w * zq;
        wsum += w;
    }
    imageStore(u_dst, px, vec4(sum / wsum)); fs_filter_done();
}
