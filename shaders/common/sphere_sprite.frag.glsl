#version 450 core
#include "common/view_ray.glsl"
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
    float b = dot(dir, v_center);
    float h = b * b - dot(v_center, v_center) + u_radius * u_radius;
    if (h < 0.0) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
    float s = sqrt(h);
#ifdef MODE_THICKNESS
    o_thickness = 2.0 * s * u_thickness_weight;
#else
    vec3 hit = dir * (b - s);
    vec4 clip = u_proj * vec4(hit, 1.0);
    gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
    o_depth = -hit.z;
    o_normal = vec4((hit - v_center) / u_radius, 1.0);
#endif
}
