#version 450 core
// Pressure (spiky gradient; boundary particles with their extrapolated
// pressure at rho0, see boundary.comp.glsl), viscosity
// (Laplacian of the viscosity kernel), gravity; symplectic Euler; the counted
// safety clamp into the box. Writes back in particle order. Same as sph_cpu.c.
#include "sph/common.glsl"
layout(local_size_x = 128) in;
uniform float u_H, u_mu, u_g, u_dt, u_r02, u_D; // u_r02, u_D: Lennard-Jones wall repulsion (sph_cpu.c)
uniform vec3 u_box_lo, u_box_hi;
void main()
{
    uint s = gl_GlobalInvocationID.x;
    if (s >= u_n) return;
    uint i = sph_sidx[s];
    if (i < u_nb) return;
    vec4 xi = sph_spos[s];
    vec3 vi = sph_svel[s].xyz;
    vec2 ri = sph_rho[s];
    float H2 = u_H * u_H, c = 45.0 / 3.14159265358979 / (H2 * H2 * H2);
    vec3 ap = vec3(0.0), av = vec3(0.0);
    ivec3 lo, hi;
    sph_range(xi.xyz, u_H, lo, hi);
    for (int k = lo.z; k <= hi.z; k++)
        for (int j = lo.y; j <= hi.y; j++) {
            uint row = sph_row(j, k), t1 = sph_start[row + uint(hi.x) + 1u];
            for (uint t = sph_start[row + uint(lo.x)]; t < t1; t++) {
                vec4 q = sph_spos[t];
                vec3 e = xi.xyz - q.xyz;
                float d2 = e.x * e.x + e.y * e.y + e.z * e.z;
                if (d2 < H2 && d2 > 0.0) {
                    float d = sqrt(d2), h = u_H - d;
                    bool bnd = sph_sidx[t] < u_nb;
                    vec2 rj = sph_rho[t];
                    float f = q.w * (ri.y + rj.y) / (2.0 * ri.x * rj.x);
                    float gr = f * c * h * h / d;
                    if (bnd && d2 < u_r02) { float z = u_r02 / d2, z2 = z * z, z6 = z2 * z2 * z2; gr += u_D * (z6 - z2) / d2; }
                    ap += gr * e;
                    if (!bnd) av += (q.w / rj.x * c * h) * (sph_svel[t].xyz - vi);
                }
            }
        }
    vec3 v = vi + u_dt * (ap + (u_mu / ri.x) * av - vec3(0.0, u_g, 0.0));
    vec3 x = xi.xyz + u_dt * v;
    if (any(isnan(x)) || any(isinf(x)) || any(isnan(v)) || any(isinf(v))) atomicAdd(sph_stats[2], 1u);
    else {
        bvec3 below = lessThan(x, u_box_lo), above = greaterThan(x, u_box_hi);
        if (any(below) || any(above)) {
            atomicAdd(sph_stats[1], 1u);
            x = clamp(x, u_box_lo, u_box_hi);
            v = mix(v, max(v, vec3(0.0)), below);
            v = mix(v, min(v, vec3(0.0)), above);
        }
        atomicMax(sph_stats[0], floatBitsToUint(length(v)));
    }
    sph_pos[i] = vec4(x, xi.w);
    sph_vel[i] = vec4(v, 0.0);
}
