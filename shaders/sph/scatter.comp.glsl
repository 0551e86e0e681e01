#version 450 core
// Grid pass 5: each particle takes a slot of its cell (any order; pass 6 sorts).
#include "sph/common.glsl"
layout(local_size_x = 128) in;
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_n) return;
    uint c = sph_cell[i];
    sph_sidx[sph_start[c] + atomicAdd(sph_count[c], 1u)] = i;
}
