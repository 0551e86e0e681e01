#version 450 core
// Grid pass 3: exclusive prefix sum over the block sums (one invocation: a few
// thousand blocks at most), and the total into start[ncells].
#include "sph/common.glsl"
layout(local_size_x = 1) in;
void main()
{
    uint run = 0u;
    for (uint b = 0u; b < u_nblocks; b++) { uint v = sph_block[b]; sph_block[b] = run; run += v; }
    sph_start[u_ncells] = run;
}
