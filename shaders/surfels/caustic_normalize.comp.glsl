#version 450 core
#include "common/counters.glsl"
// Caustics, per-pixel normalisation (iwasaki2006 eq. 3): n = sum g n_i / sum g
// (then made unit), d = sum g t_i / sum g. Output (n, d); w = -1 where no
// surfel covers the pixel (sum g <= u_wmin).
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) readonly uniform image2D u_acc;
layout(r32f, binding = 1) readonly uniform image2D u_dacc;
layout(rgba32f, binding = 2) writeonly uniform image2D u_out;
uniform int u_res;
uniform float u_wmin;

void main()
{
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= u_res || p.y >= u_res) return;
    vec4 a = imageLoad(u_acc, p);
    float len = length(a.xyz);
    FS_COUNT(FS_CNT_TEXELS, 1);
    if (!(a.w > u_wmin) || len <= 0.0) { imageStore(u_out, p, vec4(0.0, 0.0, 0.0, -1.0)); return; }
    imageStore(u_out, p, vec4(a.xyz / len, imageLoad(u_dacc, p).x / a.w));
}
