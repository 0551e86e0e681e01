/* field=zhu_bridson: the reference's march of Zhu & Bridson's phi (common/field/
 * zhu_bridson.h; README.md, "field=zhu_bridson"). The walk is the same; in each
 * near cell the particles within R of the ray's stretch are gathered and
 * g = -phi (>= 0 inside) is marched with steps proven by a Lipschitz bound of phi
 * on the step (below), falling back to step_min where none is proven; a sign
 * change is bisected to 1e-4 r. phi's sum is not the SPH sum, so the sub-cell
 * bounds, interior bits and second-order step of accel=on do not apply: this is
 * the only path for this field, whatever accel says.
 *
 * The bound (fs_zb_lipschitz, common/field/zhu_bridson.c). Where K = sum_i k_i > 0, phi = |x - xbar| - r has
 * |grad phi| <= 1 + |J|, J = d xbar / dx = sum_i (x_i - xbar) grad k_i^T / K, so
 * |grad phi| <= 1 + sum_i |x_i - xbar| |grad k_i| / K. On a stretch [t, t+s]
 * particle i lies between dn_i and df_i from the ray (nearest and farthest),
 * |grad k_i| <= fs_zb_dk_max(dn_i, df_i), K >= sum_i k(df_i / R) (k decreases),
 * and |x_i - xbar| <= min(df_i, R) + D with D = max_i min(df_i, R) over the
 * particles within R (xbar is a convex combination of them). So
 * L = 1 + sum_i (min(df_i, R) + D) dk_i / sum_i k(df_i / R) bounds |dphi/dt|
 * on the whole stretch, where the lower sum of K is positive (else no bound):
 * |phi(t)| > L s proves phi keeps its sign on [t, t+s). phi is 1-Lipschitz only
 * where the weights are constant; near the edge of the kernels' reach (K small)
 * L grows without bound, and there the march samples every step_min. */
#include "reference.h"
#include "counters.h"
#include "reference_bisect.h"
#include "zhu_bridson.h"
#include <math.h>
#include <string.h>

/* A particle within R of the current stretch: rel = p - o, foot a on the ray, squared distance b from its line. */
typedef struct zb_near {
    float rel[3], a, b;
} zb_near;

typedef struct zb_stretch {
    const reference *R;
    const zb_near *np;
    int n;
    float d[3];
    ray_result *cnt; /* counting: the ray's result; NULL otherwise */
} zb_stretch;

static inline ray_work *zb_work(const zb_stretch *S) { return S->cnt ? &S->cnt->w[S->cnt->hit] : NULL; }

static void zb_counted(const zb_stretch *S)
{
    ray_work *w = zb_work(S);
    if (!w) return;
    w->evals++;
    w->nbrs += (uint64_t)S->n;
}

/* phi at local t (grad, when not NULL, gets grad phi). */
static double zb_phi_at(const zb_stretch *S, float t, float grad[3])
{
    zb_counted(S);
    double R = S->R->zb_radius, inv_r2 = 1 / (R * R);
    fs_zb_sum s;
    memset(&s, 0, sizeof s);
    for (int j = 0; j < S->n; j++) {
        const zb_near *q = &S->np[j];
        fs_zb_add(&s, (double)q->rel[0] - (double)t * S->d[0], (double)q->rel[1] - (double)t * S->d[1],
                  (double)q->rel[2] - (double)t * S->d[2], inv_r2, grad != NULL);
    }
    return fs_zb_phi(&s, R, S->R->f.r, grad);
}

/* The bisection's field (reference_bisect.h): -phi (>= 0 inside), and grad phi (outward). */
static inline double zb_side(const void *ctx, float t) { return -zb_phi_at(ctx, t, NULL); }

static inline void zb_outward(const void *ctx, float t, float out[3]) { zb_phi_at(ctx, t, out); }

/* The Lipschitz bound of phi along the ray on local [t, t+s] (fs_zb_lipschitz); counted as a sum. */
static double zb_lipschitz(const zb_stretch *S, float t, float s)
{
    zb_counted(S);
    return S->n ? fs_zb_lipschitz(&S->np[0].a, sizeof(zb_near) / sizeof(float), S->n, t, s, S->R->zb_radius) : INFINITY;
}

/* The particles within R of the stretch o + t d, t in [0, len]: in the 27 cells around c (cell >= R). */
static int zb_gather(const reference *R, const int c[3], const float o[3], const float d[3], float len, zb_near *out,
                     ray_work *w)
{
    const fs_grid *g = R->g;
    float reach = R->zb_radius, R2 = reach * reach;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        float e = o[a] + len * d[a], x0 = fminf(o[a], e), x1 = fmaxf(o[a], e);
        lo[a] = fs_grid_coord(g, a, x0 - reach);
        hi[a] = fs_grid_coord(g, a, x1 + reach);
        lo[a] = lo[a] < c[a] - 1 ? c[a] - 1 : lo[a];
        hi[a] = hi[a] > c[a] + 1 ? c[a] + 1 : hi[a];
    }
    uint32_t runs[FS_GRID_MAX_RUNS][2];
    int nr = fs_grid_box_runs(g, lo, hi, runs), n = 0;
    for (int r = 0; w && r < nr; r++) w->nbrs += runs[r][1] - runs[r][0];
    for (int r = 0; r < nr; r++)
        for (uint32_t s = runs[r][0]; s < runs[r][1]; s++) {
            const float *q = g->pos4 + 4 * (size_t)s;
            float rel[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
            float a = rel[0] * d[0] + rel[1] * d[1] + rel[2] * d[2];
            float b = fmaxf(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - a * a, 0.0f);
            float e = a < 0 ? a : (a > len ? a - len : 0);
            if (b + e * e >= R2) continue;
            zb_near *p = &out[n++];
            memcpy(p->rel, rel, sizeof rel);
            p->a = a;
            p->b = b;
        }
    return n;
}

/* The next step from local t with g = -phi there: proven (returns 1) when
 * |g| > L s on it, else step_min (returns 0). */
static int zb_step(const zb_stretch *S, const march *m, float t, float rem, float *step)
{
    float smin = S->R->step_min, s = fminf(rem, fmaxf(smin, 2 * m->s_prev));
    double L = zb_lipschitz(S, t, s), sp = isfinite(L) ? fabs(m->g) / L : 0;
    if (sp >= s) {
        *step = s;
        return 1;
    }
    if (sp >= smin) {
        *step = (float)sp;
        return 1;
    }
    *step = fminf(smin, rem);
    return 0;
}

/* Marches [0, len] of one cell (ray distance t0 at its start); 1 when the ray is finished. */
static int zb_march(const zb_stretch *S, march *m, float t0, float len, ray_result *res)
{
    const reference *R = S->R;
    if (!m->started) {
        m->g = (float)-zb_phi_at(S, 0, NULL);
        if (S->cnt) zb_work(S)->samples++;
        m->inside = m->g >= 0; /* the ray starts in the fluid: not a visible crossing */
        m->counting = 0;
        m->started = 1;
    }
    float t = 0;
    while (t < len) {
        float rem = len - t, s;
        zb_step(S, m, t, rem, &s);
        float tn = s >= rem ? len : t + s, gn = (float)-zb_phi_at(S, tn, NULL);
        if (S->cnt) zb_work(S)->samples++;
        if (m->inside == (gn >= 0)) {
            m->s_prev = s;
            t = tn;
            m->g = gn;
            continue;
        }
        /* a sign change in [t, tn]: bisect, t on the current side */
        if (fs_ref_bisect_cross(R, m, res, zb_side, zb_outward, S, S->d, zb_work(S), t0, t, tn)) return 1;
        t = tn;
        m->g = gn;
    }
    return 0;
}

typedef struct zb_ray {
    const reference *R;
    const float *o, *d;
    zb_near *buf;
    march m;
    ray_result *res;
} zb_ray;

static int zb_cell(zb_ray *P, const int c[3], float t, float t_out)
{
    const reference *R = P->R;
    zb_stretch S = {R, P->buf, 0, {P->d[0], P->d[1], P->d[2]}, fs_counting ? P->res : NULL};
    float o_loc[3] = {P->o[0] + t * P->d[0], P->o[1] + t * P->d[1], P->o[2] + t * P->d[2]};
    S.n = zb_gather(R, c, o_loc, P->d, t_out - t, P->buf, zb_work(&S));
    if (S.n) return zb_march(&S, &P->m, t, t_out - t, P->res);
    fs_ref_leave_fluid(&P->m, P->res, t, R); /* no particle within R: phi = R - r, outside */
    P->m.g = -(float)(R->zb_radius - R->f.r);
    return 0;
}

static int zb_visit(void *ctx, const int c[3], uint32_t slot, float t, float t_out)
{
    zb_ray *P = ctx;
    if (slot == FS_GRID_NONE) {
        fs_ref_leave_fluid(&P->m, P->res, t, P->R);
        P->m.g = -(float)(P->R->zb_radius - P->R->f.r);
        return 0;
    }
    if (!fs_counting) return zb_cell(P, c, t, t_out);
    cell_mark mark;
    fs_ref_cell_begin(P->res, &P->m, &mark);
    int done = zb_cell(P, c, t, t_out);
    fs_ref_cell_end(&mark, P->res, &P->m, 0);
    return done;
}

size_t fs_ref_zb_buf_size(const reference *R) { return (R->max27 ? R->max27 : 1) * sizeof(zb_near); }

void fs_ref_cast_zb(const reference *R, const float o[3], const float d[3], void *buf, ray_result *res)
{
    memset(res, 0, sizeof *res);
    float g0 = -(float)(R->zb_radius - R->f.r);
    zb_ray P = {R, o, d, buf, {0, 0, 0, 0, g0, 0, R->step_min}, res};
    float t_last;
    fs_ref_walk(R, o, d, zb_visit, &P, &t_last);
    if (P.m.inside && P.m.counting) res->thick += t_last - P.m.t_enter;
}
