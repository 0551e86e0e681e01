#version 450 core
// Grid pass 2: the sum of each block of SPH_BLOCK cells.
#include "sph/common.glsl"
layout(local_size_x = 64) in;
void main()
{
    uint b = gl_GlobalInvocationID.x;
    if (b >= u_nblocks) return;
    uint c1 = min((b + 1u) * SPH_BLOCK, u_ncells), sum = 0u;
    for (uint c = b * SPH_BLOCK; c < c1; c++) sum += sph_count[c];
    sph_block[b] = sum;
}
