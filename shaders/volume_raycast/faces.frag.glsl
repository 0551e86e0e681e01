#version 450 core
#include "common/counters.glsl"
// Front or back faces (the C side culls the other): the ray's entry or exit
// point in normalised volume coordinates, alpha 1 where the box is hit.
in vec3 v_uvw;
layout(location = 0) out vec4 o_uvw;

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    FS_COUNT(FS_CNT_TEXELS, 1);
    o_uvw = vec4(v_uvw, 1.0);
}
