#version 450 core
// The simulator's container as 12 edges (24 vertices, no buffers), for the
// viewer's overlay; eye_depth is compared with the G-buffer's depth.
uniform mat4 u_view, u_proj;
uniform vec3 u_lo, u_hi;
out float eye_depth;
const int corner[24] = int[](0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7);
void main()
{
    int c = corner[gl_VertexID];
    vec3 p = mix(u_lo, u_hi, vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
    vec4 v = u_view * vec4(p, 1.0);
    eye_depth = -v.z;
    gl_Position = u_proj * v;
}
