#version 450 core
// Slice splatting, one 4-plane pass: the fragment is the grid point at the
// pixel centre; channel c receives V W(d_c, H) with d_c the 3D distance from
// the particle to that grid point on plane c. Additive float blending sums the
// particles. The paper looks the kernel up in a 1D texture; the kernel is
// evaluated here with the same formulas as the C code (common/kernels.glsl).
#include "common/kernels.glsl"
#include "common/counters.glsl"
in flat vec3 v_p;        // particle in (a, b, up)
uniform vec2 u_origin;   // world (a, b) of grid point (0, 0)
uniform float u_spacing;
uniform vec4 u_planes;   // up coordinate of the four planes
uniform float u_H;
uniform float u_V;       // particle volume
uniform int u_kernel;    // fs_kernel id
layout(location = 0) out vec4 o_phi;

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    FS_COUNT(FS_CNT_TEXELS, 4); // four voxels: one plane per channel
    vec2 x = u_origin + u_spacing * (gl_FragCoord.xy - 0.5);
    vec2 d = x - v_p.xy;
    float r2 = dot(d, d);
    vec4 dz = u_planes - v_p.z;
    vec4 dist = sqrt(r2 + dz * dz);
    vec4 w;
    for (int c = 0; c < 4; c++) w[c] = fs_kernel_w(u_kernel, dist[c], u_H);
    o_phi = u_V * w;
}
