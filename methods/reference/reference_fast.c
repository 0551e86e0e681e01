/* accel=on: the same march as reference_plain.c (same proven steps, same
 * bisection, same normals), made fast three ways (README.md, "Accelerated path"):
 *  - sub-cells that reference_bounds.c proved outside (phi < iso) or inside
 *    (phi >= iso) are crossed without gathering or sampling, an inside one
 *    adding its chord to the thickness;
 *  - the particles near a cell's stretch are gathered once, as structure of
 *    arrays, and phi and its bound are summed in loops the compiler vectorises
 *    (omp simd; the kernels written without branches);
 *  - a sub-cell is skipped only when that agrees with the march's state, so a
 *    crossing is always found by sampling, never assumed at a sub-cell face. */
#include "reference.h"
#include "counters.h"
#include <math.h>
#include <string.h>

typedef struct fast_ray {
    const reference *R;
    const float *o, *d;
    near_soa N;
    march m;
    ray_result *res;
    int count;       /* a counting render: count the walk's cells too (fs_counting, read once a ray) */
    int ran;         /* the current cell had a run of unproven sub-cells (not crossed on bounds alone) */
    int taylor;      /* the second-order inside step applies (fs_ref_taylor_applies) */
    void *proof_buf; /* scratch of the interior proofs on demand (fs_ref_proof_ready) */
} fast_ray;

/* The work counts of the phase the ray is in: before its first hit, or after. */
static inline ray_work *work(const fast_ray *F) { return &F->res->w[F->res->hit]; }

/* The gathered arrays' bytes, a multiple of 64. */
static size_t soa_size(const reference *R)
{
    size_t cap = R->max27 ? R->max27 : 1;
    cap = (cap + 15) & ~(size_t)15;
    return cap * (5 * sizeof(float) + sizeof(uint32_t));
}

size_t fs_ref_fast_buf_size(const reference *R)
{
    return soa_size(R) + (R->fine_state ? fs_ref_proof_buf_size(R) : 0) + 64;
}

static void soa_bind(near_soa *N, void *buf, const reference *R)
{
    size_t cap = R->max27 ? R->max27 : 1;
    cap = (cap + 15) & ~(size_t)15;
    float *f = buf;
    N->a = f;
    N->b = f + cap;
    N->k = f + 2 * cap;
    N->ws = f + 3 * cap;
    N->keep = f + 4 * cap;
    N->slot = (uint32_t *)(f + 5 * cap);
    N->n = 0;
}

/* Distance along the ray from particle foot u (relative to t) to: the point
 * t (AT), the nearest point of [t, t+s] (NEAR), its farther end (FAR). */
#define FS_REF_AT(u, s) (u)
#define FS_REF_NEAR(u, s) ((u)-fs_minf(fs_maxf((u), 0.0f), (s)))
#define FS_REF_FAR(u, s) fs_maxf(fabsf(u), fabsf((u) - (s)))

/* sum_j ws_j shape(sqrt(b_j + k_j e_j^2) / H): a loop the compiler vectorises. */
#define FS_REF_SUM(SHAPE, E)                                                                                           \
    _Pragma("omp simd reduction(+ : sum)") for (int j = 0; j < n; j++)                                                 \
    {                                                                                                                  \
        float u = a[j] - t, e = E(u, s);                                                                               \
        sum += ws[j] * SHAPE(sqrtf(b[j] + k[j] * (e * e)) * inv_h);                                                    \
    }
/* The isotropic kernel: k = ws = 1. */
#define FS_REF_SUM_ISO(SHAPE, E)                                                                                       \
    _Pragma("omp simd reduction(+ : sum)") for (int j = 0; j < n; j++)                                                 \
    {                                                                                                                  \
        float u = a[j] - t, e = E(u, s);                                                                               \
        sum += SHAPE(sqrtf(b[j] + e * e) * inv_h);                                                                     \
    }
#define FS_REF_SUMS(SHAPE)                                                                                             \
    if (!aniso) {                                                                                                      \
        if (mode == 0) {                                                                                               \
            FS_REF_SUM_ISO(SHAPE, FS_REF_AT)                                                                           \
        } else if (mode == 1) {                                                                                        \
            FS_REF_SUM_ISO(SHAPE, FS_REF_NEAR)                                                                         \
        } else {                                                                                                       \
            FS_REF_SUM_ISO(SHAPE, FS_REF_FAR)                                                                          \
        }                                                                                                              \
    } else if (mode == 0) {                                                                                            \
        FS_REF_SUM(SHAPE, FS_REF_AT)                                                                                   \
    } else if (mode == 1) {                                                                                            \
        FS_REF_SUM(SHAPE, FS_REF_NEAR)                                                                                 \
    } else {                                                                                                           \
        FS_REF_SUM(SHAPE, FS_REF_FAR)                                                                                  \
    }

/* phi at local t (mode 0), or its upper (1) or lower (2) monotone-kernel
 * bound on [t, t+s]: every kernel decreases with distance. */
/* One build for AVX2 machines, one for any x86-64; picked at load time. */
#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx2", "default")))
#endif
static float
field_sum(const reference *R, const near_soa *N, float t, float s, int mode)
{
    const fs_field *f = &R->f;
    const float *restrict a = N->a, *restrict b = N->b, *restrict k = N->k, *restrict ws = N->ws;
    float inv_h = 1.0f / f->H, sum = 0;
    int n = N->n, aniso = R->inv != NULL;
    switch (f->kernel) {
    case FS_KERNEL_POLY6: FS_REF_SUMS(fs_shape_poly6) break;
    case FS_KERNEL_SPIKY: FS_REF_SUMS(fs_shape_spiky) break;
    case FS_KERNEL_WYVILL: FS_REF_SUMS(fs_shape_wyvill) break;
    default: FS_REF_SUMS(fs_shape_cubic) break;
    }
    return sum * fs_kernel_shape_c(f) * f->volume;
}

/* field_sum, counted as one field evaluation over the gathered particles. */
static inline float field_counted(const reference *R, const near_soa *N, float t, float s, int mode, ray_work *w)
{
    w->evals++;
    w->nbrs += (uint64_t)N->n;
    return field_sum(R, N, t, s, mode);
}

/* grad phi at local t (world axes), as reference_plain.c's grad_at. */
static void grad_at(const reference *R, const near_soa *N, const float d[3], float t, float gr[3])
{
    const fs_field *f = &R->f;
    float H2 = f->H * f->H;
    gr[0] = gr[1] = gr[2] = 0;
    for (int j = 0; j < N->n; j++) {
        uint32_t q = N->slot[j];
        float x[3] = {N->o[0] + t * d[0] - R->sx[q], N->o[1] + t * d[1] - R->sy[q], N->o[2] + t * d[2] - R->sz[q]};
        float d2, w;
        if (R->inv) {
            const float *M = R->inv + 9 * (size_t)N->slot[j];
            float u[3], g2[3];
            for (int a = 0; a < 3; a++) u[a] = M[3 * a] * x[0] + M[3 * a + 1] * x[1] + M[3 * a + 2] * x[2];
            for (int a = 0; a < 3; a++) g2[a] = M[3 * a] * u[0] + M[3 * a + 1] * u[1] + M[3 * a + 2] * u[2];
            d2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
            memcpy(x, g2, sizeof x);
            if (d2 >= H2 || d2 <= 0) continue;
            w = N->ws[j] * fs_kernel_dw(f->kernel, sqrtf(d2), f->H) / sqrtf(d2);
        } else {
            d2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
            if (d2 >= H2 || d2 <= 0) continue;
            w = fs_kernel_dw(f->kernel, sqrtf(d2), f->H) / sqrtf(d2);
        }
        for (int a = 0; a < 3; a++) gr[a] += w * x[a];
    }
    for (int a = 0; a < 3; a++) gr[a] *= f->volume;
}

/* Isotropic: the particles of slots [s0, s1) within H of the stretch, appended
 * to N. The distances are computed in a vectorised loop; the survivors are
 * then packed without branches. */
static int gather_run_iso(const reference *R, uint32_t s0, uint32_t s1, const float d[3], float len, near_soa *N, int n)
{
    const float *restrict x = R->sx + s0, *restrict y = R->sy + s0, *restrict z = R->sz + s0;
    float *restrict a = N->a + n, *restrict b = N->b + n, *restrict keep = N->keep;
    float H2 = R->f.H * R->f.H, o0 = N->o[0], o1 = N->o[1], o2 = N->o[2];
    int m = (int)(s1 - s0);
#pragma omp simd
    for (int j = 0; j < m; j++) {
        float rx = x[j] - o0, ry = y[j] - o1, rz = z[j] - o2;
        float aj = rx * d[0] + ry * d[1] + rz * d[2], bj = fs_maxf(rx * rx + ry * ry + rz * rz - aj * aj, 0.0f);
        float e = aj - fs_minf(fs_maxf(aj, 0.0f), len); /* foot outside the stretch */
        a[j] = aj;
        b[j] = bj;
        keep[j] = bj + e * e < H2 ? 1.0f : 0.0f;
    }
    int k = 0;
    for (int j = 0; j < m; j++) { /* pack: a[k] <= a[j] for k <= j, so in place */
        a[k] = a[j];
        b[k] = b[j];
        N->slot[n + k] = s0 + (uint32_t)j;
        k += keep[j] != 0.0f;
    }
    return n + k;
}

/* Anisotropic: the metric |A^-1 (o + u d - q)|^2 = k (u - a)^2 + b per particle. */
static int gather_run_aniso(const reference *R, uint32_t s0, uint32_t s1, const float d[3], float len, near_soa *N,
                            int n)
{
    float H2 = R->f.H * R->f.H;
    for (uint32_t s = s0; s < s1; s++) {
        float rel[3] = {R->sx[s] - N->o[0], R->sy[s] - N->o[1], R->sz[s] - N->o[2]}, md[3], mr[3];
        const float *M = R->inv + 9 * (size_t)s;
        for (int x = 0; x < 3; x++) {
            md[x] = M[3 * x] * d[0] + M[3 * x + 1] * d[1] + M[3 * x + 2] * d[2];
            mr[x] = M[3 * x] * rel[0] + M[3 * x + 1] * rel[1] + M[3 * x + 2] * rel[2];
        }
        float k = md[0] * md[0] + md[1] * md[1] + md[2] * md[2];
        float a = (md[0] * mr[0] + md[1] * mr[1] + md[2] * mr[2]) / k;
        float b = fs_maxf(mr[0] * mr[0] + mr[1] * mr[1] + mr[2] * mr[2] - k * a * a, 0.0f);
        float e = a < 0 ? a : (a > len ? a - len : 0);
        if (b + k * (e * e) >= H2) continue;
        N->a[n] = a;
        N->b[n] = b;
        N->k[n] = k;
        N->ws[n] = R->wscale[s];
        N->slot[n++] = s;
    }
    return n;
}

/* Gathers the particles within reach of the stretch o + u d, u in [0, len], of cell c. */
static void gather(const reference *R, const int c[3], const float o[3], const float d[3], float len, near_soa *N,
                   ray_work *w)
{
    const fs_grid *g = R->g;
    float H = R->reach;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        float e = o[a] + len * d[a], x0 = o[a] < e ? o[a] : e, x1 = o[a] < e ? e : o[a];
        lo[a] = fs_grid_coord(g, a, x0 - H);
        hi[a] = fs_grid_coord(g, a, x1 + H);
        lo[a] = lo[a] < c[a] - 1 ? c[a] - 1 : lo[a];
        hi[a] = hi[a] > c[a] + 1 ? c[a] + 1 : hi[a];
        N->o[a] = o[a];
    }
    uint32_t runs[FS_GRID_MAX_RUNS][2];
    int nr = fs_grid_box_runs(g, lo, hi, runs), n = 0;
    for (int r = 0; r < nr; r++) {
        n = R->inv ? gather_run_aniso(R, runs[r][0], runs[r][1], d, len, N, n)
                   : gather_run_iso(R, runs[r][0], runs[r][1], d, len, N, n);
        w->nbrs += runs[r][1] - runs[r][0];
    }
    N->n = n;
}

/* As reference_plain.c's safe_step, on the gathered arrays. */
static int safe_step(const reference *R, const near_soa *N, const march *m, float t, float rem, float lip, float *s_out,
                     float *g_end, ray_work *w)
{
    float s_lip = fabsf(m->g) / lip, floor_s = s_lip > R->step_min ? s_lip : R->step_min;
    float s = 2.0f * m->s_prev > floor_s ? 2.0f * m->s_prev : floor_s;
    s = s < rem ? s : rem;
    while (s > floor_s) {
        float b = field_counted(R, N, t, s, m->inside ? 2 : 1, w);
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

/* A crossing at local tc (ray distance t0 + tc); returns 1 when the ray is finished. */
static int crossing(fast_ray *F, float t0, float tc)
{
    const reference *R = F->R;
    march *m = &F->m;
    ray_result *res = F->res;
    work(F)->crossings++;
    float out[3] = {0, 0, 0};
    if (!m->inside && !res->hit) { /* the first hit's normal, -grad phi: still its phase */
        grad_at(R, &F->N, F->d, tc, out);
        work(F)->evals++;
        work(F)->nbrs += (uint64_t)F->N.n;
        for (int a = 0; a < 3; a++) out[a] = -out[a];
    }
    return fs_ref_cross(R, m, res, t0 + tc, out, F->d);
}

/* Shrinks the bracket [*lo, *hi] of a sign change of phi - iso (g_lo on the
 * march's current side at *lo, g_hi on the other at *hi) to at most tol:
 * regula falsi with the Illinois correction, which needs a handful of phi
 * evaluations where bisection needs about 15, and a bisection step whenever
 * two steps did not halve the bracket. Only signs of phi decide the bracket,
 * so the crossing is as certain as with bisection. */
static void locate(fast_ray *F, float *lo, float *hi, float g_lo, float g_hi, float tol)
{
    const reference *R = F->R;
    int keep = 0, inside = F->m.inside;
    float a = *lo, b = *hi, width = b - a;
    for (int it = 0; b - a > tol; it++) {
        float t = g_lo != g_hi ? (g_lo * b - g_hi * a) / (g_lo - g_hi) : 0.5f * (a + b);
        if (it % 2 == 1) {
            if (b - a > 0.5f * width) t = 0.5f * (a + b); /* slow progress: bisect */
            width = b - a;
        }
        float q = 0.25f * tol; /* stay inside the bracket */
        t = t < a + q ? a + q : (t > b - q ? b - q : t);
        if (t <= a || t >= b) t = 0.5f * (a + b); /* a + q rounded to a: tol is below the floats' spacing here */
        if (t <= a || t >= b) break;              /* the bracket is two adjacent floats: as tight as it gets */
        float g = field_counted(R, &F->N, t, 0, 0, work(F)) - R->f.iso;
        work(F)->samples++;
        work(F)->refine_evals++;
        if ((g >= 0) == inside) {
            a = t;
            g_lo = g;
            if (keep == 1) g_hi *= 0.5f;
            keep = 1;
        } else {
            b = t;
            g_hi = g;
            if (keep == -1) g_lo *= 0.5f;
            keep = -1;
        }
    }
    *lo = a;
    *hi = b;
}

/* One step from t on the second-order bound (reference_taylor.c), with M a
 * curvature bound over the range, on either side of the surface (h = g inside,
 * -g outside): 1 when the rest of the range, *s = rem, is proven on the march's
 * side (*gn a bound of g at its end), else 0 with *gn sampled at t + *s: the
 * longest proven step, or where g must have changed sign (one crossing at most
 * before it), or step_min when neither is longer. *slope is phi' at t on entry
 * (NAN: not known) and at t + *s on return; when *gn crossed, its bracket starts
 * at *lo, with about *g_lo there. */
static int taylor_step(fast_ray *F, float t, float rem, float M, float *slope, float *s, float *gn, float *lo,
                       float *g_lo)
{
    const reference *R = F->R;
    ray_work *w = work(F);
    float iso = R->f.iso, sg = F->m.inside ? 1.0f : -1.0f, l, h;
    if (isnan(*slope)) { /* the slope at t: sample it (rounding may put a crossing's end on the other side) */
        F->m.g = sg * fs_maxf(sg * (fs_ref_slope_sum(R, &F->N, t, slope) - iso), 0.0f);
        w->evals++, w->samples++, w->nbrs += (uint64_t)F->N.n;
    }
    float g = F->m.g, g1 = *slope;
    fs_ref_taylor_steps(R, sg * g, sg * g1, M, &l, &h);
    if (l >= rem) {
        *s = rem;
        *gn = sg * fs_maxf(sg * g + sg * g1 * rem - 0.5f * M * rem * rem, 0.0f);
        *slope = NAN;
        return 1;
    }
    *s = h <= rem ? h : fs_minf(fs_maxf(l, R->step_min), rem);
    *lo = t + l;
    *g_lo = sg * fs_maxf(sg * (g + g1 * l), 1e-7f * iso); /* between the bounds: only where regula falsi starts */
    *gn = fs_ref_slope_sum(R, &F->N, t + *s, slope) - iso;
    w->evals++, w->nbrs += (uint64_t)F->N.n;
    return 0;
}

/* Marches local [u0, u1] of the cell stretch that starts at ray distance t0. */
static int march_range(fast_ray *F, float t0, float u0, float u1, float lip)
{
    const reference *R = F->R;
    march *m = &F->m;
    float iso = R->f.iso, tol = 1e-5f * R->f.r; /* finer than the plain path: halves the gap between them */
    float M = F->taylor ? fs_ref_curv_bound(R, &F->N, u0, u1) : 0.0f, slope = NAN;
    if (!m->started) {
        m->g = field_counted(R, &F->N, u0, 0, 0, work(F)) - iso;
        work(F)->samples++;
        m->inside = m->g >= 0;
        m->counting = 0;
        m->started = 1;
    }
    for (float t = u0; t < u1;) {
        float rem = u1 - t, s, gn, lo = t, g_lo = m->g;
        ray_work *w = work(F); /* a crossing below may change the phase */
        int proven;
        /* inside, the second-order step pays where the interior bits leave short unproven
         * stretches; through long unproven interior (no bits built) the doubling trials of
         * the monotone bound prove longer steps per sum (README.md, step 11) */
        if (M > 0 && (!m->inside || R->fine)) {
            proven = taylor_step(F, t, rem, M, &slope, &s, &gn, &lo, &g_lo);
        } else {
            slope = NAN;
            proven = safe_step(R, &F->N, m, t, rem, lip, &s, &gn, w);
            if (!proven) gn = field_counted(R, &F->N, s >= rem ? u1 : t + s, 0, 0, w) - iso;
        }
        float tn = s >= rem ? u1 : t + s;
        w->samples++; /* the step's end, sampled or proven */
        if (m->inside == (gn >= 0)) {
            m->s_prev = s;
            t = tn;
            m->g = gn;
            continue;
        }
        float hi = tn;
        locate(F, &lo, &hi, g_lo, gn, tol);
        if (crossing(F, t0, 0.5f * (lo + hi))) return 1;
        t = tn;
        m->g = gn;
        slope = NAN;
    }
    return 0;
}

/* A proven sub-cell of class cls, with v a bound of phi - iso on it (at least
 * v inside, at most v outside): 1 when skipping it agrees with the march's
 * state (the state is updated), 0 when it must be marched. */
static int skip_proven(march *m, int cls, float v)
{
    if (cls == FS_REF_EDGE) return 0;
    int in = cls == FS_REF_IN;
    if (m->started && m->inside != in) return 0; /* a crossing lies before: find it by sampling */
    if (!m->started) {
        m->started = 1;
        m->inside = in;
        m->counting = 0;
    }
    m->g = v;
    return 1;
}

/* Class of sub-cell c at resolution res (R->sub, or FS_REF_FINE where the cell
 * has interior bits), and *v its bound of phi - iso. */
static int sub_class(const reference *R, uint32_t slot, int res, const int c[3], float *v)
{
    int f = res / R->sub;
    size_t s = ((size_t)slot * R->sub + c[2] / f) * R->sub * R->sub + (size_t)(c[1] / f) * R->sub + c[0] / f;
    float q = R->f.iso / FS_REF_Q;
    if (R->hi[s] < FS_REF_Q) {
        *v = (float)R->hi[s] * q - R->f.iso;
        return FS_REF_OUT;
    }
    if (R->lo[s] >= FS_REF_Q) {
        *v = (float)R->lo[s] * q - R->f.iso;
        return FS_REF_IN;
    }
    *v = 0;
    if (res == R->sub) return FS_REF_EDGE;
    size_t k = ((size_t)c[2] * FS_REF_FINE + c[1]) * FS_REF_FINE + c[0];
    const uint8_t *bits = R->fine + (size_t)slot * (FS_REF_FINE3 / 8);
    return bits[k >> 3] >> (k & 7) & 1u ? FS_REF_IN : FS_REF_EDGE;
}

typedef struct subwalk {
    int c[3], step[3];
    float tmax[3], tdelta[3];
} subwalk;

static void sub_start(const reference *R, int res, const int cell[3], const float o[3], const float d[3], float t,
                      subwalk *w)
{
    const fs_grid *g = R->g;
    float e = g->cell / (float)res;
    for (int a = 0; a < 3; a++) {
        float base = g->origin[a] + g->cell * (float)cell[a];
        int c = (int)floorf((o[a] + t * d[a] - base) / e);
        w->c[a] = c < 0 ? 0 : (c > res - 1 ? res - 1 : c);
        float face = base + e * (float)(w->c[a] + (d[a] > 0));
        if (d[a] != 0) {
            w->step[a] = d[a] > 0 ? 1 : -1;
            w->tmax[a] = (face - o[a]) / d[a];
            w->tdelta[a] = e / fabsf(d[a]);
        } else {
            w->step[a] = 0;
            w->tmax[a] = w->tdelta[a] = INFINITY;
        }
    }
}

/* Marches the cell stretch [t, t_out] sub-cell by sub-cell at resolution res
 * (R->sub, or FS_REF_FINE over a cell's interior proof); edge sub-cells in a
 * row are marched as one range, over the particles gathered once. */
static int visit_subcells(fast_ray *F, const int c[3], uint32_t slot, float t, float t_out, float lip, int res)
{
    const reference *R = F->R;
    const float *o = F->o, *d = F->d;
    subwalk w;
    sub_start(R, res, c, o, d, t, &w);
    float o_loc[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]}, v;
    int gathered = 0, cls = sub_class(R, slot, res, w.c, &v);
    float edge0 = -1; /* start of a pending run of edge sub-cells, -1 when none */
    for (float ts = t;;) {
        float te = fs_minf(fs_minf(w.tmax[0], w.tmax[1]), fs_minf(w.tmax[2], t_out));
        if (te < ts) te = ts;
        int a = w.tmax[0] < w.tmax[1] ? (w.tmax[0] < w.tmax[2] ? 0 : 2) : (w.tmax[1] < w.tmax[2] ? 1 : 2);
        int last = te >= t_out, next_cls = FS_REF_EDGE;
        float next_v = 0;
        if (!last) {
            w.c[a] += w.step[a];
            last = w.c[a] < 0 || w.c[a] >= res;
            if (!last) next_cls = sub_class(R, slot, res, w.c, &next_v);
        }
        if (edge0 >= 0 || !skip_proven(&F->m, cls, v)) {
            if (edge0 < 0) edge0 = ts;
            if (last || next_cls != FS_REF_EDGE) { /* the run of marched sub-cells ends here */
                float end = last ? t_out : te;
                F->ran = 1;
                if (!gathered) {
                    gather(R, c, o_loc, d, t_out - t, &F->N, work(F));
                    gathered = 1;
                }
                if (F->N.n) {
                    if (march_range(F, t, edge0 - t, end - t, lip)) return 1;
                } else {
                    fs_ref_leave_fluid(&F->m, F->res, edge0, R);
                }
                edge0 = -1;
            }
        }
        if (last) return 0;
        w.tmax[a] += w.tdelta[a];
        ts = te;
        cls = next_cls;
        v = next_v;
    }
}

/* One near cell's stretch [t, t_out]: 1 when the ray is finished. */
static int visit_cell(fast_ray *F, const int c[3], uint32_t slot, float t, float t_out)
{
    const reference *R = F->R;
    uint32_t cnt = R->count27[slot];
    float lip = R->lip_unit * (float)cnt;
    if (cnt && R->sub) {
        int cls = fs_ref_cell_ready(R, c, slot, &F->res->w[FS_REF_BOUNDS]), res = R->sub;
        if ((cls == FS_REF_IN || cls == FS_REF_OUT) && skip_proven(&F->m, cls, 0)) return 0; /* proven whole */
        if (cls == FS_REF_EDGE_IN && F->m.started && F->m.inside && R->fine) {
            /* a ray inside on entry reads the cell's interior proof, made now if no ray has made it */
            if (fs_ref_proof_ready(R, c, slot, F->proof_buf, &F->res->w[FS_REF_PROOFS]) == FS_REF_PROOF_ALL_IN) {
                skip_proven(&F->m, FS_REF_IN, 0); /* the whole cell is inside, as the ray is */
                return 0;
            }
            res = FS_REF_FINE;
        }
        return visit_subcells(F, c, slot, t, t_out, lip, res);
    }
    F->ran = 1;
    if (cnt) {
        const float *o = F->o, *d = F->d;
        float o_loc[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
        gather(R, c, o_loc, d, t_out - t, &F->N, work(F));
        if (F->N.n) return march_range(F, t, 0, t_out - t, lip);
    }
    fs_ref_leave_fluid(&F->m, F->res, t, R);
    return 0;
}

static int fast_visit(void *ctx, const int c[3], uint32_t slot, float t, float t_out)
{
    fast_ray *F = ctx;
    if (slot == FS_GRID_NONE) {
        fs_ref_leave_fluid(&F->m, F->res, t, F->R);
        return 0;
    }
    if (!F->count) return visit_cell(F, c, slot, t, t_out);
    cell_mark mark;
    fs_ref_cell_begin(F->res, &F->m, &mark);
    F->ran = 0;
    int done = visit_cell(F, c, slot, t, t_out);
    fs_ref_cell_end(&mark, F->res, &F->m, !F->ran);
    return done;
}

void fs_ref_cast_fast(const reference *R, const float o[3], const float d[3], void *buf, ray_result *res)
{
    memset(res, 0, sizeof *res);
    fast_ray F = {R,
                  o,
                  d,
                  {0},
                  {0, 0, 0, 0, -R->f.iso, 0, R->step_min},
                  res,
                  fs_counting,
                  0,
                  fs_ref_taylor_applies(R),
                  (char *)buf + soa_size(R)};
    soa_bind(&F.N, buf, R);
    float t_last;
    fs_ref_walk(R, o, d, fast_visit, &F, &t_last);
    if (F.m.inside && F.m.counting) res->thick += t_last - F.m.t_enter;
}
