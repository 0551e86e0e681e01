#version 450 core
// Yu & Turk 2013 anisotropy per particle (common/anisotropy.c in float): one
// invocation per sorted slot of the grid, weights W(d, R) of the scene's
// kernel (xu2022 eq. 5), weighted mean and covariance (eq. 6), Jacobi
// eigen-decomposition, clamp to sigma_1 / kappa, isotropic at or below n_eps
// neighbours, stretch = scale * sigma / sigma_ref, centre moved by lambda.
// Output per slot (first .. first + count): 3 vec4 = centre, (A00 A01 A02 A11), (A12 A22 n 0).
#include "common/kernels.glsl"
#include "common/grid.glsl"
#include "common/eigen3.glsl"
#include "common/counters.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 1) writeonly buffer FsAniso { vec4 fs_aniso_out[]; };
uniform uint u_first, u_count;
uniform int u_kernel;
uniform float u_R, u_kappa, u_scale, u_lambda, u_sigma_ref;
uniform int u_n_eps;
uniform int u_per_particle; // 1: normalise by cbrt(det) (volume kept), 0: by u_sigma_ref

void main()
{
    uint i = gl_GlobalInvocationID.x, n_nbrs = 0u; // particles looked at (counters.glsl)
    if (i >= u_count) return;
    vec3 x = fs_grid_pos(u_first + i).xyz;
    float sw = 0.0, R2 = u_R * u_R;
    vec3 se = vec3(0.0), sd = vec3(0.0), so = vec3(0.0); // sums of w e, w e_k^2, w (e0e1, e0e2, e1e2)
    int n = 0;
    fs_grid_runs it;
    uvec2 run;
    if (fs_grid_runs_start(x, u_R, it))
        while (fs_grid_next_run(it, run)) {
            n_nbrs += run.y - run.x;
            for (uint s = run.x; s < run.y; s++) {
                vec3 e = fs_grid_pos(s).xyz - x;
                float d2 = dot(e, e);
                if (d2 >= R2) continue;
                float w = fs_kernel_w(u_kernel, sqrt(d2), u_R);
                if (d2 > 0.0) n++;
                sw += w;
                se += w * e;
                sd += w * e * e;
                so += w * vec3(e.x * e.y, e.x * e.z, e.y * e.z);
            }
        }
    vec3 c = x;
    mat3 A = mat3(1.0);
    if (sw > 0.0) {
        vec3 m = se / sw;
        c = x + u_lambda * m;
        if (n > u_n_eps) {
            vec3 d = sd / sw - m * m;
            vec3 o = so / sw - vec3(m.x * m.y, m.x * m.z, m.y * m.z);
            mat3 C = mat3(d.x, o.x, o.y, o.x, d.y, o.z, o.y, o.z, d.z);
            vec3 ev;
            mat3 V;
            fs_eigen3_sym(C, ev, V); // ascending: ev.z is sigma_1
            vec3 sk = max(ev, vec3(ev.z / u_kappa));
            sk *= u_scale / (u_per_particle != 0 ? pow(sk.x * sk.y * sk.z, 1.0 / 3.0) : u_sigma_ref);
            A = V * mat3(sk.x, 0.0, 0.0, 0.0, sk.y, 0.0, 0.0, 0.0, sk.z) * transpose(V);
        }
    }
    uint b = 3u * i;
    fs_aniso_out[b] = vec4(c, 0.0);
    fs_aniso_out[b + 1u] = vec4(A[0][0], A[1][0], A[2][0], A[1][1]);
    fs_aniso_out[b + 2u] = vec4(A[2][1], A[2][2], float(n), 0.0);
    FS_COUNT(FS_CNT_NEIGHBOURS, n_nbrs);
}
