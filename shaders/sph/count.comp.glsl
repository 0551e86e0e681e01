#version 450 core
// Grid pass 1: each particle's cell, and a histogram of the cells.
#include "sph/common.glsl"
layout(local_size_x = 128) in;
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_n) return;
    ivec3 c = clamp(ivec3(floor((sph_pos[i].xyz - u_origin) / u_cell)), ivec3(0), u_dim - 1);
    uint id = uint((c.z * u_dim.y + c.y) * u_dim.x + c.x);
    sph_cell[i] = id;
    atomicAdd(sph_count[id], 1u);
}
