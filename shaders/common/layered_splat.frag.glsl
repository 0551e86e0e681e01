#version 450 core
// One grid point of one layer: V W(d, H) with the scene's kernel (the paper
// uses poly6; the scene's kernel keeps the grid comparable with `reference`).
// Additive float blending sums the particles.
#include "common/kernels.glsl"
#include "common/counters.glsl"
in flat vec3 g_p;        // particle (x, y), height above this layer's plane
uniform vec3 u_origin;
uniform float u_spacing;
uniform float u_H;
uniform float u_V;
uniform int u_kernel;
layout(location = 0) out float o_phi;

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    FS_COUNT(FS_CNT_TEXELS, 1); // one voxel of the layer
    vec2 x = u_origin.xy + u_spacing * (gl_FragCoord.xy - 0.5);
    vec2 d = x - g_p.xy;
    o_phi = u_V * fs_kernel_w(u_kernel, sqrt(dot(d, d) + g_p.z * g_p.z), u_H);
}
