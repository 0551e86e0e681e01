#version 450 core
// Wall pressure of each boundary slot, extrapolated from the fluid around it
// with the hydrostatic term (Adami et al. 2012), as sph_cpu.c:
// p_b = (sum_f p_f W + sum_f rho_f g (y_f - y_b) W) / sum_f W, W = poly6 shape.
#include "sph/common.glsl"
layout(local_size_x = 128) in;
uniform float u_H, u_g;
void main()
{
    uint s = gl_GlobalInvocationID.x;
    if (s >= u_n || sph_sidx[s] >= u_nb) return;
    vec3 x = sph_spos[s].xyz;
    float H2 = u_H * u_H, sw = 0.0, sp = 0.0;
    ivec3 lo, hi;
    sph_range(x, u_H, lo, hi);
    for (int k = lo.z; k <= hi.z; k++)
        for (int j = lo.y; j <= hi.y; j++) {
            uint row = sph_row(j, k), t1 = sph_start[row + uint(hi.x) + 1u];
            for (uint t = sph_start[row + uint(lo.x)]; t < t1; t++) {
                if (sph_sidx[t] < u_nb) continue;
                vec3 e = x - sph_spos[t].xyz;
                float d2 = e.x * e.x + e.y * e.y + e.z * e.z;
                if (d2 < H2) {
                    float w = H2 - d2;
                    w = w * w * w;
                    vec2 r = sph_rho[t];
                    sw += w;
                    sp += w * (r.y - r.x * u_g * e.y);
                }
            }
        }
    sph_rho[s].y = sw > 0.0 && sp > 0.0 ? sp / sw : 0.0;
}
