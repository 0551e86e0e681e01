#version 450 core
// Narrow-range filter (Truong & Yuksel 2018): a Gaussian over the depths
// within a narrow range of the pixel's own: a sample farther than z + u_range
// (a surface behind) is left out, one nearer than z - u_range is clamped to
// z - u_range. u_axis 0 or 1: a 1D pass; 2: the final 2D pass.
#include "aniso_ssf/filter_common.glsl"
uniform int u_axis; // 0: along x, 1: along y, 2: 2D
ivec2 axis_dir() { return u_axis == 0 ? ivec2(1, 0) : (u_axis == 1 ? ivec2(0, 1) : ivec2(0)); }
uniform float u_range;

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_src);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_src, px).x;
    if (z <= 0.0) { imageStore(u_dst, px, vec4(0.0)); return; }
    ivec2 dir = axis_dir();
    float sp = sigma_px(z), sum = 0.0, wsum = 0.0;
    int rad = radius_px(z);
    bool two_d = dir == ivec2(0);
    for (int dy = two_d ? -rad : 0; dy <= (two_d ? rad : 0); dy++)
        for (int k = -rad; k <= rad; k++) {
            ivec2 o = two_d ? ivec2(k, dy) : k * dir;
            float zq = depth_at(px + o, size);
            if (zq <= 0.0 || zq > z + u_range) continue;
            zq = max(zq, z - u_range);
            float w = exp(-float(dot(o, o)) / (2.0 * sp * sp));
            sum += w * zq;
            wsum += w;
        }
    imageStore(u_dst, px, vec4(sum / wsum));
}
