#version 450 core
// Bilateral Gaussian of the depth (not separable: one 2D pass): spatial
// Gaussian times a range Gaussian of sigma u_sigma_z on the depth difference.
#include "aniso_ssf/filter_common.glsl"
uniform float u_sigma_z;

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_src);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_src, px).x;
    if (z <= 0.0) { imageStore(u_dst, px, vec4(0.0)); fs_filter_done(); return; }
    float sp = sigma_px(z), sum = 0.0, wsum = 0.0;
    int rad = radius_px(z);
    for (int dy = -rad; dy <= rad; dy++)
        for (int dx = -rad; dx <= rad; dx++) {
            float zq = depth_at(px + ivec2(dx, dy), size);
            if (zq <= 0.0) continue;
            float dz = zq - z;
            float w = exp(-float(dx * dx + dy * dy) / (2.0 * sp * sp) - dz * dz / (2.0 * u_sigma_z * u_sigma_z));
            sum += w * zq;
            wsum += w;
        }
    imageStore(u_dst, px, vec4(sum / wsum)); fs_filter_done();
}
