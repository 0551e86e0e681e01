#version 450 core
#include "common/counters.glsl"
#include "common/view_ray.glsl"
// inacio2010 IV-B: per pixel, march the view ray from the box's front face to
// its back face through the density volume (3D texture, trilinear), step u_step.
//  G-buffer: the first sample with phi >= iso brackets the iso crossing, refined
//    by u_refine bisections; the normal is minus the gradient by central
//    differences of the texture (one grid spacing); thickness is the length of
//    the samples with phi >= iso along the whole ray (the same march).
//  Own image (transfer function): surface = the opaque iso-surface, shaded;
//    translucent = front-to-back compositing: every iso crossing along the ray
//    (front and back faces, inner surfaces) adds the shaded surface with
//    opacity u_opacity, the inside absorbs u_absorption per grid spacing in the
//    material's tint; early ray termination once the accumulated opacity
//    reaches u_term (Krueger & Westermann). Written premultiplied; the C side
//    puts the background under it.
// The march ends early once nothing more is needed: the hit is found, no
// thickness is wanted and (translucent) the opacity is saturated.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_front;
layout(rgba32f, binding = 1) uniform readonly image2D u_back;
layout(r32f, binding = 2) uniform writeonly image2D u_depth;
layout(rgba32f, binding = 3) uniform writeonly image2D u_normal;
layout(r32f, binding = 4) uniform writeonly image2D u_thickness;
layout(rgba32f, binding = 5) uniform writeonly image2D u_own;
uniform sampler3D u_grid;
uniform mat4 u_proj;
uniform mat3 u_view_rot;   // world -> view
uniform vec3 u_eye;
uniform vec3 u_box_origin; // world position of grid point (0,0,0)
uniform vec3 u_box_extent; // (dim - 1) * spacing
uniform vec3 u_grid_dim;
uniform float u_spacing, u_step, u_iso;
uniform int u_refine, u_thick, u_translucent, u_own_on;
uniform float u_opacity, u_absorption, u_term;
uniform vec3 u_light_dir, u_light_color, u_material;
uniform float u_ambient;

uint n_samples = 0u; // this invocation's lookups of the volume (counters.glsl)

float phi(vec3 w)
{
    n_samples++;
    vec3 t = (w - u_box_origin) / u_box_extent;             // 0..1 between the first and last point
    vec3 uvw = (t * (u_grid_dim - 1.0) + 0.5) / u_grid_dim; // texel centres
    return textureLod(u_grid, uvw, 0.0).r;
}

vec3 gradient(vec3 x)
{
    float h = u_spacing;
    return vec3(phi(x + vec3(h, 0, 0)) - phi(x - vec3(h, 0, 0)), phi(x + vec3(0, h, 0)) - phi(x - vec3(0, h, 0)),
                phi(x + vec3(0, 0, h)) - phi(x - vec3(0, 0, h))) / (2.0 * h);
}

// Unit normal facing the viewer (ray direction d), from the gradient at x.
vec3 normal_at(vec3 x, vec3 d)
{
    vec3 g = gradient(x);
    float l = length(g);
    vec3 n = l > 0.0 ? -g / l : -d;
    return dot(n, d) > 0.0 ? -n : n;
}

vec3 shade(vec3 n, vec3 d)
{
    float diff = max(dot(n, u_light_dir), 0.0);
    float spec = pow(max(dot(n, normalize(u_light_dir - d)), 0.0), 64.0);
    return u_material * (u_ambient + diff * u_light_color) + 0.3 * spec * u_light_color;
}

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_depth);
    if (any(greaterThanEqual(px, size))) return;
    vec4 f = imageLoad(u_front, px), b = imageLoad(u_back, px);
    vec3 dv = fs_view_ray(vec2(px) + 0.5, vec2(size), u_proj);
    vec3 d = transpose(u_view_rot) * dv;
    bool hit = false;
    float t_hit = 0.0, inside = 0.0;
    vec4 acc = vec4(0.0);
    vec3 n = vec3(0.0);
    if (b.a > 0.0) {
        // no front face where the eye is inside the box: start at the eye
        float t0 = f.a > 0.0 ? dot(u_box_origin + f.xyz * u_box_extent - u_eye, d) : 0.0;
        float t1 = dot(u_box_origin + b.xyz * u_box_extent - u_eye, d);
        t0 = max(t0, 0.0);
        int nsteps = int(ceil(max(t1 - t0, 0.0) / u_step));
        float step_sp = u_step / u_spacing; // step in grid spacings (opacity correction)
        float t_prev = t0, p_prev = 0.0;
        bool in_prev = false;
        float a_in = 1.0 - pow(1.0 - u_absorption, step_sp); // interior opacity per step
        for (int i = 0; i <= nsteps; i++) {
            float t = min(t0 + float(i) * u_step, t1);
            vec3 x = u_eye + t * d;
            float p = phi(x);
            if (p >= u_iso) {
                inside += u_step;
                if (!hit) {
                    hit = true;
                    float lo = t_prev, hi = t;
                    if (i == 0) lo = hi; // the ray starts inside
                    for (int r = 0; r < u_refine; r++) {
                        float m = 0.5 * (lo + hi);
                        if (phi(u_eye + m * d) >= u_iso) hi = m; else lo = m;
                    }
                    t_hit = hi;
                    n = normal_at(u_eye + t_hit * d, d);
                }
            }
            if (u_translucent != 0 && acc.a < u_term) {
                bool in_now = p >= u_iso;
                if (in_now != in_prev) { // a surface between the last two samples: composite it
                    float tc = mix(t_prev, t, clamp((u_iso - p_prev) / (p - p_prev), 0.0, 1.0));
                    acc += (1.0 - acc.a) * u_opacity * vec4(shade(normal_at(u_eye + tc * d, d), d), 1.0);
                }
                if (in_now) acc += (1.0 - acc.a) * a_in * vec4(u_material * (0.5 + 0.5 * u_ambient), 1.0);
                in_prev = in_now;
            }
            if (hit && u_thick == 0 && (u_translucent == 0 || acc.a >= u_term)) break;
            t_prev = t;
            p_prev = p;
        }
    }
    if (hit) {
        imageStore(u_depth, px, vec4(t_hit * -dv.z));
        imageStore(u_normal, px, vec4(u_view_rot * n, 1.0));
        if (u_translucent == 0) acc = vec4(shade(n, d), 1.0);
    } else {
        imageStore(u_depth, px, vec4(0.0));
        imageStore(u_normal, px, vec4(0.0));
    }
    imageStore(u_thickness, px, vec4(inside));
    if (u_own_on != 0) imageStore(u_own, px, acc);
    FS_COUNT(FS_CNT_MARCH_SAMPLES, n_samples);
    FS_COUNT(FS_CNT_TEXELS, 1);
}
