#version 450 core
// One quad per surfel (instanced strip) bounding its disk's sphere. Back-face
// culling (iwasaki2006 section 5.3): a surfel whose normal faces away from the
// eye is dropped before it reaches the rasteriser.
#include "common/sphere_bounds.glsl"
struct Surfel { vec4 pos_radius; vec4 normal; };
layout(std430, binding = 0) readonly buffer Surfels { Surfel surfels[]; };
uniform mat4 u_view;
uniform mat4 u_proj;
uniform mat3 u_view_rot;
out flat vec3 v_center; // view space
out flat vec3 v_normal; // view space, unit
out flat float v_radius;
out flat vec3 v_world_normal;

void main()
{
    Surfel s = surfels[gl_InstanceID];
    vec3 c = (u_view * vec4(s.pos_radius.xyz, 1.0)).xyz;
    vec3 n = u_view_rot * s.normal.xyz;
    v_center = c;
    v_normal = n;
    v_radius = s.pos_radius.w;
    v_world_normal = s.normal.xyz;
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    if (dot(n, -c) <= 0.0) return; // back face
    sphere_sprite_corner(c, v_radius, u_proj, gl_VertexID, gl_Position);
}
