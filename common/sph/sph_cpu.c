/* One SPH step on the CPU (C + OpenMP). Same order of work as the shaders in
 * shaders/sph/: counting-sort grid over fluid and boundary particles, density
 * and pressure per sorted slot, then forces and symplectic Euler per fluid slot.
 * Mueller et al. 2003 terms:
 *   rho_i = sum_j m_j W_poly6                      (boundary j: m_j = Psi_j)
 *   a_p   = -sum_j m_j (p_i + p_j) / (2 rho_i rho_j) grad W_spiky
 * Boundary particles j add their mass to rho_i (Akinci et al. 2012) and push
 * with a pressure extrapolated from the fluid around them, hydrostatics
 * included (Adami et al. 2012), at rho_j = rho0. Mirroring p_i instead (Akinci)
 * lets the fluid push a free-surface particle (p_i clamped to 0) into a wall.
 * A lone splash particle reads too little density for any pressure, so the
 * boundary particles also repel closer than the rest spacing r0 = 2r
 * (Lennard-Jones, Monaghan 1994): a = D ((r0/d)^12 - (r0/d)^4) x_ib / d^2,
 * D = c^2 / 40 (= 5 g h_top at c = 10 sqrt(2 g h_top)); zero at rest.
 *   a_v   = mu / rho_i sum_j m_j (v_j - v_i) / rho_j lap W_visc,  mu = nu rho0
 * The box clamp at the end is a safety net only; every use is counted. */
#include "fs_error.h"
#include "kernels.h"
#include "sph_internal.h"
#include "vec3.h"
#include <math.h>
#include <string.h>

/* Below this many particles (boundary included) threads cost more than they
 * save: a step is a few milliseconds and each loop ends in a barrier. */
#define FS_SPH_PARALLEL_MIN 16384

/* Calls BODY for every slot t of the cells around x within one support, cells
 * in (k, j, i) order as the GPU path's dense grid visits them. */
#define FOR_NEIGHBOUR_SLOTS(g, x, H, t, ...)                                                                           \
    do {                                                                                                               \
        int lo_[3], hi_[3];                                                                                            \
        for (int a_ = 0; a_ < 3; a_++) {                                                                               \
            lo_[a_] = fs_grid_coord(g, a_, (x)[a_] - (H));                                                             \
            hi_[a_] = fs_grid_coord(g, a_, (x)[a_] + (H));                                                             \
        }                                                                                                              \
        for (int k_ = lo_[2]; k_ <= hi_[2]; k_++)                                                                      \
            for (int j_ = lo_[1]; j_ <= hi_[1]; j_++)                                                                  \
                for (int i_ = lo_[0], e_; i_ <= hi_[0]; i_ = e_ + 1) {                                                 \
                    uint32_t s0_, s1_;                                                                                 \
                    e_ = fs_grid_row_run(g, i_, hi_[0], j_, k_, &s0_, &s1_);                                           \
                    for (uint32_t t = s0_; t < s1_; t++) { __VA_ARGS__ }                                               \
                }                                                                                                      \
    } while (0)

/* The constants of a step: support H, poly6 and spiky normalisations, dynamic
 * viscosity mu, the wall repulsion's r0^2 and D, gravity. */
typedef struct step_consts {
    float H, H2, rho0, cpoly, cspiky, mu, r02, D, gy;
} step_consts;

static step_consts step_consts_of(const fs_sph *s)
{
    step_consts k;
    const float H = s->H, H2 = H * H, rho0 = s->prm.rho0;
    k.H = H;
    k.H2 = H2;
    k.rho0 = rho0;
    k.cpoly = (float)(315.0 / (64.0 * FS_PI)) / (H2 * H2 * H2 * H2 * H);
    k.cspiky = (float)(45.0 / FS_PI) / (H2 * H2 * H2); /* |grad| = c (H - d)^2, lap = c (H - d) */
    k.mu = s->prm.nu * rho0;
    k.r02 = 4 * s->prm.r * s->prm.r;
    k.D = s->prm.c * s->prm.c / 40;
    k.gy = s->prm.gravity;
    return k;
}

/* The velocities in sorted slot order. */
static void sort_velocities(fs_sph *s, long n)
{
    const fs_grid *g = &s->g;
    float *vel4 = s->vel4;
#pragma omp parallel for schedule(static) if (n > FS_SPH_PARALLEL_MIN)
    for (long t = 0; t < n; t++) {
        uint32_t i = g->index[t];
        vel4[4 * t] = s->vx[i];
        vel4[4 * t + 1] = s->vy[i];
        vel4[4 * t + 2] = s->vz[i];
        vel4[4 * t + 3] = 0;
    }
}

/* rho_i and p_i per fluid slot; boundary slots get rho0 (their pressure comes next). */
static void density_pressure(fs_sph *s, const step_consts *k, long n)
{
    const fs_grid *g = &s->g;
    const uint32_t nb = (uint32_t)s->nb;
    const float H = k->H, H2 = k->H2, cpoly = k->cpoly, *m = s->m;
    float *rho = s->rho, *prs = s->prs;
#pragma omp parallel for schedule(static) if (n > FS_SPH_PARALLEL_MIN)
    for (long sl = 0; sl < n; sl++) {
        if (g->index[sl] < nb) {
            rho[sl] = k->rho0;
            prs[sl] = 0;
            continue;
        }
        const float *xi = g->pos4 + 4 * sl;
        float sum = 0;
        FOR_NEIGHBOUR_SLOTS(g, xi, H, t, {
            const float *xj = g->pos4 + 4 * (size_t)t;
            float dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2], d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < H2) {
                float w = H2 - d2;
                sum += m[g->index[t]] * cpoly * w * w * w;
            }
        });
        rho[sl] = sum;
        prs[sl] = fs_sph_pressure(s, sum);
    }
}

/* Wall pressure p_b = (sum_f p_f W + sum_f rho_f g (y_f - y_b) W) / sum_f W. */
static void wall_pressure(fs_sph *s, const step_consts *k, long n)
{
    const fs_grid *g = &s->g;
    const uint32_t nb = (uint32_t)s->nb;
    const float H = k->H, H2 = k->H2, gy = k->gy, *rho = s->rho;
    float *prs = s->prs;
#pragma omp parallel for schedule(static) if (n > FS_SPH_PARALLEL_MIN)
    for (long sl = 0; sl < n; sl++) {
        if (g->index[sl] >= nb) continue;
        const float *xb = g->pos4 + 4 * sl;
        float sw = 0, sp = 0;
        FOR_NEIGHBOUR_SLOTS(g, xb, H, t, {
            if (g->index[t] < nb) continue;
            const float *xj = g->pos4 + 4 * (size_t)t;
            float dx = xb[0] - xj[0], dy = xb[1] - xj[1], dz = xb[2] - xj[2], d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < H2) {
                float w = H2 - d2;
                w = w * w * w;
                sw += w;
                sp += w * (prs[t] - rho[t] * gy * dy);
            }
        });
        prs[sl] = sw > 0 && sp > 0 ? sp / sw : 0;
    }
}

/* The sums over the neighbours of fluid slot sl: a, the pressure (and wall
 * repulsion) acceleration; b, the viscosity sum before the factor mu / rho_i. */
static void fluid_forces(const fs_sph *s, const step_consts *k, long sl, float a[3], float b[3])
{
    const fs_grid *g = &s->g;
    const uint32_t nb = (uint32_t)s->nb;
    const float H = k->H, H2 = k->H2, cspiky = k->cspiky, r02 = k->r02, D = k->D;
    const float *m = s->m, *rho = s->rho, *prs = s->prs, *vel4 = s->vel4;
    const float *xi = g->pos4 + 4 * sl, *vi = vel4 + 4 * sl;
    float ri = rho[sl], pi = prs[sl];
    float ax = 0, ay = 0, az = 0, bx = 0, by = 0, bz = 0; /* pressure, viscosity sums */
    FOR_NEIGHBOUR_SLOTS(g, xi, H, t, {
        const float *xj = g->pos4 + 4 * (size_t)t;
        float dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2], d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < H2 && d2 > 0) {
            uint32_t j = g->index[t];
            float d = sqrtf(d2), h = H - d;
            float f = m[j] * (pi + prs[t]) / (2 * ri * rho[t]);
            float gr = f * cspiky * h * h / d; /* -grad W points from j to i: push apart */
            if (j < nb) {
                if (d2 < r02) {
                    float q = r02 / d2, q2 = q * q, q6 = q2 * q2 * q2;
                    gr += D * (q6 - q2) / d2;
                }
                ax += gr * dx;
                ay += gr * dy;
                az += gr * dz;
            } else {
                ax += gr * dx;
                ay += gr * dy;
                az += gr * dz;
                const float *vj = vel4 + 4 * (size_t)t;
                float l = m[j] / rho[t] * cspiky * h;
                bx += l * (vj[0] - vi[0]);
                by += l * (vj[1] - vi[1]);
                bz += l * (vj[2] - vi[2]);
            }
        }
    });
    a[0] = ax;
    a[1] = ay;
    a[2] = az;
    b[0] = bx;
    b[1] = by;
    b[2] = bz;
}

/* The safety-net box clamp of x (velocity into the wall zeroed); returns whether it clamped. */
static int clamp_to_box(const fs_sph *s, float x[3], float v[3])
{
    const float *lo = s->box_lo, *hi = s->box_hi;
    int clamped = 0;
    for (int a = 0; a < 3; a++) {
        if (x[a] < lo[a]) {
            x[a] = lo[a];
            if (v[a] < 0) v[a] = 0;
            clamped = 1;
        }
        if (x[a] > hi[a]) {
            x[a] = hi[a];
            if (v[a] > 0) v[a] = 0;
            clamped = 1;
        }
    }
    return clamped;
}

/* Forces and symplectic Euler per fluid slot; fills the step's statistics. */
static void forces_integrate(fs_sph *s, const step_consts *k, long n, float dt)
{
    const fs_grid *g = &s->g;
    const uint32_t nb = (uint32_t)s->nb;
    float vmax = 0;
    long clamps = 0, bad = 0;
#pragma omp parallel for schedule(static) if (n > FS_SPH_PARALLEL_MIN) reduction(max : vmax) reduction(+ : clamps, bad)
    for (long sl = 0; sl < n; sl++) {
        uint32_t i = g->index[sl];
        if (i < nb) continue;
        const float *xi = g->pos4 + 4 * sl, *vi = s->vel4 + 4 * sl;
        float a[3], b[3];
        fluid_forces(s, k, sl, a, b);
        float c = k->mu / s->rho[sl];
        float v[3] = {vi[0] + dt * (a[0] + c * b[0]), vi[1] + dt * (a[1] + c * b[1] - k->gy),
                      vi[2] + dt * (a[2] + c * b[2])};
        float x[3] = {xi[0] + dt * v[0], xi[1] + dt * v[1], xi[2] + dt * v[2]};
        if (!isfinite(x[0] + x[1] + x[2] + v[0] + v[1] + v[2])) bad++;
        else {
            clamps += clamp_to_box(s, x, v);
            float sp = fs_v3_len(v);
            if (sp > vmax) vmax = sp;
        }
        s->x[i] = x[0];
        s->y[i] = x[1];
        s->z[i] = x[2];
        s->vx[i] = v[0];
        s->vy[i] = v[1];
        s->vz[i] = v[2];
    }
    s->st.v_max = vmax;
    s->st.clamps += clamps;
    s->st.nonfinite = bad;
}

int fs_sph_cpu_step(fs_sph *s, float dt)
{
    fs_particles view = {0};
    view.n = s->nb + s->nf;
    view.x = s->x;
    view.y = s->y;
    view.z = s->z;
    fs_grid_free(&s->g);
    int rc = fs_grid_build(&s->g, &view, s->H);
    if (rc) return rc;
    const long n = (long)view.n;
    const step_consts k = step_consts_of(s);
    sort_velocities(s, n);
    density_pressure(s, &k, n);
    wall_pressure(s, &k, n);
    forces_integrate(s, &k, n, dt);
    return FS_OK;
}
