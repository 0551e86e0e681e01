#version 450 core
#include "common/view_ray.glsl"
#include "common/sphere_hit.glsl"
#include "common/ellipsoid_sprite.glsl"
#include "common/counters.glsl"
// Exact ray-ellipsoid intersection per fragment (common/ellipsoid_sprite.glsl).
// MODE_DEPTH: eye depth and view normal of the front hit, depth replaced.
// MODE_THICKNESS: the chord length, added by the blender.
uniform mat4 u_proj;
uniform vec2 u_viewport;
in flat vec3 v_center;
in flat mat3 v_inv;
#ifdef MODE_THICKNESS
layout(location = 0) out float o_thickness;
#else
layout(location = 0) out float o_depth;
layout(location = 1) out vec4 o_normal;
#endif

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    vec3 dir = fs_view_ray(gl_FragCoord.xy, u_viewport, u_proj);
    float t, chord;
    if (!ellipsoid_ray(dir, v_center, v_inv, t, chord)) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
#ifdef MODE_THICKNESS
    o_thickness = chord;
#else
    vec3 hit = dir * t;
    gl_FragDepth = window_depth(hit, u_proj);
    o_depth = -hit.z;
    o_normal = vec4(ellipsoid_normal(hit, v_center, v_inv), 1.0);
#endif
}
