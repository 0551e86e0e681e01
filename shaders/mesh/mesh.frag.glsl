#version 450 core
#include "common/counters.glsl"
// MODE_DEPTH (default): eye depth and the interpolated field-gradient normal,
// depth-tested. MODE_THICKNESS: signed additive depth, the ray distance added
// at back faces (exits) and subtracted at front faces (entries): summed by the
// blender it is the path length inside a closed, outward-wound mesh.
in vec3 v_pos;
in vec3 v_nrm;
#ifdef MODE_THICKNESS
layout(location = 0) out float o_thickness;
#else
layout(location = 0) out float o_depth;
layout(location = 1) out vec4 o_normal;
#endif

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
#ifdef MODE_THICKNESS
    o_thickness = gl_FrontFacing ? -length(v_pos) : length(v_pos);
#else
    vec3 n = dot(v_nrm, v_nrm) > 0.0 ? normalize(v_nrm) : normalize(cross(dFdx(v_pos), dFdy(v_pos)));
    if (dot(n, v_pos) > 0.0) n = -n; // face the camera
    o_depth = -v_pos.z;
    o_normal = vec4(n, 1.0);
#endif
}
