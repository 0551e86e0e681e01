#version 450 core
#include "common/counters.glsl"
#include "common/view_ray.glsl"
#include "surfels/appearance.glsl"
// Pass 3 (iwasaki2006 section 5.3): per-pixel normalisation of the blended
// surfels, dividing the weighted sums by the accumulated Gaussian weight; the
// G-buffer (eye depth, view normal + coverage) and the own appearance, with the
// background (sky, or the floor lit by sun or caustics) where no surfel landed.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_acc_normal;
layout(rgba32f, binding = 1) uniform readonly image2D u_acc_depth;
layout(rgba32f, binding = 2) uniform readonly image2D u_acc_color;
layout(r32f, binding = 3) uniform writeonly image2D u_depth;
layout(rgba32f, binding = 4) uniform writeonly image2D u_normal;
layout(rgba32f, binding = 5) uniform writeonly image2D u_own;
uniform mat4 u_proj;
uniform mat4 u_view_inv;

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_depth);
    if (any(greaterThanEqual(px, size))) return;
    vec4 an = imageLoad(u_acc_normal, px);
    float w = an.w;
    if (w > 0.0) {
        vec4 ad = imageLoad(u_acc_depth, px), ac = imageLoad(u_acc_color, px);
        vec3 n = an.xyz / w;
        float len = length(n);
        imageStore(u_depth, px, vec4(ad.x / w));
        imageStore(u_normal, px, vec4(len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0), 1.0));
        imageStore(u_own, px, vec4(ac.rgb / w, ad.y / w));
        FS_COUNT(FS_CNT_TEXELS, 1);
        return;
    }
    vec3 dir = fs_view_ray(vec2(px) + 0.5, vec2(size), u_proj);
    vec3 wd = normalize(mat3(u_view_inv) * dir);
    float caustic, path;
    vec3 bg = scene_behind(u_eye_world, wd, 0.0, caustic, path);
    imageStore(u_depth, px, vec4(0.0));
    imageStore(u_normal, px, vec4(0.0));
    imageStore(u_own, px, vec4(bg, caustic));
    FS_COUNT(FS_CNT_TEXELS, 1);
}
