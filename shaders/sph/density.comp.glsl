#version 450 core
// Density (poly6, boundary particles weighted by Psi) and pressure per slot;
// common/sph_cpu.c does the same in C.
#include "sph/common.glsl"
layout(local_size_x = 128) in;
uniform float u_H, u_rho0, u_B, u_k;
uniform int u_tait;
void main()
{
    uint s = gl_GlobalInvocationID.x;
    if (s >= u_n) return;
    if (sph_sidx[s] < u_nb) { sph_rho[s] = vec2(u_rho0, 0.0); return; }
    vec3 x = sph_spos[s].xyz;
    float H2 = u_H * u_H, c = 315.0 / (64.0 * 3.14159265358979) / (H2 * H2 * H2 * H2 * u_H), sum = 0.0;
    ivec3 lo, hi;
    sph_range(x, u_H, lo, hi);
    for (int k = lo.z; k <= hi.z; k++)
        for (int j = lo.y; j <= hi.y; j++) {
            uint row = sph_row(j, k), t1 = sph_start[row + uint(hi.x) + 1u];
            for (uint t = sph_start[row + uint(lo.x)]; t < t1; t++) {
                vec4 q = sph_spos[t];
                vec3 e = x - q.xyz;
                float d2 = e.x * e.x + e.y * e.y + e.z * e.z;
                if (d2 < H2) { float w = H2 - d2; sum += q.w * c * w * w * w; }
            }
        }
    float p;
    if (u_tait != 0) { float r = sum / u_rho0, r2 = r * r, r4 = r2 * r2; p = u_B * (r4 * r2 * r - 1.0); }
    else p = u_k * (sum - u_rho0);
    sph_rho[s] = vec2(sum, max(p, 0.0)); // no tension, as sph_internal.h
}
