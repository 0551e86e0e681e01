#version 450 core
#include "common/view_ray.glsl"
#include "common/counters.glsl"
// Exact ray-ellipsoid intersection per fragment (the ray taken to the unit
// sphere's parameter space). MODE_DEPTH: eye depth and view normal of the
// front hit, depth replaced. MODE_THICKNESS: the chord length, added by the blender.
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
    // Ray t = tc + s around the point nearest the centre, so the quadratic has small coefficients.
    float tc = dot(dir, v_center);
    vec3 q = v_inv * dir, p = v_inv * (dir * tc - v_center);
    float qq = dot(q, q), qp = dot(q, p);
    float h = qp * qp - qq * (dot(p, p) - 1.0);
    if (h < 0.0) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
    float s = sqrt(h);
#ifdef MODE_THICKNESS
    o_thickness = 2.0 * s / qq;
#else
    float t = tc + (-qp - s) / qq;
    vec3 hit = dir * t;
    vec3 u = v_inv * (hit - v_center);
    vec4 clip = u_proj * vec4(hit, 1.0);
    gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
    o_depth = -hit.z;
    o_normal = vec4(normalize(transpose(v_inv) * u), 1.0);
#endif
}
