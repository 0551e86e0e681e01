#version 450 core
// Bilateral Gaussian filter of the normal map (xiao2017 3.3, after Aurich &
// Weule 1995): spatial Gaussian of sigma u_sigma (scene units, projected at the
// pixel's depth) times a range Gaussian on the normal difference, over pixels
// with a hit whose depth is close (a surface behind is not mixed in).
#include "common/counters.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_raw;
layout(r32f, binding = 1) uniform readonly image2D u_depth;
layout(rgba32f, binding = 2) uniform writeonly image2D u_normal;
uniform int u_enable;
uniform float u_focal_px;  // pixels per scene unit at eye depth 1
uniform float u_sigma, u_sigma_n, u_depth_gate;
uniform int u_max_radius;

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_raw);
    if (any(greaterThanEqual(px, size))) return;
    vec4 c = imageLoad(u_raw, px);
    if (c.w < 0.5 || u_enable == 0) { imageStore(u_normal, px, c); FS_COUNT(FS_CNT_TEXELS, 1); return; }
    float z = imageLoad(u_depth, px).x;
    float sp = u_sigma * u_focal_px / z; // sigma in pixels
    int rad = min(int(ceil(2.0 * sp)), u_max_radius);
    vec3 acc = vec3(0.0);
    uint taps = 0u; // texels of the window inside the image (counters.glsl)
    for (int dy = -rad; dy <= rad; dy++)
        for (int dx = -rad; dx <= rad; dx++) {
            ivec2 q = px + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            taps++;
            vec4 nq = imageLoad(u_raw, q);
            if (nq.w < 0.5) continue;
            float o2 = float(dx * dx + dy * dy);
            // Depths on one slanted surface differ with the offset: allow slopes up to ~63 degrees.
            float gate = u_depth_gate + 2.0 * sqrt(o2) * z / u_focal_px;
            if (abs(imageLoad(u_depth, q).x - z) > gate) continue;
            vec3 dn = nq.xyz - c.xyz;
            acc += exp(-o2 / (2.0 * sp * sp + 1e-12) - dot(dn, dn) / (2.0 * u_sigma_n * u_sigma_n)) * nq.xyz;
        }
    imageStore(u_normal, px, vec4(length(acc) > 0.0 ? normalize(acc) : c.xyz, 1.0));
    FS_COUNT(FS_CNT_FILTER_TAPS, taps);
    FS_COUNT(FS_CNT_TEXELS, 1);
}
