#version 450 core
// xiao2017 3.3 at each hit: the basic normal (eq. 2: -sum grad W_spiky(R)), the
// PCA normal (eqs. 3-4, weight 1 - (d/R)^3, Jacobi, smallest eigenvalue, sign
// of the basic normal) and their blend (eqs. 5-6); the fallbacks follow
// methods/raycast_pca/pca_normal.c. Also writes eye depth and, with particle
// colours, their kernel-weighted average (support H) at the hit.
#include "common/kernels.glsl"
#include "common/grid.glsl"
#include "common/eigen3.glsl"
#include "common/counters.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_hit;
layout(r32f, binding = 1) uniform writeonly image2D u_depth;
layout(rgba32f, binding = 2) uniform writeonly image2D u_raw;   // view normal, w = hit
layout(rgba32f, binding = 3) uniform writeonly image2D u_color;
uniform mat4 u_proj;
uniform mat3 u_view_rot;
uniform vec3 u_eye;
uniform int u_kernel;
uniform float u_H;
uniform float u_R;
uniform int u_mode;          // 0 basic, 1 pca, 2 blend
uniform int u_min_neighbors;
uniform int u_fixed_weight;
uniform float u_w, u_blend_d, u_blend_k;
uniform int u_use_color;

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_hit);
    if (any(greaterThanEqual(px, size))) return;
    vec4 h = imageLoad(u_hit, px);
    if (h.w < 0.5) {
        imageStore(u_raw, px, vec4(0.0));
        imageStore(u_color, px, vec4(0.0));
        FS_COUNT(FS_CNT_TEXELS, 1);
        return;
    }
    uint n_nbrs = 0u; // particles looked at (counters.glsl)
    vec3 x = h.xyz;
    float rad = max(u_R, u_use_color != 0 ? u_H : 0.0), R2 = u_R * u_R, H2 = u_H * u_H;
    vec3 grad = vec3(0.0), m = vec3(0.0), col = vec3(0.0);
    mat3 s2 = mat3(0.0);
    float ws = 0.0, wc = 0.0;
    int cnt = 0;
    fs_grid_runs it;
    uvec2 run;
    if (fs_grid_runs_start(x, rad, it))
        while (fs_grid_next_run(it, run)) {
            n_nbrs += run.y - run.x;
            for (uint i = run.x; i < run.y; i++) {
                vec3 u = fs_grid_pos(i).xyz - x; // relative to x: keeps float precision
                float d2 = dot(u, u);
                if (u_use_color != 0 && d2 < H2) {
                    float wk = fs_kernel_w(u_kernel, sqrt(d2), u_H);
                    col += wk * fs_grid_attr(i).rgb;
                    wc += wk;
                }
                if (d2 >= R2) continue;
                float d = sqrt(d2);
                if (d > 0.0) grad += fs_spiky_dw(d, u_R) / d * u; // -grad_x W: outwards
                float q = d / u_R, w = 1.0 - q * q * q;
                ws += w;
                m += w * u;
                s2 += w * outerProduct(u, u);
                cnt++;
            }
        }
    vec3 viewfwd = -transpose(u_view_rot)[2];
    vec3 dir = normalize(x - u_eye);
    vec3 nb = length(grad) > 0.0 ? normalize(grad) : -dir;
    vec3 n = nb;
    if (u_mode != 0 && cnt >= max(u_min_neighbors, 3) && ws > 0.0) {
        m /= ws;
        mat3 c = s2 / ws - outerProduct(m, m);
        vec3 ev;
        mat3 evec;
        fs_eigen3_sym(c, ev, evec);
        if (ev.z > 0.0 && ev.y > 1e-4 * ev.z) { // rank >= 2: the plane is defined
            vec3 np = normalize(evec[0]);
            if (dot(np, nb) < 0.0) np = -np;
            if (u_mode == 1) n = np;
            else {
                float w = u_fixed_weight != 0 ? u_w : min(1.0, exp(u_blend_d * (dot(nb, np) - u_blend_k)));
                vec3 b = (1.0 - w) * nb + w * np;
                n = length(b) > 0.0 ? normalize(b) : nb;
            }
        }
    }
    vec3 nv = u_view_rot * n;
    vec3 dv = u_view_rot * dir;
    if (dot(nv, dv) > 0.0) nv = -nv; // face the camera
    imageStore(u_depth, px, vec4(dot(x - u_eye, viewfwd)));
    imageStore(u_raw, px, vec4(nv, 1.0));
    imageStore(u_color, px, u_use_color != 0 && wc > 0.0 ? vec4(col / wc, 1.0) : vec4(0.0));
    FS_COUNT(FS_CNT_FIELD_EVALS, 1); // the gradient and the PCA at the hit: one sum over its neighbours
    FS_COUNT(FS_CNT_NEIGHBOURS, n_nbrs);
    FS_COUNT(FS_CNT_TEXELS, 1);
}
