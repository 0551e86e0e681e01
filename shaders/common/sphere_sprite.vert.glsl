#version 450 core
// One screen-aligned quad per particle (instanced triangle strip), sized to the
// exact screen-space bounds of the perspective-projected sphere.
#include "common/sphere_bounds.glsl"
layout(std430, binding = 0) readonly buffer Positions { vec4 pos[]; };
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
out flat vec3 v_center; // view space

void main()
{
    vec3 c = (u_view * vec4(pos[gl_InstanceID].xyz, 1.0)).xyz;
    v_center = c;
    sphere_sprite_corner(c, u_radius, u_proj, gl_Position);
}
