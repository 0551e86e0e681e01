#version 450 core
#include "common/view_ray.glsl"
// xiao2017 3.2: per pixel, march the view ray from the splatted entry depth
// through phi (the scene's kernel, support H, iso) until the iso value. An entry
// already inside steps back; a layer passed without a crossing is marched on
// (cells with no particle within H are skipped whole) up to the grid's far
// side or u_max_steps samples. The crossing is refined by bisection.
#include "common/kernels.glsl"
#include "common/grid.glsl"
#include "common/counters.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform readonly image2D u_entry;   // eye depth of the nearest sphere
layout(rgba32f, binding = 1) uniform readonly image2D u_splat; // w: a sphere covers the pixel
layout(rgba32f, binding = 2) uniform writeonly image2D u_hit;  // world hit point, w = 1 on a hit
uniform mat4 u_proj;
uniform mat3 u_view_rot; // world -> view
uniform vec3 u_eye;
uniform int u_kernel;
uniform float u_H, u_V, u_iso;
uniform float u_step, u_step_back;
uniform int u_max_steps, u_refine;

uint n_evals = 0u, n_nbrs = 0u; // this invocation's work (counters.glsl)

// The work counts, and one texel written, once per invocation that stores.
void count_done()
{
    FS_COUNT(FS_CNT_FIELD_EVALS, n_evals);
    FS_COUNT(FS_CNT_MARCH_SAMPLES, n_evals); // every evaluation here is a sample along the ray
    FS_COUNT(FS_CNT_NEIGHBOURS, n_nbrs);
    FS_COUNT(FS_CNT_TEXELS, 1);
}

float phi(vec3 x)
{
    n_evals++;
    fs_grid_runs it;
    uvec2 run;
    if (!fs_grid_runs_start(x, u_H, it)) return 0.0;
    float s = 0.0, H2 = u_H * u_H;
    while (fs_grid_next_run(it, run)) {
        n_nbrs += run.y - run.x;
        for (uint i = run.x; i < run.y; i++) {
            vec3 e = fs_grid_pos(i).xyz - x;
            float d2 = dot(e, e);
            if (d2 < H2) s += fs_kernel_w(u_kernel, sqrt(d2), u_H);
        }
    }
    return s * u_V;
}

// Ray distance where the ray leaves cell c.
float cell_exit(ivec3 c, vec3 d)
{
    vec3 lo = u_grid_origin + vec3(c) * u_grid_cell, hi = lo + vec3(u_grid_cell);
    vec3 bound = mix(lo, hi, greaterThan(d, vec3(0.0)));
    vec3 t = (bound - u_eye) / d; // +-inf on an axis the ray is parallel to
    t = mix(t, vec3(1e30), equal(d, vec3(0.0)));
    return min(t.x, min(t.y, t.z));
}

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_splat);
    if (any(greaterThanEqual(px, size))) return;
    if (imageLoad(u_splat, px).w < 0.5) { imageStore(u_hit, px, vec4(0.0)); count_done(); return; } // no entry: no ray
    vec3 dv = fs_view_ray(vec2(px) + 0.5, vec2(size), u_proj);
    vec3 d = transpose(u_view_rot) * dv;
    float t0 = imageLoad(u_entry, px).x / -dv.z;
    // Far limit: where the ray leaves the range of the stored cells (phi is zero beyond).
    vec3 b0 = (u_grid_origin + vec3(u_grid_lo) * u_grid_cell - u_eye) / d;
    vec3 b1 = (u_grid_origin + vec3(u_grid_hi + 1) * u_grid_cell - u_eye) / d;
    vec3 tfar3 = mix(max(b0, b1), vec3(1e30), equal(d, vec3(0.0)));
    float t_far = min(tfar3.x, min(tfar3.y, tfar3.z));

    float lo = t0, hi = t0;
    bool found = false;
    if (phi(u_eye + t0 * d) >= u_iso) {
        // The entry is already inside (the ray slipped between spheres): step back.
        float inside = t0;
        int nback = int(ceil(u_step_back / u_step));
        for (int i = 1; i <= nback; i++) {
            float tb = max(t0 - float(i) * u_step, 0.0);
            if (phi(u_eye + tb * d) < u_iso) { lo = tb; hi = inside; break; }
            inside = tb;
            if (tb == 0.0) break;
        }
        if (lo == t0) { lo = hi = inside; } // inside all the way back: take the farthest point back
        found = true;
    } else {
        float tp = t0; // last point known outside
        int samples = 0;
        for (int it = 0; it < 4 * u_max_steps && samples < u_max_steps; it++) {
            float tn = tp + u_step;
            if (tn > t_far) break;
            vec3 x = u_eye + tn * d;
            ivec3 c = fs_grid_cell_of(x);
            if (!fs_grid_near_occupied(c)) { tp = max(cell_exit(c, d), tn); continue; } // phi = 0 in the whole cell
            samples++;
            if (phi(x) >= u_iso) { lo = tp; hi = tn; found = true; break; }
            tp = tn;
        }
    }
    if (!found) { imageStore(u_hit, px, vec4(0.0)); count_done(); return; }
    for (int i = 0; i < u_refine && hi > lo; i++) {
        float mid = 0.5 * (lo + hi);
        if (phi(u_eye + mid * d) >= u_iso) hi = mid; else lo = mid;
    }
    imageStore(u_hit, px, vec4(u_eye + 0.5 * (lo + hi) * d, 1.0));
    count_done();
}
