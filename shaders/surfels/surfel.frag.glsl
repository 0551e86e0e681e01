#version 450 core
#include "common/counters.glsl"
// The surfel disk per fragment: the pixel's view ray meets the disk's plane;
// fragments outside radius R are discarded (a perspective-correct splat).
// MODE_VISIBILITY (pass 1): depth only, pushed back by u_epsilon (eye depth).
// MODE_BLEND (pass 2): depth-tested against pass 1 without writes; adds the
// Gaussian weight g(d/R) times normal, depth and the surfel's own appearance.
#include "common/view_ray.glsl"
#ifdef MODE_BLEND
#include "surfels/appearance.glsl"
#endif
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_epsilon;
uniform float u_gauss; // g(t) = exp(-u_gauss t^2), t = d / R
in flat vec3 v_center;
in flat vec3 v_normal;
in flat float v_radius;
in flat vec3 v_world_normal;
#ifdef MODE_BLEND
layout(location = 0) out vec4 o_normal_w;    // (w n, w)
layout(location = 1) out vec4 o_depth_w;     // (w depth, w caustic, 0, w)
layout(location = 2) out vec4 o_color_w;     // (w rgb, w)
uniform mat4 u_view_inv;
#endif

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    vec3 dir = fs_view_ray(gl_FragCoord.xy, u_viewport, u_proj);
    float den = dot(dir, v_normal);
    if (den >= -1e-6) discard; // grazing or behind
    vec3 hit = dir * (dot(v_center, v_normal) / den);
    float d = length(hit - v_center);
    if (d > v_radius) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
#ifdef MODE_VISIBILITY
    vec3 off = hit * ((-hit.z + u_epsilon) / -hit.z);
    vec4 clip = u_proj * vec4(off, 1.0);
    gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
#else
    vec4 clip = u_proj * vec4(hit, 1.0);
    gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
    float t = d / v_radius;
    float w = exp(-u_gauss * t * t);
    vec3 wp = (u_view_inv * vec4(hit, 1.0)).xyz;
    vec3 wd = normalize(mat3(u_view_inv) * dir);
    float caustic;
    vec3 rgb = surfel_appearance(wp, wd, normalize(v_world_normal), caustic);
    o_normal_w = vec4(w * v_normal, w);
    o_depth_w = vec4(w * -hit.z, w * caustic, 0.0, w);
    o_color_w = vec4(w * rgb, w);
#endif
}
