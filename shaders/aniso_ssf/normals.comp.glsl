#version 450 core
#include "common/view_ray.glsl"
#include "common/counters.glsl"
// Normals from the filtered eye depth by finite differences: view-space
// positions of the pixel and its four neighbours; along each axis the one-sided
// difference with the smaller depth change is used (so a depth discontinuity
// does not tilt the normal), the missing side when a neighbour is empty.
layout(local_size_x = 8, local_size_y = 8) in;
uint fs_taps = 0u; // in-image depth texels read by the stencil (counters.glsl)
layout(r32f, binding = 0) uniform readonly image2D u_src;
layout(r32f, binding = 1) uniform writeonly image2D u_depth;
layout(rgba32f, binding = 2) uniform writeonly image2D u_normal;
uniform mat4 u_proj;
uniform int u_write_depth;

vec3 view_pos(ivec2 q, float z, ivec2 size)
{
    return fs_view_dir_unnormalized(vec2(q) + 0.5, vec2(size), u_proj) * z;
}
float depth_at(ivec2 q, ivec2 size)
{
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) return 0.0;
    fs_taps++;
    return imageLoad(u_src, q).x;
}
// Difference along axis e: the smaller one-sided change; zero vector when both sides are empty.
vec3 diff(ivec2 px, ivec2 e, float z, vec3 p, ivec2 size)
{
    float zp = depth_at(px + e, size), zm = depth_at(px - e, size);
    bool hp = zp > 0.0, hm = zm > 0.0;
    if (hp && (!hm || abs(zp - z) <= abs(z - zm))) return view_pos(px + e, zp, size) - p;
    if (hm) return p - view_pos(px - e, zm, size);
    return vec3(0.0);
}

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_src);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_src, px).x;
    if (u_write_depth != 0) imageStore(u_depth, px, vec4(z));
    if (z <= 0.0) { imageStore(u_normal, px, vec4(0.0)); FS_COUNT(FS_CNT_TEXELS, 1); return; }
    vec3 p = view_pos(px, z, size);
    vec3 n = cross(diff(px, ivec2(1, 0), z, p, size), diff(px, ivec2(0, 1), z, p, size));
    float l = length(n);
    n = l > 0.0 ? n / l : vec3(0.0, 0.0, 1.0); // an isolated pixel faces the camera
    if (dot(n, p) > 0.0) n = -n;
    imageStore(u_normal, px, vec4(n, 1.0));
    FS_COUNT(FS_CNT_FILTER_TAPS, fs_taps + 1u); // and the centre
    FS_COUNT(FS_CNT_TEXELS, 1);
}
