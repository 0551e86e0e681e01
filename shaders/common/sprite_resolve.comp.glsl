#version 450 core
#ifdef SPLAT_INT64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
// The compute splatter's per-pixel resolve (common/gl/gl_splat.h) into the
// G-buffer's textures, one invocation per pixel:
//   RESOLVE_DEPTH      the winning sprite's hit (sprite_splat.comp.glsl) as the
//                      raster's fragment writes it: eye depth and view normal,
//                      for the sprites of the bound buffer [u_first, u_first + u_count)
//   RESOLVE_THICKNESS  the fixed-point sum in scene units
layout(local_size_x = 8, local_size_y = 8) in;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_radius;
uniform float u_quantum; // thickness: scene units per fixed-point unit
uniform uint u_first;
uniform uint u_count;
#include "common/view_ray.glsl"
#include "common/sphere_hit.glsl"
#include "common/counters.glsl"
#include "common/splat_buffers.glsl"
#ifdef RESOLVE_DEPTH
#include "common/sprite_shape.glsl"
layout(r32f, binding = 0) uniform writeonly image2D u_depth;
layout(rgba32f, binding = 1) uniform writeonly image2D u_normal;

// The sprite (of all) whose hit is nearest at pixel p, or SPLAT_NONE.
uint winner(uint p)
{
#ifdef SPLAT_INT64
    uint64_t k = splat_key[p];
    return uint(k >> 32) < SPLAT_DEPTH_ONE ? uint(k & 0xffffffffUL) : SPLAT_NONE;
#else
    return splat_win[p];
#endif
}

// Returns 1 when it wrote the pixel.
uint resolve(ivec2 px, uint p)
{
    uint gi = winner(p);
    if (gi == SPLAT_NONE || gi < u_first || gi - u_first >= u_count) return 0u; // none, or another buffer's
    Sprite sp = sprite_core(gi - u_first);
    float t, chord;
    vec3 dir = fs_view_ray(vec2(px) + 0.5, u_viewport, u_proj);
    sprite_ray(sp, dir, t, chord); // it hit here in the splat pass
    vec3 hit = dir * t;
    imageStore(u_depth, px, vec4(-hit.z));
    imageStore(u_normal, px, vec4(sprite_normal(sp, hit), 1.0));
    return 1u;
}
#else
layout(r32f, binding = 2) uniform writeonly image2D u_thickness;

uint resolve(ivec2 px, uint p)
{
    uint lo = splat_thick[2u * p], hi = splat_thick[2u * p + 1u];
    if ((lo | hi) == 0u) return 0u; // the target is cleared to 0
    double units = double(hi) * 4294967296.0LF + double(lo);
    imageStore(u_thickness, px, vec4(float(units * double(u_quantum))));
    return 1u;
}
#endif

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= int(u_viewport.x) || px.y >= int(u_viewport.y)) return;
    uint stored = resolve(px, uint(px.y) * uint(u_viewport.x) + uint(px.x));
    FS_COUNT(FS_CNT_TEXELS, stored);
}
