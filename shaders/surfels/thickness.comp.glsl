#version 450 core
#include "common/counters.glsl"
#include "common/view_ray.glsl"
// Thickness for the shared shading (not in the paper, whose own appearance
// needs none): the fluid path length along the view ray, marched through the
// density grid (3D texture, trilinear) from the visible surface to where the
// ray leaves the grid, counting the steps with phi >= iso.
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform readonly image2D u_depth;
layout(r32f, binding = 1) uniform writeonly image2D u_thickness;
uniform sampler3D u_grid;
uniform mat4 u_proj;
uniform mat4 u_view_inv;
uniform vec3 u_grid_origin;  // world position of texel centre (0,0,0)
uniform vec3 u_grid_extent;  // (dim - 1) * spacing
uniform vec3 u_grid_dim;
uniform float u_step;
uniform float u_iso;

uint n_samples = 0u; // this invocation's lookups of the density grid (counters.glsl)

float phi(vec3 w)
{
    n_samples++;
    vec3 t = (w - u_grid_origin) / u_grid_extent;          // 0..1 between the first and last point
    vec3 uvw = (t * (u_grid_dim - 1.0) + 0.5) / u_grid_dim; // texel centres
    return textureLod(u_grid, uvw, 0.0).r;
}

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_depth);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_depth, px).x;
    if (z <= 0.0) { imageStore(u_thickness, px, vec4(0.0)); FS_COUNT(FS_CNT_TEXELS, 1); return; }
    vec3 dv = fs_view_dir_unnormalized(vec2(px) + 0.5, vec2(size), u_proj);
    vec3 o = (u_view_inv * vec4(dv * z, 1.0)).xyz;
    vec3 d = normalize(mat3(u_view_inv) * dv);
    // distance to the far side of the grid's box
    vec3 lo = (u_grid_origin - o) / d, hi = (u_grid_origin + u_grid_extent - o) / d;
    vec3 tfar = max(lo, hi);
    float tmax = min(min(tfar.x, tfar.y), tfar.z);
    float inside = 0.0;
    for (float t = 0.5 * u_step; t < tmax; t += u_step)
        if (phi(o + t * d) >= u_iso) inside += u_step;
    imageStore(u_thickness, px, vec4(inside));
    FS_COUNT(FS_CNT_MARCH_SAMPLES, n_samples);
    FS_COUNT(FS_CNT_TEXELS, 1);
}
