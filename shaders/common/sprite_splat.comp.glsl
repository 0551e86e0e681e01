#version 450 core
#ifdef SPLAT_INT64
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
// The compute splatter (common/gl/gl_splat.h): the raster's sprites
// (common/sprite_shape.glsl) splatted by atomics on storage buffers. One pass:
//   PASS_DEPTH      atomicMin of the hit's window depth bits (non-negative
//                   floats order as their bits), or with SPLAT_INT64 of the
//                   64-bit (depth, index) key
//   PASS_INDEX      where a sprite's depth equals the minimum, atomicMin of its
//                   index: the first drawn wins a tie, as under GL_LESS
//   PASS_THICKNESS  fixed-point atomicAdd of chord * u_weight
// u_phase 0: one invocation per sprite walks its footprint, or lists the
// sprite when the footprint exceeds u_large_px pixels; 2: one invocation
// turns the list into the dispatch of phase 1; 1: a workgroup per listed
// sprite, its invocations covering the footprint in 8x8 blocks.
layout(local_size_x = 64) in;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_radius;
uniform float u_weight = 1.0;  // thickness: the factor on each chord
uniform float u_inv_quantum;   // thickness: fixed-point units per scene unit
uniform float u_subpixel;      // 2^GL_SUBPIXEL_BITS: the raster snaps vertices to 1/u_subpixel pixel
uniform uint u_first;          // the index of the bound buffer's first sprite among all
uniform uint u_base;           // this dispatch's first sprite in the buffer
uniform uint u_count;          // and how many
uniform uint u_large_px;
uniform uint u_split_groups; // the most workgroups of phase 1 (at most 65535)
uniform int u_phase;
#include "common/view_ray.glsl"
#include "common/sphere_hit.glsl"
#include "common/counters.glsl"
#include "common/sprite_shape.glsl"
#include "common/splat_buffers.glsl"

uint n_pixels = 0u, n_atomics = 0u; // this invocation's work counts

// The pixels [x0, x1) x [y0, y1) whose centres the raster finds inside the
// quad: GL's viewport transform, the vertices snapped to the sub-pixel grid,
// edges half-open; clipped to the image.
ivec4 footprint(vec4 rect)
{
    vec4 half_size = 0.5 * u_viewport.xxyy;
    vec4 w = rect * half_size + half_size;
    ivec4 f = ivec4(ceil(round(w * u_subpixel) / u_subpixel - 0.5));
    return clamp(f, ivec4(0), ivec2(u_viewport).xxyy);
}

// Sprite i's shape and footprint; false when the raster would draw nothing
// (culled, its quad outside the near or far plane, or no pixel centre inside).
bool sprite_at(uint i, out Sprite sp, out ivec4 f)
{
    vec4 rect;
    float z;
    f = ivec4(0);
    if (!sprite_load(i, sp, rect, z) || !(z >= -1.0 && z <= 1.0)) return false;
    f = footprint(rect);
    return f.x < f.y && f.z < f.w;
}

// Adds v >= 0 in fixed point to pixel p: a 64-bit sum as (lo, hi) words, the
// carry of lo into hi, exact and independent of the order of the adds.
void thickness_add(uint p, float v)
{
    float units = round(v * u_inv_quantum);
    if (!(units > 0.0)) return;
    if (units >= 1.8e19) { // one add past 2^64 units: cannot be summed
        atomicOr(list_overflow, 1u);
        return;
    }
    float hi_f = floor(units * (1.0 / 4294967296.0));
    uint hi = uint(hi_f), lo = uint(units - hi_f * 4294967296.0); // both exact
    uint old = atomicAdd(splat_thick[2u * p], lo);
    n_atomics++;
    hi += old + lo < old ? 1u : 0u;
    if (hi == 0u) return;
    uint old_hi = atomicAdd(splat_thick[2u * p + 1u], hi);
    n_atomics++;
    if (old_hi + hi < old_hi) atomicOr(list_overflow, 1u);
}

// Sprite gi (of all) at pixel px: the per-fragment work of the raster.
void splat_pixel(ivec2 px, Sprite sp, uint gi)
{
    n_pixels++;
    vec3 dir = fs_view_ray(vec2(px) + 0.5, u_viewport, u_proj);
    float t, chord;
    if (!sprite_ray(sp, dir, t, chord)) return;
    uint p = uint(px.y) * uint(u_viewport.x) + uint(px.x);
#ifdef PASS_THICKNESS
    thickness_add(p, chord * u_weight);
#else
    float z = window_depth(dir * t, u_proj);
    uint key = z > 0.0 ? floatBitsToUint(min(z, 1.0)) : 0u; // GL clamps gl_FragDepth to [0, 1]
    if (key >= SPLAT_DEPTH_ONE) return;                      // GL_LESS against the cleared 1.0
#if defined(PASS_INDEX)
    if (key == splat_key[p]) {
        atomicMin(splat_win[p], gi);
        n_atomics++;
    }
#elif defined(SPLAT_INT64)
    uint64_t k = uint64_t(key) << 32 | uint64_t(gi);
    if (k < splat_key[p]) {
        atomicMin(splat_key[p], k);
        n_atomics++;
    }
#else
    if (key < splat_key[p]) {
        atomicMin(splat_key[p], key);
        n_atomics++;
    }
#endif
#endif
}

// Phase 0: this invocation's sprite, walked or listed.
void phase_walk()
{
    uint k = gl_GlobalInvocationID.x, i = u_base + k;
    Sprite sp;
    ivec4 f;
    if (k >= u_count || !sprite_at(i, sp, f)) return;
    if (uint(f.y - f.x) * uint(f.w - f.z) > u_large_px) {
        list_entry[atomicAdd(list_count, 1u)] = uvec3(i, uint(f.x) | uint(f.y) << 16, uint(f.z) | uint(f.w) << 16);
        n_atomics++;
        return;
    }
    for (int y = f.z; y < f.w; y++)
        for (int x = f.x; x < f.y; x++) splat_pixel(ivec2(x, y), sp, u_first + i);
}

// Phase 1: the listed sprites, a workgroup each, the workgroups striding over
// the list (fewer workgroups than sprites where the list is long: llvmpipe
// pays for each). The workgroup covers the footprint in 8x8 pixel blocks, an
// invocation per pixel of a block (no integer division per pixel). The list
// holds each footprint, so an invocation loads only the sprite's shape (no barrier).
void phase_split()
{
    uint groups = gl_NumWorkGroups.x, n = list_listed;
    ivec2 lid = ivec2(gl_LocalInvocationIndex & 7u, gl_LocalInvocationIndex >> 3);
    for (uint g = gl_WorkGroupID.x; g < n; g += groups) {
        uvec3 e = list_entry[g];
        Sprite sp = sprite_core(e.x);
        ivec4 f = ivec4(e.y & 0xffffu, e.y >> 16, e.z & 0xffffu, e.z >> 16);
        for (int by = f.z; by < f.w; by += 8)
            for (int bx = f.x; bx < f.y; bx += 8) {
                ivec2 px = ivec2(bx, by) + lid;
                if (px.x < f.y && px.y < f.w) splat_pixel(px, sp, u_first + e.x);
            }
    }
}

// Phase 2: the list's dispatch (at most u_split_groups workgroups), and the
// list emptied for the next piece.
void phase_args()
{
    if (gl_GlobalInvocationID.x != 0u) return;
    uint n = list_count;
    list_listed = n;
    list_count = 0u;
    splat_args[0] = min(n, u_split_groups);
    splat_args[1] = 1u;
    splat_args[2] = 1u;
}

void main()
{
    if (u_phase == 0) phase_walk();
    else if (u_phase == 1) phase_split();
    else phase_args();
    FS_COUNT(FS_CNT_SPLAT_PIXELS, n_pixels);
    FS_COUNT(FS_CNT_SPLAT_ATOMICS, n_atomics);
}
