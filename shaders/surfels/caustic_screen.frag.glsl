#version 450 core
#include "common/counters.glsl"
// Caustics, virtual screen: the pixel's light ray P - t light meets the surfel's
// disk plane at depth t; the fragment exists where that point lies within R of
// the centre. MODE_DEPTH (pass 1) writes only depth, pushed back by u_eps surfel
// radii; the blend pass (depth test LEQUAL against pass 1, no depth writes) adds
// g(r/R) (n, 1) and g(r/R) t, so only surfels within epsilon of the first
// surface the light meets are blended (Botsch & Kobbelt's visibility splatting).
// g(x) = (exp(-2 x^2) - exp(-2)) / (1 - exp(-2)) for x < 1, else 0: a Gaussian
// of standard deviation R/2, shifted to reach 0 continuously at the disk edge.
uniform vec3 u_light;
uniform vec3 u_ea, u_eb, u_eu;
uniform vec2 u_rect_min, u_pix;  // world size of a screen pixel along a and b
uniform float u_top;
uniform float u_tfar;            // depth t mapped to [0, 1] as t / u_tfar
uniform float u_eps;             // depth offset in surfel radii (pass 1)
in flat vec3 v_center;
in flat vec3 v_normal;
in flat float v_radius;
#ifndef MODE_DEPTH
layout(location = 0) out vec4 o_acc;   // sum g n, sum g
layout(location = 1) out float o_dacc; // sum g t
#endif

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    vec2 ab = u_rect_min + gl_FragCoord.xy * u_pix;
    vec3 P = ab.x * u_ea + ab.y * u_eb + u_top * u_eu;
    float t = dot(P - v_center, v_normal) / dot(u_light, v_normal);
    vec3 X = P - t * u_light;
    float x = length(X - v_center) / v_radius;
    if (x >= 1.0 || t < 0.0) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
#ifdef MODE_DEPTH
    gl_FragDepth = clamp((t + u_eps * v_radius) / u_tfar, 0.0, 1.0);
#else
    gl_FragDepth = clamp(t / u_tfar, 0.0, 1.0);
    const float e2 = exp(-2.0);
    float g = (exp(-2.0 * x * x) - e2) / (1.0 - e2);
    o_acc = vec4(g * v_normal, g);
    o_dacc = g * t;
#endif
}
