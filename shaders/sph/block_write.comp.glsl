#version 450 core
// Grid pass 4: start[] of every cell from its block's offset; counts become cursors.
#include "sph/common.glsl"
layout(local_size_x = 64) in;
void main()
{
    uint b = gl_GlobalInvocationID.x;
    if (b >= u_nblocks) return;
    uint c1 = min((b + 1u) * SPH_BLOCK, u_ncells), run = sph_block[b];
    for (uint c = b * SPH_BLOCK; c < c1; c++) { sph_start[c] = run; run += sph_count[c]; sph_count[c] = 0u; }
}
