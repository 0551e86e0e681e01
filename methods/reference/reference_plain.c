/* accel=off: the reference's march as it was first written (README.md,
 * "Algorithm"): per cell, the particles near the ray's stretch are gathered
 * and phi is stepped with the Lipschitz and monotone-kernel bounds. Kept as the
 * plain path that the accelerated one is checked against. */
#include "reference.h"
#include "counters.h"
#include "reference_bisect.h"
#include <math.h>
#include <string.h>

/* A particle near the current cell's stretch of the ray, relative to the
 * stretch's start point o: the ray reaches its foot at local t = a, b is the
 * squared distance from the ray line, rel = p - o. */
typedef struct near_particle {
    float a, b, k, ws, rel[3];
    uint32_t slot;
} near_particle;

typedef struct stretch {
    const reference *R;
    const near_particle *np;
    int n;
    float d[3];
    ray_result *cnt; /* the ray's result, whose work counts it keeps; NULL when not counting (read once per stretch) */
} stretch;

/* The counts of the phase the ray is in (before its first hit, or after); NULL when not counting. */
static inline ray_work *work(const stretch *S) { return S->cnt ? &S->cnt->w[S->cnt->hit] : NULL; }

/* One field evaluation (value, bound or gradient) over the stretch's particles. */
static inline void counted(const stretch *S)
{
    ray_work *w = work(S);
    if (!w) return; /* a timed render: no read-modify-write of the ray's counts */
    w->evals++;
    w->nbrs += (uint64_t)S->n;
}

/* phi at local ray parameter t. */
static float phi_at(const stretch *S, float t)
{
    counted(S);
    const fs_field *f = &S->R->f;
    float H2 = f->H * f->H, sum = 0;
    for (int j = 0; j < S->n; j++) {
        float u = t - S->np[j].a, d2 = S->np[j].b + S->np[j].k * (u * u);
        if (d2 < H2) sum += S->np[j].ws * fs_kernel_w(f->kernel, sqrtf(d2), f->H);
    }
    return sum * f->volume;
}

/* Every kernel decreases with distance, so on the stretch [t, t+s] each particle
 * contributes at most W(its distance to the stretch) and at least W(its
 * distance to the farther end). upper = 1 gives the upper bound of phi there. */
static float phi_bound(const stretch *S, float t, float s, int upper)
{
    counted(S);
    const fs_field *f = &S->R->f;
    float H2 = f->H * f->H, sum = 0;
    for (int j = 0; j < S->n; j++) {
        float u = S->np[j].a - t, e; /* foot relative to t */
        if (upper) e = u < 0 ? u : (u > s ? u - s : 0);
        else e = u > 0.5f * s ? u : u - s; /* the farther end */
        float d2 = S->np[j].b + S->np[j].k * (e * e);
        if (d2 < H2) sum += S->np[j].ws * fs_kernel_w(f->kernel, sqrtf(d2), f->H);
    }
    return sum * f->volume;
}

/* grad phi at local t (world axes). */
static void grad_at(const stretch *S, float t, float gr[3])
{
    counted(S);
    const fs_field *f = &S->R->f;
    float H2 = f->H * f->H;
    gr[0] = gr[1] = gr[2] = 0;
    for (int j = 0; j < S->n; j++) {
        float x[3] = {t * S->d[0] - S->np[j].rel[0], t * S->d[1] - S->np[j].rel[1], t * S->d[2] - S->np[j].rel[2]};
        const float *M = S->R->inv ? S->R->inv + 9 * (size_t)S->np[j].slot : NULL;
        if (M) { /* u = A^-1 x; the gradient is W'(|u|)/|u| A^-1 u / det A (A symmetric) */
            float u[3], g2[3];
            for (int a = 0; a < 3; a++) u[a] = M[3 * a] * x[0] + M[3 * a + 1] * x[1] + M[3 * a + 2] * x[2];
            for (int a = 0; a < 3; a++) g2[a] = M[3 * a] * u[0] + M[3 * a + 1] * u[1] + M[3 * a + 2] * u[2];
            memcpy(x, g2, sizeof x);
            float d2u = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
            if (d2u >= H2 || d2u <= 0) continue;
            float d = sqrtf(d2u), w = S->np[j].ws * fs_kernel_dw(f->kernel, d, f->H) / d;
            for (int a = 0; a < 3; a++) gr[a] += w * x[a];
            continue;
        }
        float d2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        if (d2 >= H2 || d2 <= 0) continue;
        float d = sqrtf(d2), w = fs_kernel_dw(f->kernel, d, f->H) / d;
        for (int a = 0; a < 3; a++) gr[a] += w * x[a];
    }
    for (int a = 0; a < 3; a++) gr[a] *= f->volume;
}

/* The bisection's field (reference_bisect.h): phi - iso, and -grad phi. */
static inline double plain_side(const void *ctx, float t)
{
    const stretch *S = ctx;
    return phi_at(S, t) - S->R->f.iso;
}

static inline void plain_outward(const void *ctx, float t, float out[3])
{
    grad_at(ctx, t, out);
    for (int a = 0; a < 3; a++) out[a] = -out[a];
}

/* Collects the particles that can reach the stretch o + t d, t in [0, len]
 * (distance to the stretch below H). They lie in the 27 cells around cell c
 * because cell >= H; only the cells the stretch's box grown by H touches are read. */
static int gather(const reference *R, const int c[3], const float o[3], const float d[3], float len, near_particle *out,
                  ray_work *w)
{
    const fs_grid *g = R->g;
    float H = R->reach, H2 = R->f.H * R->f.H;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        float e = o[a] + len * d[a], x0 = o[a] < e ? o[a] : e, x1 = o[a] < e ? e : o[a];
        lo[a] = fs_grid_coord(g, a, x0 - H);
        hi[a] = fs_grid_coord(g, a, x1 + H);
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
            float a, b, k = 1, ws = 1;
            if (R->inv) {
                /* Metric |A^-1 (o + t d - q)|^2 = k (t - a)^2 + b: the same form as the isotropic one. */
                const float *M = R->inv + 9 * (size_t)s;
                float md[3], mr[3];
                for (int x = 0; x < 3; x++) {
                    md[x] = M[3 * x] * d[0] + M[3 * x + 1] * d[1] + M[3 * x + 2] * d[2];
                    mr[x] = M[3 * x] * rel[0] + M[3 * x + 1] * rel[1] + M[3 * x + 2] * rel[2];
                }
                k = md[0] * md[0] + md[1] * md[1] + md[2] * md[2];
                a = (md[0] * mr[0] + md[1] * mr[1] + md[2] * mr[2]) / k;
                b = mr[0] * mr[0] + mr[1] * mr[1] + mr[2] * mr[2] - k * a * a;
                ws = R->wscale[s];
            } else {
                a = rel[0] * d[0] + rel[1] * d[1] + rel[2] * d[2];
                b = rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - a * a;
            }
            float e = a < 0 ? a : (a > len ? a - len : 0); /* foot outside the stretch */
            b = b > 0 ? b : 0;
            if (b + k * (e * e) >= H2) continue;
            near_particle *p = &out[n++];
            p->a = a;
            p->b = b;
            p->k = k;
            p->ws = ws;
            p->slot = s;
            memcpy(p->rel, rel, sizeof rel);
        }
    return n;
}

/* Step from local t. The per-cell Lipschitz step |g| / L_c is safe without a
 * test; longer steps (doubling the last one) are tried against the
 * monotone-kernel bound of phi on [t, t+s]. When that bound proves the step,
 * *proven gets phi - iso's conservative value at the end (the bound minus iso)
 * and returns 1; otherwise the step is |g| / L_c or step_min and phi must be sampled. */
static int safe_step(const stretch *S, const march *m, float t, float rem, float lip, float *s_out, float *g_end)
{
    const reference *R = S->R;
    float s_lip = fabsf(m->g) / lip, floor_s = s_lip > R->step_min ? s_lip : R->step_min;
    float s = 2.0f * m->s_prev > floor_s ? 2.0f * m->s_prev : floor_s;
    s = s < rem ? s : rem;
    while (s > floor_s) {
        float b = phi_bound(S, t, s, !m->inside);
        if (m->inside ? b >= R->f.iso : b < R->f.iso) {
            *s_out = s;
            *g_end = b - R->f.iso;
            return 1;
        }
        s = 0.5f * s > floor_s ? 0.5f * s : floor_s;
    }
    *s_out = s < rem ? s : rem;
    return 0;
}

/* Marches the stretch [0, len] of one cell (ray distance t0 at its start).
 * Returns 1 when the ray is finished. */
static int march_stretch(const stretch *S, march *m, float t0, float len, float lip, ray_result *res)
{
    const reference *R = S->R;
    float iso = R->f.iso;
    if (!m->started) {
        m->g = phi_at(S, 0) - iso;
        if (S->cnt) work(S)->samples++;
        m->inside = m->g >= 0; /* the ray starts in the fluid: not a visible crossing */
        m->counting = 0;
        m->started = 1;
    }
    float t = 0;
    while (t < len) {
        float rem = len - t, s, gn;
        int proven = safe_step(S, m, t, rem, lip, &s, &gn);
        float tn = s >= rem ? len : t + s;
        if (!proven) gn = phi_at(S, tn) - iso;
        if (S->cnt) work(S)->samples++; /* the step's end, sampled or proven */
        if (m->inside == (gn >= 0)) {
            m->s_prev = s;
            t = tn;
            m->g = gn;
            continue;
        }
        /* Sign change in [t, tn]: bisect, keeping t on the current side. */
        if (fs_ref_bisect_cross(R, m, res, plain_side, plain_outward, S, S->d, work(S), t0, t, tn)) return 1;
        t = tn;
        m->g = gn;
    }
    return 0;
}

typedef struct plain_ray {
    const reference *R;
    const float *o, *d;
    near_particle *buf;
    march m;
    ray_result *res;
} plain_ray;

/* One near cell's stretch [t, t_out]: 1 when the ray is finished. */
static int visit_cell(plain_ray *P, const int c[3], uint32_t slot, float t, float t_out)
{
    const reference *R = P->R;
    uint32_t cnt = R->count27[slot];
    const float *o = P->o, *d = P->d;
    stretch S = {R, P->buf, 0, {d[0], d[1], d[2]}, fs_counting ? P->res : NULL};
    float o_loc[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    if (cnt) S.n = gather(R, c, o_loc, d, t_out - t, P->buf, work(&S));
    if (S.n) return march_stretch(&S, &P->m, t, t_out - t, R->lip_unit * cnt, P->res);
    fs_ref_leave_fluid(&P->m, P->res, t, R);
    return 0;
}

static int plain_visit(void *ctx, const int c[3], uint32_t slot, float t, float t_out)
{
    plain_ray *P = ctx;
    if (slot == FS_GRID_NONE) { /* phi = 0 here: it cannot be inside (phi is continuous) */
        fs_ref_leave_fluid(&P->m, P->res, t, P->R);
        return 0;
    }
    if (!fs_counting) return visit_cell(P, c, slot, t, t_out);
    cell_mark mark; /* no bounds on this path: a cell is marched or passed, never proven */
    fs_ref_cell_begin(P->res, &P->m, &mark);
    int done = visit_cell(P, c, slot, t, t_out);
    fs_ref_cell_end(&mark, P->res, &P->m, 0);
    return done;
}

size_t fs_ref_plain_buf_size(const reference *R) { return (R->max27 ? R->max27 : 1) * sizeof(near_particle); }

void fs_ref_cast_plain(const reference *R, const float o[3], const float d[3], void *buf, ray_result *res)
{
    memset(res, 0, sizeof *res);
    plain_ray P = {R, o, d, buf, {0, 0, 0, 0, -R->f.iso, 0, R->step_min}, res};
    float t_last;
    fs_ref_walk(R, o, d, plain_visit, &P, &t_last);
    if (P.m.inside && P.m.counting) res->thick += t_last - P.m.t_enter; /* left the last box inside */
}
