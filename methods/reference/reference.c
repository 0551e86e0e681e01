/* reference: exact CPU ray caster of the SPH iso-surface phi = iso (docs/DESIGN.md,
 * References). Per pixel the ray walks the neighbour grid cell by cell (3D-DDA);
 * empty cells are skipped, inside a non-empty cell the ray advances by steps
 * proven not to cross the iso-surface, a sign change is bisected to 1e-4 r and
 * the normal is the analytic -grad phi. See README.md for why the steps are safe.
 * field=anisotropic: Yu & Turk's kernel W(|A_j^-1 (x - c_j)|, H) / det A_j with
 * the centres c_j and stretches A_j of common/field/anisotropy.c. */
#include "reference.h"
#include "zhu_bridson.h"
#include "aniso_params.h"
#include "fs_error.h"
#include "method.h"
#include "progress.h"
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

typedef enum { REF_INTERIOR_AUTO, REF_INTERIOR_ON, REF_INTERIOR_OFF, REF_INTERIOR_DEMAND } ref_interior;

typedef struct reference_params {
    double step_min;
    bool thickness;
    int max_layers;
    bool accel;
    ref_interior interior;
    fs_field_choice field;
    int supersample;
    fs_aniso_param_values aniso;
    double zb_radius;
} reference_params;

#define FIELD(f) FS_PARAM_FIELD(reference_params, f)
static const fs_param_def params[] = {
    {FIELD(step_min), FS_PARAM_FLOAT, 0.02, 1e-4, 1.0, NULL,
     "smallest march step, multiples of r; crossing intervals shorter than this can be missed"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL, "march past the first hit and sum every inside interval (on/off)"},
    {FIELD(max_layers), FS_PARAM_INT, 64, 1, 1e6, NULL, "most inside intervals summed into the thickness"},
    {FIELD(accel), FS_PARAM_BOOL, 1, 0, 1, NULL,
     "sub-cell bounds, gathered arrays and vectorised sums (on); off: the plain march, for comparison"},
    {FIELD(interior), FS_PARAM_ENUM, 0, 0, 3, "auto|on|off|demand",
     "accel, thickness on: fine interior proofs; on: every cell's up front, demand: a cell's when a ray first enters "
     "it inside; auto: as the rays per cell pay for them"},
    {FIELD(field), FS_PARAM_ENUM, 0, 0, 2, "isotropic|anisotropic|zhu_bridson",
     "SPH kernel, Yu & Turk's anisotropic kernel, or Zhu & Bridson's |x - xbar| - r (own march, accel ignored)"},
    {FIELD(supersample), FS_PARAM_INT, 1, 1, FS_REF_MAX_SUPERSAMPLE, NULL,
     "N x N rays per pixel, depth, normal, coverage and thickness averaged (against moire where r is about a pixel)"},
    FS_ANISO_PARAM_DEFS(reference_params),
    {FIELD(zb_radius), FS_PARAM_FLOAT, FS_ZB_RADIUS, 1.0, 40.0, NULL,
     "zhu_bridson: kernel radius R, multiples of r (the paper's twice the particle spacing: 4)"},
};
#undef FIELD

static void destroy(void *self)
{
    reference *R = self;
    if (!R) return;
    free(R->count27);
    free(R->sx);
    free(R->sy);
    free(R->sz);
    fs_ref_bounds_free(R);
    fs_ref_interior_free(R);
    fs_aniso_kernels_free(&R->ak);
    if (R->zgrid_own) fs_grid_free(&R->zgrid);
    free(R);
}

static void *create(const fs_method_setup *setup)
{
    const fs_field *f = &setup->field;
    if (fs_method_check_field("reference", f)) return NULL;
    reference_params p;
    if (fs_method_params_copy("reference", setup, &p, sizeof p)) return NULL;
    reference *R = calloc(1, sizeof *R);
    if (!R) {
        fs_fail(FS_ERR_RUNTIME, "reference: out of memory");
        return NULL;
    }
    R->f = *f;
    R->aniso = p.field == FS_FIELD_ANISOTROPIC;
    R->zb = p.field == FS_FIELD_ZHU_BRIDSON;
    R->zb_radius = p.zb_radius * f->r;
    fs_aniso_params_set(&R->ap, &p.aniso, f->kernel, f->r);
    R->reach = R->zb ? (float)R->zb_radius : f->H;
    R->step_min = (float)p.step_min * f->r;
    R->thickness = p.thickness;
    R->accel = p.accel;
    R->interior = p.interior;
    R->max_layers = p.max_layers;
    R->supersample = p.supersample;
    R->lip_unit = f->volume * fs_kernel_max_dw(f->kernel, f->H);
    return R;
}

/* field=anisotropic: the kernels of common/field/aniso_kernels.c, on a grid of
 * their centres with cells of at least H times the largest axis (so the
 * 27-cell argument of upload still holds), and the Lipschitz unit
 * V max|W'| max_j (1 / (det A_j a_min,j)): the gradient of W(|A^-1 y|)/det A is
 * W'(|u|) A^-1 u / (|u| det A), at most max|W'| / (det A a_min). */
static int upload_aniso(reference *R, const fs_particles *p, const fs_grid *g)
{
    fs_aniso_kernels_free(&R->ak);
    R->inv = R->wscale = NULL;
    int rc = fs_aniso_kernels_build(&R->ak, p, g, &R->ap, R->f.H);
    if (rc) return rc;
    R->inv = R->ak.inv;
    R->wscale = R->ak.wscale;
    R->reach = R->ak.reach;
    R->lip_unit = R->f.volume * fs_kernel_max_dw(R->f.kernel, R->f.H) * R->ak.lip;
    return FS_OK;
}

/* count27 of every stored cell slot, and its maximum. With cell >= H every
 * particle within H of a point of cell c lies in the 27 cells around c: that
 * is what makes the per-cell Lipschitz bound valid. */
static int count_neighbours(reference *R, const fs_grid *g)
{
    free(R->count27);
    R->count27 = malloc((g->ncells ? g->ncells : 1) * sizeof *R->count27);
    if (!R->count27) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %zu cells", g->ncells);
    uint32_t mx = 0;
    size_t nn = 0;
    long nb = (long)g->nblocks;
#pragma omp parallel for reduction(max : mx) reduction(+ : nn) schedule(static)
    for (long b = 0; b < nb; b++)
        for (int l = 0; l < FS_GRID_B3; l++) {
            int lo[3], hi[3];
            lo[0] = g->bkey[3 * b] * FS_GRID_B + l % FS_GRID_B - 1;
            lo[1] = g->bkey[3 * b + 1] * FS_GRID_B + l / FS_GRID_B % FS_GRID_B - 1;
            lo[2] = g->bkey[3 * b + 2] * FS_GRID_B + l / (FS_GRID_B * FS_GRID_B) - 1;
            for (int a = 0; a < 3; a++) hi[a] = lo[a] + 2;
            uint32_t runs[FS_GRID_MAX_RUNS][2], c = 0;
            int nr = fs_grid_box_runs(g, lo, hi, runs);
            for (int r = 0; r < nr; r++) c += runs[r][1] - runs[r][0];
            R->count27[(size_t)b * FS_GRID_B3 + l] = c;
            if (c > mx) mx = c;
            nn += c > 0;
        }
    R->max27 = mx;
    R->nnear = nn;
    return FS_OK;
}

/* accel: the sorted positions as structure of arrays. */
static int sorted_soa(reference *R, const fs_grid *g)
{
    free(R->sx);
    free(R->sy);
    free(R->sz);
    size_t n = g->n ? g->n : 1;
    R->sx = malloc(n * sizeof *R->sx);
    R->sy = malloc(n * sizeof *R->sy);
    R->sz = malloc(n * sizeof *R->sz);
    if (!R->sx || !R->sy || !R->sz) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %zu particles", n);
    long nl = (long)g->n;
#pragma omp parallel for schedule(static)
    for (long s = 0; s < nl; s++) {
        R->sx[s] = g->pos4[4 * s];
        R->sy[s] = g->pos4[4 * s + 1];
        R->sz[s] = g->pos4[4 * s + 2];
    }
    return FS_OK;
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    reference *R = self;
    R->g = NULL;
    for (int a = 0; a < 3; a++) R->centre[a] = 0.5f * (g->bulk_lo[a] + g->bulk_hi[a]);
    if (R->aniso) {
        if (g->n != p->n)
            return fs_fail(FS_ERR_RUNTIME, "reference: grid holds %zu particles, the set %zu", g->n, p->n);
        int rc = upload_aniso(R, p, g);
        if (rc) return rc;
        g = &R->ak.grid;
    }
    if (R->zb) { /* its own reach R: a grid of cell >= R (the given one when it is) */
        int rc = fs_grid_fit(g, p, R->reach, &R->zgrid, &R->zgrid_own, &g);
        if (rc) return rc;
    }
    if (!(g->cell >= R->reach))
        return fs_fail(FS_ERR_INPUT, "reference: grid cell %g is smaller than the kernel support %g", g->cell,
                       R->reach);
    if (g->n != p->n) return fs_fail(FS_ERR_RUNTIME, "reference: grid holds %zu particles, the set %zu", g->n, p->n);
    int rc = count_neighbours(R, g);
    if (!rc) rc = sorted_soa(R, g);
    if (rc) return rc;
    R->g = g;
    fs_ref_bounds_free(R);
    fs_ref_interior_free(R);
    R->sub = 0;
    R->prepared = 0; /* the bounds and proofs: at the first render, when they pay (prepare) */
    return FS_OK;
}

/* Pixels are cast in tiles of FS_REF_TILE^2 under dynamic scheduling: rays of
 * a tile walk the same cells, and a tile is enough work to hide the schedule. */
#define FS_REF_TILE 16

/* One ray's answer in view space: whether it hit, and there its eye depth, its
 * normal facing the camera and the thickness along it. */
typedef struct ray_sample {
    int hit;
    float depth, n[3], thick;
} ray_sample;

/* The ray through pixel position (fx, fy); its work added to w (w[0] before and
 * with the first hit, w[1] after it, w[2] its interior proofs). */
static void cast(const reference *R, const fs_camera_rays *cam, float fx, float fy, void *buf, ray_work w[FS_REF_NWORK],
                 ray_sample *out)
{
    float d[3];
    ray_result res;
    fs_camera_rays_dir(cam, fx, fy, d);
    if (R->zb) fs_ref_cast_zb(R, cam->eye, d, buf, &res);
    else if (R->accel) fs_ref_cast_fast(R, cam->eye, d, buf, &res);
    else fs_ref_cast_plain(R, cam->eye, d, buf, &res);
    for (int k = 0; k < FS_REF_NWORK; k++) fs_ref_work_add(&w[k], &res.w[k]);
    out->hit = res.hit;
    out->thick = res.thick;
    if (!res.hit) return;
    float nv[3], dv[3];
    fs_camera_rays_to_view(cam, res.n, nv);
    fs_camera_rays_to_view(cam, d, dv);
    float s = nv[0] * dv[0] + nv[1] * dv[1] + nv[2] * dv[2] > 0 ? -1.0f : 1.0f; /* face the camera */
    for (int a = 0; a < 3; a++) out->n[a] = s * nv[a];
    out->depth = res.t * (d[0] * cam->fwd[0] + d[1] * cam->fwd[1] + d[2] * cam->fwd[2]);
}

/* supersample = N > 1: N x N rays through the centres of an N x N grid over the
 * pixel. Coverage is the share that hit, thickness the mean over all, depth the
 * mean over the hits and the normal their sum, renormalised. */
static void shade_supersampled(const reference *R, const fs_camera_rays *cam, int px, int py, void *buf,
                               fs_gbuffer *out, ray_work w[FS_REF_NWORK])
{
    int n = R->supersample, hits = 0;
    double depth = 0, thick = 0, sum[3] = {0, 0, 0};
    float first[3] = {0, 0, 1};
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            ray_sample s;
            cast(R, cam, px + (i + 0.5f) / n, py + (j + 0.5f) / n, buf, w, &s);
            thick += s.thick;
            if (!s.hit) continue;
            if (!hits++) memcpy(first, s.n, sizeof first);
            depth += s.depth;
            for (int a = 0; a < 3; a++) sum[a] += s.n[a];
        }
    size_t id = (size_t)py * out->w + px;
    out->thickness[id] = (float)(thick / (n * n));
    if (!hits) return;
    double len = sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    for (int a = 0; a < 3; a++) out->normal[3 * id + a] = len > 1e-6 * hits ? (float)(sum[a] / len) : first[a];
    out->depth[id] = (float)(depth / hits);
    out->coverage[id] = (float)hits / (float)(n * n);
}

/* One pixel into the G-buffer; its work added to w. supersample = 1 casts the
 * pixel centre alone and writes its answer as it is. */
static void shade_pixel(const reference *R, const fs_camera_rays *cam, int px, int py, void *buf, fs_gbuffer *out,
                        ray_work w[FS_REF_NWORK])
{
    if (R->supersample > 1) {
        shade_supersampled(R, cam, px, py, buf, out, w);
        return;
    }
    ray_sample s;
    cast(R, cam, px + 0.5f, py + 0.5f, buf, w, &s);
    size_t id = (size_t)py * out->w + px;
    out->thickness[id] = s.thick;
    if (!s.hit) return;
    for (int a = 0; a < 3; a++) out->normal[3 * id + a] = s.n[a];
    out->depth[id] = s.depth;
    out->coverage[id] = 1.0f;
}

/* r in pixels at the depth of the particles' bulk box centre (the grid's bulk
 * box: far strays left out), where a pixel spans 2 z tan(fovy / 2) / height
 * scene units; 0 when the centre is not in front of the camera. */
static double radius_px(const reference *R, const fs_camera *cam, const float fwd[3])
{
    double z = 0;
    for (int a = 0; a < 3; a++) z += (R->centre[a] - cam->eye[a]) * fwd[a];
    if (!(z > 0)) return 0;
    return R->f.r * cam->height / (2 * z * tan(cam->fovy_deg * M_PI / 360));
}

/* Once per run: a note when r is under FS_REF_SMALL_R_PX pixels, where the
 * surface's bumps (a particle's width) alias into moire that dominates the
 * normals; not when supersample = N rays a pixel side sample r at N px * r. */
static void note_small_radius(reference *R, const fs_camera *cam, const float fwd[3])
{
    double px = radius_px(R, cam, fwd);
    if (R->noted_small || !(px > 0 && px * R->supersample < FS_REF_SMALL_R_PX)) return;
    R->noted_small = 1;
    int n = (int)ceil(FS_REF_SMALL_R_PX / px);
    if (n > FS_REF_MAX_SUPERSAMPLE) n = FS_REF_MAX_SUPERSAMPLE;
    fs_note("reference: r is %.2f px at the particles' centre (under %d px, the surface's bumps alias into moire): "
            "set reference.supersample=%d (N x N rays a pixel) or a larger image",
            px, FS_REF_SMALL_R_PX, n);
}

/* Rays per near cell at which the coarse sub-cell bounds pay: a cell's take
 * about as long to build as ~10 gathers and marches of its stretch. */
#define FS_REF_BOUNDS_VISITS 10.0

/* Rays per interior cell at which the fine interior proofs pay for themselves:
 * proving a cell costs about as much as marching its inside for ~100 rays
 * (measured on the 1M-particle box, results/bench/speed.csv, interior=on/off). */
#define FS_REF_VISITS 100.0

/* The rays that cross each of n cells of the fluid, about: each of the W x H rays
 * crosses about cbrt(n) of them. */
static double rays_per_cell(size_t n, const fs_camera *cam)
{
    return n ? (double)cam->width * cam->height * cbrt((double)n) / (double)n : 0;
}

/* The cells an interior proof can help (FS_REF_EDGE_IN), after every cell's bounds. */
static size_t edge_in_cells(const reference *R)
{
    size_t n = 0;
    for (size_t c = 0; c < R->g->ncells; c++) n += R->cell_cls[c] == FS_REF_EDGE_IN;
    return n;
}

/* How the fine interior proofs are made for this render (after the bounds): none
 * (REF_INTERIOR_OFF), every cell's up front (ON) or on demand (DEMAND). auto: up
 * front when each of the W x H rays crosses about cbrt(n) of the n cells a proof
 * can help, at least FS_REF_VISITS rays a cell. auto does not choose demand: on
 * the frames measured it made nearly every proof on makes, and was no faster
 * (README.md, `interior`). */
static ref_interior want_interior(const reference *R, const fs_camera *cam)
{
    if (!R->thickness || !R->sub) return REF_INTERIOR_OFF;
    if (R->interior != REF_INTERIOR_AUTO) return (ref_interior)R->interior;
    return rays_per_cell(edge_in_cells(R), cam) >= FS_REF_VISITS ? REF_INTERIOR_ON : REF_INTERIOR_OFF;
}

/* Once per upload, when the image is large enough for them to pay: the coarse
 * sub-cell bounds (stage "bounds") and the fine interior proofs as want_interior
 * says (stage "interior"); with interior=demand both are made by the march, a cell's
 * when a ray first needs it, and so are the bounds with thickness off. A small image
 * marches without. */
static int prepare(reference *R, const fs_camera *cam, fs_stages *st)
{
    if (R->prepared) return FS_OK;
    R->prepared = 1;
    if (!R->accel || R->zb || rays_per_cell(R->nnear, cam) < FS_REF_BOUNDS_VISITS) return FS_OK;
    /* thickness off: a ray stops at its first hit, so only the cells in front of the
     * surface are walked; their bounds are made when a ray first walks them (README.md,
     * step 1) instead of every near cell's up front */
    int demand = !R->thickness || R->interior == REF_INTERIOR_DEMAND;
    double t0 = fs_now_ms();
    int rc = fs_ref_bounds_build(R, demand);
    if (!rc && st && R->sub && !demand) fs_stages_add(st, "bounds", fs_now_ms() - t0);
    ref_interior how = rc ? REF_INTERIOR_OFF : want_interior(R, cam);
    t0 = fs_now_ms();
    if (how != REF_INTERIOR_OFF) rc = fs_ref_interior_build(R, how == REF_INTERIOR_DEMAND);
    if (!rc && st && R->fine && how == REF_INTERIOR_ON) fs_stages_add(st, "interior", fs_now_ms() - t0);
    if (rc) {
        fs_ref_bounds_free(R);
        fs_ref_interior_free(R);
        R->sub = 0;
        R->g = NULL;
    }
    return rc;
}

/* A phase's work into the pending counts (a no-op unless counting). */
static void count_work(const ray_work *w)
{
    fs_count_add(FS_CNT_FIELD_EVALS, w->evals);
    fs_count_add(FS_CNT_NEIGHBOURS, w->nbrs);
    fs_count_add(FS_CNT_MARCH_SAMPLES, w->samples);
    fs_count_add(FS_CNT_CROSSINGS, w->crossings);
    fs_count_add(FS_CNT_CELLS_WALKED, w->cells);
    fs_count_add(FS_CNT_CELLS_MARCHED, w->marched);
    fs_count_add(FS_CNT_CELLS_MARCHED_INSIDE, w->marched_in);
    fs_count_add(FS_CNT_CELLS_PROVEN_INSIDE, w->proven_in);
    fs_count_add(FS_CNT_CELLS_PROVEN_OUTSIDE, w->proven_out);
    fs_count_add(FS_CNT_REFINE_EVALS, w->refine_evals);
    fs_count_add(FS_CNT_INSIDE_EVALS, w->inside_evals);
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    reference *R = self;
    if (!R->g || !R->count27) return fs_fail(FS_ERR_RUNTIME, "reference: render before upload");
    if (out->w != cam->width || out->h != cam->height)
        return fs_fail(FS_ERR_RUNTIME, "reference: G-buffer %dx%d does not match the camera %dx%d", out->w, out->h,
                       cam->width, cam->height);
    int rc = prepare(R, cam, st);
    if (rc) return rc;
    double t0 = fs_now_ms();
    int nth = omp_get_max_threads();
    size_t per = R->zb ? fs_ref_zb_buf_size(R) : R->accel ? fs_ref_fast_buf_size(R) : fs_ref_plain_buf_size(R);
    per = (per + 63) & ~(size_t)63;
    char *bufs = malloc((size_t)nth * per);
    if (!bufs) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %d ray buffers", nth);
    fs_camera_rays rays; /* the basis once, not per ray */
    fs_camera_rays_init(cam, &rays);
    note_small_radius(R, cam, rays.fwd);
    fs_gbuffer_clear(out);
    int tw = (cam->width + FS_REF_TILE - 1) / FS_REF_TILE, th = (cam->height + FS_REF_TILE - 1) / FS_REF_TILE;
    fs_progress_sub_total((long)tw * th);
    ray_work total[FS_REF_NWORK] = {{0}}; /* both phases and the proofs, over the threads */
#pragma omp parallel num_threads(nth)
    {
        void *buf = bufs + (size_t)omp_get_thread_num() * per;
        ray_work w[FS_REF_NWORK] = {{0}}; /* this thread's rays */
#pragma omp for schedule(dynamic, 1)
        for (int tile = 0; tile < tw * th; tile++) {
            int x0 = tile % tw * FS_REF_TILE, y0 = tile / tw * FS_REF_TILE;
            for (int py = y0; py < y0 + FS_REF_TILE && py < cam->height; py++)
                for (int px = x0; px < x0 + FS_REF_TILE && px < cam->width; px++)
                    shade_pixel(R, &rays, px, py, buf, out, w);
            fs_progress_sub(1);
        }
#pragma omp critical(fs_reference_work)
        for (int k = 0; k < FS_REF_NWORK; k++) fs_ref_work_add(&total[k], &w[k]);
    }
    free(bufs);
    /* The march is one timed stage; a counting render splits its counts into the
     * first-hit march ("march") and the thickness march after the first hit
     * ("thickness", a stage of counts only: README.md, "Work counters"). */
    count_work(&total[FS_REF_FIRST]);
    if (st) fs_stages_add(st, "march", fs_now_ms() - t0); /* the bounds are built in upload */
    count_work(&total[FS_REF_AFTER]);
    if (st && fs_counting && R->thickness) fs_stages_add(st, "thickness", 0);
    /* bounds and proofs made on demand: timed in the march, counted apart (stages of counts only) */
    count_work(&total[FS_REF_BOUNDS]);
    if (st && fs_counting && total[FS_REF_BOUNDS].evals) fs_stages_add(st, "bounds", 0);
    count_work(&total[FS_REF_PROOFS]);
    if (st && fs_counting && total[FS_REF_PROOFS].evals) fs_stages_add(st, "interior", 0);
    R->waits += total[FS_REF_BOUNDS].waits + total[FS_REF_PROOFS].waits;
    return FS_OK;
}

const fs_method fs_method_reference = {
    .name = "reference",
    .cost = 10, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "exact CPU ray caster of the SPH iso-surface (safe steps, bisection, analytic normals)",
    .paper = "",
    .needs_gl = 0,
    .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS) | FS_CNT_BIT(FS_CNT_NEIGHBOURS) | FS_CNT_BIT(FS_CNT_MARCH_SAMPLES) |
        FS_CNT_BIT(FS_CNT_CROSSINGS) | FS_CNT_BIT(FS_CNT_CELLS_WALKED) | FS_CNT_BIT(FS_CNT_CELLS_MARCHED) |
        FS_CNT_BIT(FS_CNT_CELLS_MARCHED_INSIDE) | FS_CNT_BIT(FS_CNT_CELLS_PROVEN_INSIDE) |
        FS_CNT_BIT(FS_CNT_CELLS_PROVEN_OUTSIDE) | FS_CNT_BIT(FS_CNT_REFINE_EVALS) | FS_CNT_BIT(FS_CNT_INSIDE_EVALS),
    .params = params,
    .nparams = (int)(sizeof params / sizeof *params),
    .params_size = sizeof(reference_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
};
