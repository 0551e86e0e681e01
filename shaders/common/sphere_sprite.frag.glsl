#version 450 core
#include "common/view_ray.glsl"
#include "common/sphere_hit.glsl"
#include "common/counters.glsl"
// Exact ray-sphere intersection per fragment; depth replaced by the hit.
// MODE_DEPTH: eye depth + view normal (depth-tested). MODE_THICKNESS: the chord
// length of the view ray through the sphere times u_thickness_weight (1 unless a
// method sets it), added up by the blender.
uniform mat4 u_proj;
uniform float u_radius;
uniform vec2 u_viewport;
in flat vec3 v_center;
#ifdef MODE_THICKNESS
uniform float u_thickness_weight = 1.0;
layout(location = 0) out float o_thickness;
#else
layout(location = 0) out float o_depth;
layout(location = 1) out vec4 o_normal;
#endif

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    vec3 dir = fs_view_ray(gl_FragCoord.xy, u_viewport, u_proj);
    float b, s;
    if (!sphere_ray(dir, v_center, u_radius, b, s)) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
#ifdef MODE_THICKNESS
    o_thickness = 2.0 * s * u_thickness_weight;
#else
    vec3 hit = dir * (b - s);
    gl_FragDepth = window_depth(hit, u_proj);
    o_depth = -hit.z;
    o_normal = vec4((hit - v_center) / u_radius, 1.0);
#endif
}
