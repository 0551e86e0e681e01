/* reference: exact CPU ray caster of the SPH iso-surface phi = iso (docs/DESIGN.md,
 * References). Per pixel the ray walks the neighbour grid cell by cell (3D-DDA);
 * empty cells are skipped, inside a non-empty cell the ray advances by steps
 * proven not to cross the iso-surface, a sign change is bisected to 1e-4 r and
 * the normal is the analytic -grad phi. See README.md for why the steps are safe.
 * field=anisotropic: Yu & Turk's kernel W(|A_j^-1 (x - c_j)|, H) / det A_j with
 * the centres c_j and stretches A_j of common/field/anisotropy.c. */
#include "anisotropy.h"
#include "eigen3.h"
#include "fs_error.h"
#include "method.h"
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

typedef struct reference_params {
    double step_min, thickness, max_layers, field, aniso_radius, kappa, n_eps, aniso_scale, aniso_norm, lambda;
} reference_params;

#define FIELD(f) FS_PARAM_FIELD(reference_params, f)
static const fs_param_def params[] = {
    {FIELD(step_min), FS_PARAM_FLOAT, 0.02, 1e-4, 1.0, NULL,
     "smallest march step, multiples of r; crossing intervals shorter than this can be missed"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL, "march past the first hit and sum every inside interval (on/off)"},
    {FIELD(max_layers), FS_PARAM_INT, 64, 1, 1e6, NULL, "most inside intervals summed into the thickness"},
    {FIELD(field), FS_PARAM_ENUM, 0, 0, 1, "isotropic|anisotropic", "SPH kernel, or Yu & Turk's anisotropic kernel"},
    {FIELD(aniso_radius), FS_PARAM_FLOAT, FS_ANISO_RADIUS_R, 1.0, 40.0, NULL, "anisotropic: WPCA radius, multiples of r"},
    {FIELD(kappa), FS_PARAM_FLOAT, FS_ANISO_KAPPA, 1.0, 100.0, NULL, "anisotropic: largest/smallest eigenvalue limit"},
    {FIELD(n_eps), FS_PARAM_INT, FS_ANISO_N_EPS, 0, 10000, NULL, "anisotropic: at or below this many neighbours: isotropic"},
    {FIELD(aniso_scale), FS_PARAM_FLOAT, FS_ANISO_SCALE, 0.05, 20.0, NULL, "anisotropic: stretch scale"},
    {FIELD(aniso_norm), FS_PARAM_ENUM, FS_ANISO_PER_PARTICLE, 0, 1, "global|volume", "anisotropic: stretch normalisation"},
    {FIELD(lambda), FS_PARAM_FLOAT, FS_ANISO_LAMBDA, 0.0, 1.0, NULL, "anisotropic: Laplacian smoothing of centres"},
};
#undef FIELD

typedef struct reference {
    fs_field f;
    float step_min;      /* scene units */
    int thickness, max_layers;
    const fs_grid *g;
    int dim[3];          /* rays traverse cells [0, dim): the box of the former dense grid */
    uint32_t *count27;   /* particles in the 27 cells around each cell slot */
    uint32_t max27;
    float lip_unit;      /* V max|W'|: the cell's Lipschitz bound is lip_unit * count27 */
    int aniso;
    fs_aniso_params ap;
    float reach;         /* largest distance at which a particle's kernel is nonzero: H (times the largest axis) */
    fs_grid own;         /* anisotropic: grid of the kernel centres, cell >= reach */
    float *inv;          /* anisotropic: A^-1 per sorted slot of own (9 floats) */
    float *wscale;       /* anisotropic: 1 / det A per sorted slot */
} reference;

/* A particle near the current cell's stretch of the ray, relative to the
 * stretch's start point o: the ray reaches its foot at local t = a, b is the
 * squared distance from the ray line, rel = p - o. */
typedef struct near_particle { float a, b, k, ws, rel[3]; uint32_t slot; } near_particle;

typedef struct stretch {
    const reference *R;
    const near_particle *np;
    int n;
    float d[3];
} stretch;

typedef struct ray_result {
    int hit;
    float t;        /* ray distance of the first hit */
    float n[3];     /* world normal, -grad phi normalised */
    float thick;
} ray_result;

static void destroy(void *self)
{
    reference *R = self;
    if (!R) return;
    free(R->count27);
    free(R->inv);
    free(R->wscale);
    fs_grid_free(&R->own);
    free(R);
}

static void *create(const fs_method_setup *setup)
{
    const fs_field *f = &setup->field;
    if (fs_method_check_field("reference", f)) return NULL;
    reference_params p;
    if (fs_method_params_copy("reference", setup, &p, sizeof p)) return NULL;
    reference *R = calloc(1, sizeof *R);
    if (!R) { fs_fail(FS_ERR_RUNTIME, "reference: out of memory"); return NULL; }
    R->f = *f;
    R->aniso = p.field != 0;
    fs_aniso_defaults(&R->ap, f->kernel, f->r);
    R->ap.radius = (float)p.aniso_radius * f->r;
    R->ap.kappa = (float)p.kappa;
    R->ap.n_eps = (int)p.n_eps;
    R->ap.scale = (float)p.aniso_scale;
    R->ap.per_particle = (int)p.aniso_norm;
    R->ap.lambda = (float)p.lambda;
    R->ap.sigma_ref = (float)fs_aniso_sigma_ref(f->kernel, R->ap.radius, 2 * f->r);
    R->reach = f->H;
    R->step_min = (float)p.step_min * f->r;
    R->thickness = p.thickness != 0;
    R->max_layers = (int)p.max_layers;
    R->lip_unit = f->volume * fs_kernel_max_dw(f->kernel, f->H);
    return R;
}

/* field=anisotropic: the kernel centres and stretches of common/field/anisotropy.c,
 * a grid of the centres with cells of at least H times the largest axis (so
 * the 27-cell argument of upload still holds), A^-1 and 1/det A per slot, and
 * the Lipschitz unit V max|W'| max_j (1 / (det A_j a_min,j)): the gradient of
 * W(|A^-1 y|)/det A is W'(|u|) A^-1 u / (|u| det A), at most max|W'| / (det A a_min). */
static int upload_aniso(reference *R, const fs_particles *p, const fs_grid *g)
{
    size_t n = p->n;
    float *A = malloc((n ? n : 1) * 9 * sizeof *A);
    fs_particles c;
    int rc = A ? fs_particles_alloc(&c, n, 0) : fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %zu particles", n);
    if (rc) { free(A); return rc; }
    float *cen = malloc((n ? n : 1) * 3 * sizeof *cen);
    if (!cen) { free(A); fs_particles_free(&c); return fs_fail(FS_ERR_RUNTIME, "reference: out of memory"); }
    rc = fs_aniso_compute(p, g, &R->ap, cen, A, NULL);
    float amax = 1, lip = 0;
    float *inv = malloc((n ? n : 1) * 9 * sizeof *inv), *ws = malloc((n ? n : 1) * sizeof *ws);
    if (!rc && (!inv || !ws)) rc = fs_fail(FS_ERR_RUNTIME, "reference: out of memory");
    for (size_t i = 0; !rc && i < n; i++) {
        c.x[i] = cen[3 * i];
        c.y[i] = cen[3 * i + 1];
        c.z[i] = cen[3 * i + 2];
        double a[9], ev[3], V[9];
        for (int k = 0; k < 9; k++) a[k] = A[9 * i + k];
        fs_eigen3_sym(a, ev, V);
        if (!(ev[0] > 0)) { rc = fs_fail(FS_ERR_RUNTIME, "reference: particle %zu has a degenerate stretch", i); break; }
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++) {
                double v = 0;
                for (int k = 0; k < 3; k++) v += V[3 * k + r] * V[3 * k + q] / ev[k];
                inv[9 * i + 3 * r + q] = (float)v;
            }
        ws[i] = (float)(1.0 / (ev[0] * ev[1] * ev[2]));
        if (ev[2] > amax) amax = (float)ev[2];
        if (ws[i] / ev[0] > lip) lip = (float)(ws[i] / ev[0]);
    }
    free(A);
    free(cen);
    fs_grid_free(&R->own);
    if (!rc) {
        fs_particles_bounds(&c);
        R->reach = R->f.H * amax * 1.0001f; /* a little margin for float rounding of the metric */
        rc = fs_grid_build(&R->own, &c, R->reach);
    }
    fs_particles_free(&c);
    free(R->inv);
    free(R->wscale);
    R->inv = R->wscale = NULL;
    if (rc) { free(inv); free(ws); return rc; }
    /* To sorted slot order. */
    R->inv = malloc((n ? n : 1) * 9 * sizeof *R->inv);
    R->wscale = malloc((n ? n : 1) * sizeof *R->wscale);
    if (!R->inv || !R->wscale) { free(inv); free(ws); return fs_fail(FS_ERR_RUNTIME, "reference: out of memory"); }
    for (size_t sl = 0; sl < n; sl++) {
        uint32_t o = R->own.index[sl];
        memcpy(R->inv + 9 * sl, inv + 9 * (size_t)o, 9 * sizeof *inv);
        R->wscale[sl] = ws[o];
    }
    free(inv);
    free(ws);
    R->lip_unit = R->f.volume * fs_kernel_max_dw(R->f.kernel, R->f.H) * (lip > 0 ? lip : 1);
    return FS_OK;
}

/* The cell range of the former dense grid (the lowest particle is in cell 1,
 * one empty cell beyond the highest), so rays walk the same cells as before. */
static void box_dim(const fs_grid *g, int dim[3])
{
    for (int a = 0; a < 3; a++) {
        float hi = -INFINITY;
        for (size_t s = 0; s < g->n; s++) hi = fmaxf(hi, g->pos4[4 * s + a]);
        dim[a] = g->n ? (int)(floor(((double)hi - g->origin[a]) / g->cell) + 2) : 1;
    }
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    reference *R = self;
    if (R->aniso) {
        if (g->n != p->n) return fs_fail(FS_ERR_RUNTIME, "reference: grid holds %zu particles, the set %zu", g->n, p->n);
        int rc = upload_aniso(R, p, g);
        if (rc) return rc;
        g = &R->own;
    }
    /* With cell >= H every particle within H of a point of cell c lies in the
     * 27 cells around c: that is what makes the per-cell bound valid. */
    if (!(g->cell >= R->reach))
        return fs_fail(FS_ERR_INPUT, "reference: grid cell %g is smaller than the kernel support H = %g", g->cell, R->f.H);
    if (g->n != p->n) return fs_fail(FS_ERR_RUNTIME, "reference: grid holds %zu particles, the set %zu", g->n, p->n);
    free(R->count27);
    R->count27 = malloc(g->ncells * sizeof *R->count27);
    if (!R->count27) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %zu cells", g->ncells);
    R->g = g;
    box_dim(g, R->dim);
    uint32_t mx = 0;
    long nb = (long)g->nblocks;
#pragma omp parallel for reduction(max : mx) schedule(static)
    for (long b = 0; b < nb; b++)
        for (int l = 0; l < FS_GRID_B3; l++) {
            const int32_t *key = g->bkey + 3 * b;
            int i = key[0] * FS_GRID_B + l % FS_GRID_B, j = key[1] * FS_GRID_B + l / FS_GRID_B % FS_GRID_B,
                k = key[2] * FS_GRID_B + l / (FS_GRID_B * FS_GRID_B);
            uint32_t c = 0, s0, s1;
            for (int kk = k - 1; kk <= k + 1; kk++)
                for (int jj = j - 1; jj <= j + 1; jj++)
                    for (int ii = i - 1, e; ii <= i + 1; ii = e + 1) {
                        e = fs_grid_row_run(g, ii, i + 1, jj, kk, &s0, &s1);
                        c += s1 - s0;
                    }
            R->count27[(size_t)b * FS_GRID_B3 + l] = c;
            if (c > mx) mx = c;
        }
    R->max27 = mx;
    return FS_OK;
}

/* phi at local ray parameter t. */
static float phi_at(const stretch *S, float t)
{
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

/* Collects the particles that can reach the stretch o + t d, t in [0, len]
 * (distance to the stretch below H). They lie in the 27 cells around cell c
 * because cell >= H; only the cells the stretch's box grown by H touches are read. */
static int gather(const reference *R, const int c[3], const float o[3], const float d[3], float len, near_particle *out)
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
        lo[a] = lo[a] < 0 ? 0 : lo[a];
        hi[a] = hi[a] > R->dim[a] - 1 ? R->dim[a] - 1 : hi[a];
    }
    int n = 0;
    uint32_t s0, s1;
    for (int k = lo[2]; k <= hi[2]; k++)
        for (int j = lo[1]; j <= hi[1]; j++)
            for (int i = lo[0], ie; i <= hi[0]; i = ie + 1) { /* cells i..ie: one run of slots */
            ie = fs_grid_row_run(g, i, hi[0], j, k, &s0, &s1);
            for (uint32_t s = s0; s < s1; s++) {
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
        }
    return n;
}

/* The march state carried from cell to cell along one ray. */
typedef struct march {
    int started;       /* phi has been sampled once */
    int inside;        /* phi >= iso at the current point */
    int counting;      /* the inside interval was entered from outside */
    int layers;
    float g;           /* phi - iso at the current point */
    float t_enter;     /* ray distance where the current inside interval began */
    float s_prev;
} march;

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
    float iso = R->f.iso, tol = 1e-4f * R->f.r;
    if (!m->started) {
        m->g = phi_at(S, 0) - iso;
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
        if (m->inside == (gn >= 0)) { m->s_prev = s; t = tn; m->g = gn; continue; }
        /* Sign change in [t, tn]: bisect, keeping lo on the current side. */
        float lo = t, hi = tn;
        while (hi - lo > tol) {
            float mid = 0.5f * (lo + hi);
            if ((phi_at(S, mid) - iso >= 0) == m->inside) lo = mid; else hi = mid;
        }
        float tc = 0.5f * (lo + hi);
        if (!m->inside) {
            if (!res->hit) {
                float gr[3], l;
                grad_at(S, tc, gr);
                l = sqrtf(gr[0] * gr[0] + gr[1] * gr[1] + gr[2] * gr[2]);
                for (int a = 0; a < 3; a++) res->n[a] = l > 0 ? -gr[a] / l : -S->d[a];
                res->hit = 1;
                res->t = t0 + tc;
                if (!R->thickness) return 1;
            }
            m->t_enter = t0 + tc;
            m->counting = 1;
            m->layers++;
        } else {
            if (m->counting) res->thick += t0 + tc - m->t_enter;
            m->counting = 0;
            if (m->layers >= R->max_layers) return 1;
        }
        m->inside = !m->inside;
        m->s_prev = R->step_min;
        t = tn;
        m->g = gn;
    }
    return 0;
}

/* The last block a ray looked up, so a walk through an empty block costs no lookups. */
typedef struct block_cache { int key[3]; uint32_t b; } block_cache;

static uint32_t count_at(const reference *R, const int c[3], block_cache *bc)
{
    int k[3] = {fs_grid_floordiv(c[0]), fs_grid_floordiv(c[1]), fs_grid_floordiv(c[2])};
    if (k[0] != bc->key[0] || k[1] != bc->key[1] || k[2] != bc->key[2]) {
        memcpy(bc->key, k, sizeof k);
        bc->b = fs_grid_block(R->g, k[0], k[1], k[2]);
    }
    if (bc->b == FS_GRID_NONE) return 0;
    int l = ((c[2] - k[2] * FS_GRID_B) * FS_GRID_B + (c[1] - k[1] * FS_GRID_B)) * FS_GRID_B + (c[0] - k[0] * FS_GRID_B);
    return R->count27[(size_t)bc->b * FS_GRID_B3 + l];
}

/* Casts one ray from o along unit d through the grid. */
static void cast(const reference *R, const float o[3], const float d[3], near_particle *buf, ray_result *res)
{
    const fs_grid *g = R->g;
    memset(res, 0, sizeof *res);
    float te = 0, tx = INFINITY; /* start at the eye: the reference is not clipped */
    for (int a = 0; a < 3; a++) {
        float lo = g->origin[a], hi = g->origin[a] + g->cell * R->dim[a];
        if (d[a] == 0) {
            if (o[a] < lo || o[a] > hi) return;
            continue;
        }
        float u = (lo - o[a]) / d[a], v = (hi - o[a]) / d[a];
        if (u > v) { float w = u; u = v; v = w; }
        te = fmaxf(te, u);
        tx = fminf(tx, v);
    }
    if (!(te < tx)) return;
    int c[3], step[3];
    float tmax[3], tdelta[3];
    for (int a = 0; a < 3; a++) {
        c[a] = fs_grid_clampi(fs_grid_coord(g, a, o[a] + te * d[a]), R->dim[a] - 1);
        if (d[a] > 0) {
            step[a] = 1;
            tmax[a] = (g->origin[a] + (c[a] + 1) * g->cell - o[a]) / d[a];
            tdelta[a] = g->cell / d[a];
        } else if (d[a] < 0) {
            step[a] = -1;
            tmax[a] = (g->origin[a] + c[a] * g->cell - o[a]) / d[a];
            tdelta[a] = -g->cell / d[a];
        } else {
            step[a] = 0;
            tmax[a] = tdelta[a] = INFINITY;
        }
    }
    march m = {0, 0, 0, 0, -R->f.iso, 0, R->step_min};
    block_cache cache = {{INT32_MIN, 0, 0}, FS_GRID_NONE};
    float t = te;
    for (;;) {
        float t_out = fminf(fminf(tmax[0], tmax[1]), fminf(tmax[2], tx));
        if (t_out < t) t_out = t;
        uint32_t cnt = count_at(R, c, &cache);
        stretch S = {R, buf, 0, {d[0], d[1], d[2]}};
        float o_loc[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
        if (cnt && t_out > t) S.n = gather(R, c, o_loc, d, t_out - t, buf);
        if (S.n) {
            if (march_stretch(&S, &m, t, t_out - t, R->lip_unit * cnt, res)) return;
        } else if (t_out > t) {
            /* phi = 0 on this whole stretch (it cannot be inside: phi is continuous). */
            if (m.inside && m.counting) res->thick += t - m.t_enter;
            m.inside = m.counting = 0;
            m.g = -R->f.iso;
            m.started = 1;
        }
        if (t_out >= tx) break;
        int a = tmax[0] < tmax[1] ? (tmax[0] < tmax[2] ? 0 : 2) : (tmax[1] < tmax[2] ? 1 : 2);
        c[a] += step[a];
        if (c[a] < 0 || c[a] >= R->dim[a]) break;
        tmax[a] += tdelta[a];
        t = t_out;
    }
    if (m.inside && m.counting) res->thick += tx - m.t_enter; /* left the grid inside */
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    reference *R = self;
    if (!R->g || !R->count27) return fs_fail(FS_ERR_RUNTIME, "reference: render before upload");
    if (out->w != cam->width || out->h != cam->height)
        return fs_fail(FS_ERR_RUNTIME, "reference: G-buffer %dx%d does not match the camera %dx%d", out->w, out->h,
                       cam->width, cam->height);
    double t0 = fs_now_ms();
    int nth = omp_get_max_threads();
    size_t per = R->max27 ? R->max27 : 1;
    near_particle *bufs = malloc((size_t)nth * per * sizeof *bufs);
    if (!bufs) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %d ray buffers", nth);
    float right[3], up[3], fwd[3];
    fs_camera_basis(cam, right, up, fwd);
    fs_gbuffer_clear(out);
#pragma omp parallel num_threads(nth)
    {
        near_particle *buf = bufs + (size_t)omp_get_thread_num() * per;
#pragma omp for schedule(dynamic, 1)
        for (int py = 0; py < cam->height; py++)
            for (int px = 0; px < cam->width; px++) {
                float d[3];
                ray_result res;
                fs_camera_ray(cam, px + 0.5f, py + 0.5f, d);
                cast(R, cam->eye, d, buf, &res);
                size_t id = (size_t)py * cam->width + px;
                out->thickness[id] = res.thick;
                if (!res.hit) continue;
                float nv[3], dv[3];
                fs_camera_to_view_dir(cam, res.n, nv);
                fs_camera_to_view_dir(cam, d, dv);
                float s = nv[0] * dv[0] + nv[1] * dv[1] + nv[2] * dv[2] > 0 ? -1.0f : 1.0f; /* face the camera */
                for (int a = 0; a < 3; a++) out->normal[3 * id + a] = s * nv[a];
                out->depth[id] = res.t * (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]);
                out->coverage[id] = 1.0f;
            }
    }
    free(bufs);
    if (st) fs_stages_add(st, "march", fs_now_ms() - t0);
    return FS_OK;
}

const fs_method fs_method_reference = {
    .name = "reference",
    .description = "exact CPU ray caster of the SPH iso-surface (safe steps, bisection, analytic normals)",
    .paper = "",
    .needs_gl = 0,
    .params = params,
    .nparams = (int)(sizeof params / sizeof *params),
    .params_size = sizeof(reference_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
};
