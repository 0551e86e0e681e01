#version 450 core
// The mesh method's triangles: view-space position and normal per vertex.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_nrm;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform mat3 u_view_rot;
out vec3 v_pos; // view space
out vec3 v_nrm; // view space, unit or 0 (no gradient there)

void main()
{
    vec4 p = u_view * vec4(a_pos, 1.0);
    v_pos = p.xyz;
    v_nrm = u_view_rot * a_nrm;
    gl_Position = u_proj * p;
}
