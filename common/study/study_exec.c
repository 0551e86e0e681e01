/* The study's executor (study.h): every work item, frame by frame. */
#include "study.h"
#include "analytic.h"
#include "fs_error.h"
#include "gbuffer_cache.h"
#include "frame_source.h"
#include "obstacle_mask.h"
#include "shading.h"
#include "study_temporal.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What the executor holds: one frame, each view's current and previous
 * G-buffer, the open runs. */
typedef struct exec {
    fs_study *s;
    const fs_study_io *io;
    const fs_gl_context *ctx;
    fs_particles p; /* frame f (frame 0: the study's frame0) */
    fs_grid g;
    int have_frame, have_grid;
    fs_run *ref_run[FS_STUDY_MAX_REFS], *run[FS_STUDY_MAX_ENTRIES];
    fs_run_image ref_cur[FS_STUDY_MAX_REFS], ref_prev; /* ref_prev: the first reference's frame before */
    fs_run_image prev[FS_STUDY_MAX_ENTRIES];
    int prev_frame[FS_STUDY_MAX_ENTRIES], ref_prev_frame;
    fs_study_temporal_sums ts[FS_STUDY_MAX_ENTRIES], ref_ts;
} exec;

static fs_item_where where(const exec *x, int is_ref, int index, int f)
{
    return fs_study_item_where(x->s, x->io, is_ref, index, f);
}

static void done(const exec *x, const char *label, int f)
{
    if (x->io->done) x->io->done(x->io->user, x->s, label, f);
}

static void note(const exec *x, const char *fmt, const char *a, int b, int c)
{
    char text[512];
    snprintf(text, sizeof text, fmt, a, b, c);
    if (x->io->note) x->io->note(x->io->user, text);
}

/* The view is the first frame's (kept in the study) when it is that frame's. */
static void view_free(fs_run_image *v, const fs_run_image *first)
{
    if (v->rgba != first->rgba || v->g.depth != first->g.depth) fs_run_image_free(v);
    memset(v, 0, sizeof *v);
}

/* 1 when some item of frame f is rendered here (needs the particles). */
static int frame_needed(const exec *x, int f)
{
    for (int k = 0; k < x->s->nrefs; k++)
        if (where(x, 1, k, f) == FS_ITEM_RENDER) return 1;
    for (int i = 0; i < x->s->nentries; i++)
        if (where(x, 0, i, f) == FS_ITEM_RENDER) return 1;
    return 0;
}

/* Frame f's particles and neighbour grid, when any item of it renders here. */
static int load_frame(exec *x, int f)
{
    fs_study *s = x->s;
    if (!frame_needed(x, f)) return FS_OK;
    int rc = FS_OK;
    if (f > 0 && s->given && !(rc = fs_particles_validate(&s->given[f], "particles"))) {
        x->p = s->given[f]; /* borrowed: the struct is ours, the arrays the caller's */
        fs_particles_bounds(&x->p);
    } else if (f > 0) rc = fs_scene_load_frame(&s->scene, fs_study_frame(s, f), &x->p);
    x->have_frame = !rc;
    if (!rc) rc = fs_grid_build(&x->g, f == 0 ? &s->frame0 : &x->p, fs_scene_field(&s->scene).H);
    x->have_grid = !rc;
    return rc;
}

static const fs_particles *frame_particles(const exec *x, int f) { return f == 0 ? &x->s->frame0 : &x->p; }

static void unload_frame(exec *x, int f)
{
    if (x->have_frame && f > 0 && !x->s->given) fs_particles_free(&x->p);
    if (x->have_grid) fs_grid_free(&x->g);
    x->have_frame = x->have_grid = 0;
}

/* The analytic reference of frame f: the ideal shape's exact G-buffer. */
static int render_analytic(exec *x, int f, fs_run_image *v, fs_stages *st)
{
    fs_study *s = x->s;
    double t0 = fs_now_ms();
    int rc = fs_gbuffer_alloc(&v->g, s->scene.camera.width, s->scene.camera.height);
    if (!rc && !(v->rgba = malloc((size_t)v->g.w * v->g.h * 4 * sizeof(float))))
        rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc) rc = fs_synthetic_analytic(&s->scene, fs_study_frame(s, f), &s->scene.camera, &v->g);
    if (!rc) fs_shade(&s->scene, &s->scene.camera, &v->g, fs_scene_floor(&s->scene, &x->g), v->rgba);
    if (!rc) fs_stages_add(st, "analytic", fs_now_ms() - t0);
    return rc;
}

/* A reference rendered without a cache: once, then its counting render. */
static int render_reference(exec *x, int k, int f, fs_run_image *v, fs_stages *st, fs_study_made *made)
{
    fs_study *s = x->s;
    fs_run *run = x->ref_run[k];
    const fs_particles *p = frame_particles(x, f);
    if (x->io->ref_view) return x->io->ref_view(x->io->user, s, k, f, run, p, &x->g, v, st, made);
    int rc = fs_study_render_once(run, &s->scene, p, &x->g, v, st);
    if (rc || !s->counters) return rc;
    fs_run_image cv = {0}; /* between the timed spans: no stage of st */
    rc = fs_run_count(fs_run_method(run), &s->scene, fs_run_values(run), NULL, p, &x->g, &s->scene.camera, &cv,
                      &made->counts);
    fs_run_image_free(&cv);
    return rc;
}

/* Reference k's view of frame f into v (empty when another shard's). */
static int ref_frame(exec *x, int k, int f, fs_run_image *v)
{
    fs_study *s = x->s;
    fs_study_ref *ref = &s->refs[k];
    fs_item_where w = where(x, 1, k, f);
    int rc = FS_OK, got = 0;
    if (w == FS_ITEM_SKIP) return FS_OK;
    if (w == FS_ITEM_LOAD) {
        rc = x->io->load ? x->io->load(x->io->user, s, 1, k, f, NULL, v, &got) : FS_OK;
        if (!rc && !got) rc = fs_fail(FS_ERR_RUNTIME, "%s, frame %d: not loaded", ref->spec, fs_study_frame(s, f));
        if (!rc) done(x, ref->spec, f);
        return rc;
    }
    fs_stages st = {0};
    if (!ref->analytic && !x->ref_run[k]) rc = fs_run_open(&x->ref_run[k], ref->v.m, &s->scene, ref->v.params, NULL);
    if (!rc) rc = ref->analytic ? render_analytic(x, f, v, &st) : render_reference(x, k, f, v, &st, &ref->made[f]);
    if (rc) return rc;
    ref->hits += ref->made[f].hit;
    if (f == 0) ref->stages = st;
    if (x->io->store) {
        fs_provenance prov = s->prov;
        rc = x->io->store(x->io->user, s, 1, k, f, v, &prov);
    }
    if (!rc) done(x, ref->spec, f);
    return rc;
}

/* An entry's metrics of frame f against every reference's view of it. */
static int entry_metrics(exec *x, fs_study_entry *e, int f, const fs_run_image *cur)
{
    fs_study *s = x->s;
    int rc = FS_OK;
    for (int k = 0; k < s->nrefs && !rc; k++)
        rc = fs_metrics_compute_in_scene(&s->scene, &s->scene.camera, &cur->g, cur->rgba, &x->ref_cur[k].g,
                                         x->ref_cur[k].rgba, &e->metrics[k * s->nframes + f]);
    return rc;
}

/* Entry i rendered on frame f: one upload, the timed renders, shading; or, when
 * io->load supplies the item (--resume), loaded (*stored = 1: no files to write). */
static int render_entry(exec *x, int i, int f, fs_run_image *cur, fs_provenance *prov, int *stored)
{
    fs_study *s = x->s;
    fs_study_entry *e = &s->entries[i];
    int rc = FS_OK;
    if (!x->run[i]) {
        rc = fs_run_open(&x->run[i], e->v.m, &s->scene, e->v.params, e->v.m->needs_gl ? x->ctx : NULL);
        if (rc) return rc;
        snprintf(e->renderer, sizeof e->renderer, "%s", fs_run_renderer(x->run[i]));
    }
    fs_run_provenance(x->run[i], &s->prov, fs_study_frame(s, f), prov);
    if (x->io->load && (rc = x->io->load(x->io->user, s, 0, i, f, prov, cur, stored))) return rc;
    if (*stored) return FS_OK;
    rc = fs_run_upload(x->run[i], frame_particles(x, f), &x->g, NULL);
    if (!rc)
        rc = fs_study_time_renders(x->run[i], &s->scene.camera, cur, s->repeat, f == 0 ? e->runs : NULL,
                                   &e->frame_ms[f]);
    if (!rc && f == 0) e->nruns = s->repeat;
    if (!rc) rc = fs_run_shade(x->run[i], &s->scene.camera, cur, FS_APPEARANCE_SHARED, NULL);
    return rc;
}

/* With counters, after the timed renders: a counting render on the same inputs
 * (docs/DESIGN.md, "Work counters"). */
static int count_entry(exec *x, int i, int f)
{
    fs_study *s = x->s;
    fs_study_entry *e = &s->entries[i];
    fs_run_image v = {0};
    note(x, "counting %s, frame %d/%d", e->label, f + 1, s->nframes);
    int rc = fs_run_count(e->v.m, &s->scene, e->v.params, x->ctx, frame_particles(x, f), &x->g, &s->scene.camera, &v,
                          &e->counts[f]);
    /* the counts describe the timed render only when it drew the same G-buffer */
    if (!rc && f == 0 && !fs_digest_equal(fs_gcache_data_hash(&v.g), fs_gcache_data_hash(&e->first.g)))
        note(x, "%s: the counting render's G-buffer differs from the timed render's", e->label, 0, 0);
    fs_run_image_free(&v);
    return rc;
}

/* The first reference's views of frames f-1 and f, when both are at hand. */
static int ref_pair(const exec *x, int f)
{
    return x->s->measure && x->ref_prev.g.w && x->ref_prev_frame == f - 1 && x->ref_cur[0].g.w;
}

/* Entry i's view of frame f becomes its previous one (the first frame's is kept). */
static void keep_view(exec *x, int i, int f, fs_run_image *cur)
{
    fs_study_entry *e = &x->s->entries[i];
    if (cur->g.w && f > 0 && x->prev_frame[i] == f - 1) {
        const fs_gbuffer *ra = ref_pair(x, f) ? &x->ref_prev.g : NULL;
        fs_study_temporal_add(&x->s->scene, &x->prev[i].g, &cur->g, ra, ra ? &x->ref_cur[0].g : NULL, &x->ts[i]);
    }
    view_free(&x->prev[i], &e->first);
    if (f == 0) e->first = *cur;
    x->prev[i] = *cur;
    x->prev_frame[i] = f;
}

static int entry_frame(exec *x, int i, int f)
{
    fs_study *s = x->s;
    fs_study_entry *e = &s->entries[i];
    fs_item_where w = where(x, 0, i, f);
    if (w == FS_ITEM_SKIP) return FS_OK;
    fs_run_image cur = {0};
    fs_provenance prov;
    int stored = w == FS_ITEM_LOAD, rc;
    rc = stored ? (x->io->load ? x->io->load(x->io->user, s, 0, i, f, NULL, &cur, &stored) : FS_OK)
                : render_entry(x, i, f, &cur, &prov, &stored);
    if (!rc && w == FS_ITEM_LOAD && !stored)
        rc = fs_fail(FS_ERR_RUNTIME, "%s, frame %d: not loaded", e->label, fs_study_frame(s, f));
    if (!rc && s->measure) rc = entry_metrics(x, e, f, &cur);
    if (!rc && !stored && x->io->store) rc = x->io->store(x->io->user, s, 0, i, f, &cur, &prov);
    if (rc) {
        fs_run_image_free(&cur);
        return rc;
    }
    done(x, e->label, f);
    keep_view(x, i, f, &cur);
    return s->counters && w == FS_ITEM_RENDER ? count_entry(x, i, f) : FS_OK;
}

/* An imported G-buffer: metrics of its one frame against every reference. */
static int measure_import(exec *x, fs_study_entry *e)
{
    e->frame_ms[0] = NAN;
    e->temporal_deg = e->temporal_err_deg = e->temporal_err_depth_r = NAN;
    return x->s->measure ? entry_metrics(x, e, 0, &e->first) : FS_OK;
}

/* Frame f: the references, then every entry against them. */
static int run_frame(exec *x, int f)
{
    fs_study *s = x->s;
    int rc = load_frame(x, f);
    for (int k = 0; k < s->nrefs && !rc; k++) rc = ref_frame(x, k, f, &x->ref_cur[k]);
    if (!rc && f > 0 && ref_pair(x, f))
        fs_study_temporal_add(&s->scene, &x->ref_prev.g, &x->ref_cur[0].g, NULL, NULL, &x->ref_ts);
    for (int i = 0; i < s->nentries && !rc; i++)
        rc = s->entries[i].imported ? (f == 0 ? measure_import(x, &s->entries[i]) : FS_OK) : entry_frame(x, i, f);
    unload_frame(x, f);
    for (int k = 0; k < s->nrefs; k++) {
        if (f == 0) s->refs[k].first = x->ref_cur[k]; /* kept for the panel and heatmaps */
        if (k == 0) {
            view_free(&x->ref_prev, &s->refs[0].first);
            x->ref_prev = x->ref_cur[0];
            x->ref_prev_frame = x->ref_cur[0].g.w ? f : -2;
        } else view_free(&x->ref_cur[k], &s->refs[k].first);
        memset(&x->ref_cur[k], 0, sizeof x->ref_cur[k]);
    }
    return rc;
}

static void finish(exec *x)
{
    fs_study *s = x->s;
    for (int i = 0; i < s->nentries; i++) {
        fs_study_entry *e = &s->entries[i];
        if (!e->imported)
            fs_study_temporal_means(&x->ts[i], &e->temporal_deg, &e->temporal_err_deg, &e->temporal_err_depth_r);
        view_free(&x->prev[i], &e->first);
        fs_run_close(x->run[i]);
    }
    double unused;
    fs_study_temporal_means(&x->ref_ts, &s->ref_temporal_deg, &unused, &unused);
    view_free(&x->ref_prev, s->nrefs ? &s->refs[0].first : &x->ref_prev);
    for (int k = 0; k < s->nrefs; k++) {
        view_free(&x->ref_cur[k], &s->refs[k].first);
        fs_run_close(x->ref_run[k]);
    }
}

int fs_study_execute(fs_study *s, const fs_study_io *io, const fs_gl_context *ctx)
{
    static const fs_study_io no_io;
    exec *x = calloc(1, sizeof *x);
    if (!x) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    x->s = s, x->io = io ? io : &no_io, x->ctx = ctx;
    x->ref_prev_frame = -2;
    for (int i = 0; i < FS_STUDY_MAX_ENTRIES; i++) x->prev_frame[i] = -2;
    int rc = FS_OK;
    for (int f = 0; f < s->nframes && !rc; f++) rc = run_frame(x, f);
    finish(x);
    free(x);
    return rc;
}
