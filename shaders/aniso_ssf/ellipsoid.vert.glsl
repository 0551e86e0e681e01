#version 450 core
// xu2022 4.3: one screen-aligned quad per particle bounding its ellipsoid
// (common/ellipsoid_sprite.glsl: the sprite's bounds, shared with the compute
// splatter).
#include "common/ellipsoid_sprite.glsl"
layout(std430, binding = 0) readonly buffer FsAniso { vec4 aniso[]; }; // 3 vec4 per particle
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
out flat vec3 v_center; // view space
out flat mat3 v_inv;    // view-space offset -> unit-sphere parameter space

void main()
{
    uint i = 3u * uint(gl_InstanceID);
    vec3 c;
    mat3 M;
    ellipsoid_setup(aniso[i], aniso[i + 1u], aniso[i + 2u], u_view, u_radius, c, M);
    v_center = c;
    v_inv = inverse(M);
    vec4 rect;
    float z;
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    if (!ellipsoid_sprite_rect(c, M, u_proj, rect, z)) return; // reaches the eye plane: cull
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(mix(rect.x, rect.y, corner.x), mix(rect.z, rect.w, corner.y), z, 1.0);
}
