#version 450 core
// Grid pass 6, one invocation per cell: sort the cell's slots by particle
// index (cells hold a handful), so sums run in the CPU grid's order and the
// result does not depend on atomic timing; then copy positions and velocities
// into slot order.
#include "sph/common.glsl"
layout(local_size_x = 64) in;
void main()
{
    uint c = gl_GlobalInvocationID.x;
    if (c >= u_ncells) return;
    uint s0 = sph_start[c], s1 = sph_start[c + 1u];
    for (uint s = s0 + 1u; s < s1; s++) {
        uint v = sph_sidx[s], t = s;
        while (t > s0 && sph_sidx[t - 1u] > v) { sph_sidx[t] = sph_sidx[t - 1u]; t--; }
        sph_sidx[t] = v;
    }
    for (uint s = s0; s < s1; s++) { uint i = sph_sidx[s]; sph_spos[s] = sph_pos[i]; sph_svel[s] = sph_vel[i]; }
}
