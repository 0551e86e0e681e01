#version 450 core
// One screen-aligned quad per particle (instanced triangle strip), sized to the
// exact screen-space bounds of the perspective-projected sphere.
#include "common/sphere_bounds.glsl"
#ifdef POS_PACKED3
// packed float triples (a vec3 array would take 16 bytes per particle in std430)
layout(std430, binding = 0) readonly buffer Positions { float pos[]; };
vec3 sprite_pos(int i) { return vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]); }
#else
layout(std430, binding = 0) readonly buffer Positions { vec4 pos[]; };
vec3 sprite_pos(int i) { return pos[i].xyz; }
#endif
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
out flat vec3 v_center; // view space

void main()
{
    vec3 c = (u_view * vec4(sprite_pos(gl_InstanceID), 1.0)).xyz;
    v_center = c;
    sphere_sprite_corner(c, u_radius, u_proj, gl_VertexID, gl_Position);
}
