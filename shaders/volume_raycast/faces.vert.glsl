#version 450 core
// inacio2010 IV-B: the volume's bounding box, 12 triangles from a storage
// buffer (36 corners in normalised volume coordinates, counter-clockwise seen
// from outside); each fragment gets the normalised coordinate of its box point.
layout(std430, binding = 0) readonly buffer Corners { vec4 corner[]; };
uniform mat4 u_view, u_proj;
uniform vec3 u_box_origin, u_box_extent; // world box of the grid points
out vec3 v_uvw;

void main()
{
    v_uvw = corner[gl_VertexID].xyz;
    gl_Position = u_proj * u_view * vec4(u_box_origin + v_uvw * u_box_extent, 1.0);
}
