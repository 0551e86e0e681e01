/* fluidsurf compare: every method variant on the same particles, camera, light,
 * material and resolution; metrics against references; timings; figures. */
#include "scene_provenance.h"
#include "cli.h"
#include "compare.h"
#include "compare_merge.h"
#include "compare_outdir.h"
#include "compare_resume.h"
#include "compare_shard.h"
#include "compare_temporal.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "obstacle_mask.h"
#include "options.h"
#include "progress.h"
#include "render_output.h"
#include "run.h"
#include "shading.h"
#include "stats.h"
#include "analytic.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* what --help says after the options */
static const char epilogue[] =
    "--set M.P=v1,v2,... sweeps the parameter over the values.\n"
    "Writes DIR/<label>.png|.exr, diff_<label>.png, metrics.csv, timings.csv, panel.png,\n"
    "<label>_own.png for a method with its own appearance (fluidsurf methods says which),\n"
    "report.md (and temporal.csv for a sequence); with --counters also counters.csv.\n"
    "A label is [A-Za-z0-9_-]: the method, then _PARAM-VALUE per swept parameter, '.'\n"
    "written 'p' and '-' 'm' (spheres_radius_scale-0p8); report.md maps each label to its\n"
    "parameters, and metrics.csv has a column per swept parameter after 'variant'.\n"
    "The files written are listed in DIR/fluidsurf-outputs.txt; a DIR holding another\n"
    "run's outputs is refused unless --resume or --force.\n"
    "metrics.csv's last columns (depth_median_r, depth_abs_p50/p95/p99_r,\n"
    "depth_over_1r_frac) measure the depth error itself, not around its mean.\n"
    "Reference G-buffers are cached (--cache DIR, default $XDG_CACHE_HOME/fluidsurf or\n"
    "~/.cache/fluidsurf), keyed by a hash of the particles, field, camera, image size,\n"
    "the reference's parameters and fluidsurf's commit; a hit is named in report.md and\n"
    "timed as the stage 'cache' in timings.csv. Method variants are always rendered.\n";

static void free_view(cmp_view *v) { fs_run_image_free(v); }

static int make_outdir(const char *dir, int *made)
{
    struct stat st;
    if (stat(dir, &st) != 0) {
        if (mkdir(dir, 0755) != 0) return fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", dir, strerror(errno));
        *made = 1;
    } else if (!S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: exists and is not a folder", dir);
    if (access(dir, W_OK) != 0) return fs_fail(FS_ERR_INPUT, "%s: output folder is not writable", dir);
    return FS_OK;
}

/* "reference" | "reference:p=v,q=w" | "analytic" */
static int parse_ref(cmp_run *r, const char *spec)
{
    if (r->nrefs == CMP_MAX_REFS) return fs_fail(FS_ERR_INPUT, "--reference %s: at most %d references", spec, CMP_MAX_REFS);
    cmp_ref *ref = &r->refs[r->nrefs];
    memset(ref, 0, sizeof *ref);
    snprintf(ref->spec, sizeof ref->spec, "%s", spec);
    if (!strcmp(spec, "analytic")) {
        if (!r->scene.synth.shape) return fs_fail(FS_ERR_INPUT, "--reference analytic: needs a synthetic scene");
        ref->analytic = 1;
        snprintf(ref->label, sizeof ref->label, "analytic");
        r->nrefs++;
        return FS_OK;
    }
    const fs_method *m = fs_method_find("reference");
    if (strncmp(spec, "reference", 9) || (spec[9] && spec[9] != ':'))
        return fs_fail(FS_ERR_INPUT, "--reference %s: expected reference, reference:PARAM=V,... or analytic", spec);
    fs_scene s = r->scene;
    snprintf(ref->label, sizeof ref->label, "reference");
    if (spec[9] == ':') {
        char buf[160];
        snprintf(buf, sizeof buf, "%s", spec + 10);
        for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
            char set[200];
            snprintf(set, sizeof set, "reference.%s", tok);
            int rc = fs_scene_add_set(&s, set);
            if (rc) return rc;
            char value[160];
            const char *eq = strchr(tok, '='); /* there is one: fs_scene_add_set checked */
            fs_label_value(eq + 1, value, sizeof value);
            size_t l = strlen(ref->label);
            if (snprintf(ref->label + l, sizeof ref->label - l, "_%.*s-%s", (int)(eq - tok), tok, value) >= (int)(sizeof ref->label - l))
                return fs_fail(FS_ERR_INPUT, "--reference %s: too long", spec);
        }
    }
    int n = fs_sweep_variants(m, &s, NULL, 0, &ref->v, 1);
    if (n < 0) return -n;
    r->nrefs++;
    return FS_OK;
}

static int parse_import(cmp_run *r, const char *spec)
{
    const char *eq = strchr(spec, '=');
    if (!eq || eq == spec || !eq[1] || eq - spec >= 64) return fs_fail(FS_ERR_INPUT, "--import %s: expected NAME=FILE.exr", spec);
    if (r->nentries == CMP_MAX_ENTRIES) return fs_fail(FS_ERR_INPUT, "--import %s: too many entries", spec);
    cmp_entry *e = &r->entries[r->nentries];
    memset(e, 0, sizeof *e);
    snprintf(e->name, sizeof e->name, "%.*s", (int)(eq - spec), spec);
    if (!fs_label_is_safe(e->name)) return fs_fail(FS_ERR_INPUT, "--import %s: NAME may hold only letters, digits, '_' and '-'", spec);
    strcpy(e->label, e->name); /* name is shorter than label */
    snprintf(e->variant, sizeof e->variant, "import");
    e->imported = 1;
    e->file = eq + 1;
    float rr;
    int rc = fs_read_render(eq + 1, &e->first.g, &e->first.rgba, &rr);
    if (rc) return rc;
    if (e->first.g.w != r->scene.camera.width || e->first.g.h != r->scene.camera.height) {
        int w = e->first.g.w, h = e->first.g.h;
        free_view(&e->first);
        return fs_fail(FS_ERR_INPUT, "%s: %dx%d, but the run renders %dx%d", eq + 1, w, h, r->scene.camera.width,
                       r->scene.camera.height);
    }
    snprintf(e->renderer, sizeof e->renderer, "imported");
    r->nentries++;
    return FS_OK;
}

static double since_s(double t0) { return (fs_now_ms() - t0) / 1000.0; }

/* The analytic reference of frame f: the ideal shape's exact G-buffer. */
static int render_analytic(cmp_run *r, int f, const fs_grid *g, cmp_view *v, fs_stages *st)
{
    double t0 = fs_now_ms();
    int rc = fs_gbuffer_alloc(&v->g, r->scene.camera.width, r->scene.camera.height);
    if (!rc && !(v->rgba = malloc((size_t)v->g.w * v->g.h * 4 * sizeof(float)))) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc) rc = fs_synthetic_analytic(&r->scene, r->first_frame + f, &r->scene.camera, &v->g);
    if (!rc) fs_shade(&r->scene, &r->scene.camera, &v->g, fs_scene_floor(&r->scene, g), v->rgba);
    if (!rc) fs_stages_add(st, "analytic", fs_now_ms() - t0);
    return rc;
}

/* A finished work item (one view of one frame), for the progress bar or line. */
static void item_done(const cmp_run *r, const char *label, int f)
{
    char what[160];
    if (r->nframes > 1) snprintf(what, sizeof what, "%s, frame %d", label, r->first_frame + f);
    else snprintf(what, sizeof what, "%s", label);
    fs_progress_item(what);
}

/* 1 when this process renders some frame of reference (is_ref) or entry index. */
static int renders_any(const cmp_run *r, int is_ref, int index)
{
    for (int f = 0; f < r->nframes; f++)
        if (cmp_renders(r, cmp_item_id(r, is_ref, index, f))) return 1;
    return 0;
}

/* One reference on every frame, from the cache where it holds the frame;
 * stages time the first, and its time is their sum (fs_stages_total), so the
 * counting render of --counters, which cli_cache_render runs outside every
 * stage, is never part of it. */
static int render_ref(cmp_run *r, int k, const fs_particles *frames_p, const fs_grid *grids)
{
    cmp_ref *ref = &r->refs[k];
    fs_run *run = NULL;
    int rc = ref->analytic || !renders_any(r, 1, k) ? FS_OK : fs_run_open(&run, ref->v.m, &r->scene, ref->v.params, NULL);
    for (int f = 0; f < r->nframes && !rc; f++) {
        cmp_view *v = &ref->frames[f];
        cli_cache_view *made = &ref->made[f];
        fs_stages st = {0};
        if (r->merge) {
            if (!(rc = cmp_merge_ref(r, k, f, v))) item_done(r, ref->spec, f);
            continue;
        }
        if (!cmp_renders(r, cmp_item_id(r, 1, k, f))) continue;
        if (ref->analytic) rc = render_analytic(r, f, &grids[f], v, &st);
        else rc = cli_cache_render(&r->cache, run, &r->scene, &frames_p[f], &grids[f], &r->prov, r->first_frame + f, v,
                                   &st, made);
        ref->hits += made->hit;
        if (!rc && made->hit) fs_note("%s, frame %d: from the cache, %s", ref->spec, r->first_frame + f, made->entry);
        if (f == 0) ref->stages = st;
        if (!rc) item_done(r, ref->spec, f);
    }
    fs_run_close(run);
    return rc;
}

/* Renders the references of every frame (before any method, so metrics and
 * temporal stability can be computed frame by frame). */
static int render_refs(cmp_run *r, const fs_particles *frames_p, const fs_grid *grids)
{
    for (int k = 0; k < r->nrefs; k++) {
        cmp_ref *ref = &r->refs[k];
        ref->frames = calloc(r->nframes, sizeof *ref->frames);
        ref->made = calloc(r->nframes, sizeof *ref->made);
        if (!ref->frames || !ref->made) return fs_fail(FS_ERR_RUNTIME, "out of memory");
        int rc = render_ref(r, k, frames_p, grids);
        if (rc) return rc;
    }
    return FS_OK;
}

/* The PNGs first and the EXR last: a complete EXR means a finished item (--resume). */
static int write_view(const cmp_run *r, const char *label, int frame, const cmp_view *v, const fs_provenance *prov)
{
    char path[1400];
    cmp_view_path(r, NULL, label, frame, "", "png", path, sizeof path);
    int rc = cmp_outdir_record(path);
    if (!rc) rc = fs_write_render(path, &v->g, v->rgba, prov);
    const float *own = fs_gbuffer_aov(&v->g, FS_AOV_OWN);
    if (!rc && own) { /* the method's own appearance beside the shared shading */
        cmp_view_path(r, NULL, label, frame, "_own", "png", path, sizeof path);
        if (!(rc = cmp_outdir_record(path))) rc = fs_write_render(path, &v->g, own, prov);
    }
    cmp_view_path(r, NULL, label, frame, "", "exr", path, sizeof path);
    if (!rc) rc = cmp_outdir_record(path);
    return rc ? rc : fs_write_render_in_scene(path, &r->scene, &r->scene.camera, &v->g, v->rgba, prov);
}

/* The metrics of a variant's view of frame f against every reference. */
static int item_metrics(cmp_run *r, cmp_entry *e, int f, const cmp_view *cur)
{
    int rc = FS_OK;
    for (int k = 0; k < r->nrefs && !rc; k++)
        rc = fs_metrics_compute_in_scene(&r->scene, &r->scene.camera, &cur->g, cur->rgba, &r->refs[k].frames[f].g,
                                         r->refs[k].frames[f].rgba, &e->metrics[k * r->nframes + f]);
    return rc;
}

/* Frame f of one variant: upload, a warm-up render, `repeat` timed renders
 * (the first frame's kept in e->runs), shading, metrics, images. */
static int run_frame(cmp_run *r, cmp_entry *e, fs_run *run, int f, const fs_particles *p, const fs_grid *g,
                     cmp_view *cur)
{
    if (r->merge) {
        int rc = cmp_merge_entry(r, (int)(e - r->entries), f, cur);
        return rc ? rc : item_metrics(r, e, f, cur);
    }
    fs_provenance prov;
    fs_run_provenance(run, &r->prov, r->first_frame + f, &prov);
    char exr[1400];
    cmp_view_path(r, NULL, e->label, r->first_frame + f, "", "exr", exr, sizeof exr);
    if (r->resume && cmp_resume_load(e, f, &prov, exr, cur)) {
        r->resumed++;
        return r->shard_n ? FS_OK : item_metrics(r, e, f, cur);
    }
    double times[CMP_MAX_RUNS];
    int rc = fs_run_upload(run, p, g, NULL);
    for (int k = 0; k <= r->repeat && !rc; k++) { /* run 0 is the warm-up */
        fs_stages st = {0};
        rc = fs_run_render(run, &r->scene.camera, cur, &st);
        if (k == 0) continue;
        times[k - 1] = fs_stages_total(&st);
        if (f == 0) e->runs[e->nruns++] = st;
    }
    if (!rc) rc = fs_run_shade(run, &r->scene.camera, cur, FS_APPEARANCE_SHARED, NULL);
    if (rc) return rc;
    e->frame_ms[f] = fs_median(times, r->repeat);
    rc = r->shard_n ? FS_OK : item_metrics(r, e, f, cur); /* a shard has not every reference: merge measures */
    cmp_resume_stamp(&prov, e, f);
    if (!rc) rc = write_view(r, e->label, r->first_frame + f, cur, &prov);
    return rc;
}

/* With --counters, after the timed renders: a counting render of every frame
 * on the same inputs (docs/DESIGN.md, "Work counters"). */
static int count_entry(cmp_run *r, cmp_entry *e, const fs_particles *frames_p, const fs_grid *grids,
                       const fs_gl_context *ctx)
{
    int rc = FS_OK;
    for (int f = 0; f < r->nframes && !rc; f++) {
        if (!cmp_renders(r, cmp_item_id(r, 0, (int)(e - r->entries), f))) continue;
        cmp_view v = {0};
        fs_note("counting %s, frame %d/%d", e->label, f + 1, r->nframes);
        rc = fs_run_count(e->v.m, &r->scene, e->v.params, ctx, &frames_p[f], &grids[f], &r->scene.camera, &v,
                          &e->counts[f]);
        /* the counts describe the timed render only when it drew the same G-buffer */
        if (!rc && f == 0 && !fs_digest_equal(fs_gcache_data_hash(&v.g), fs_gcache_data_hash(&e->first.g)))
            fs_note("%s: the counting render's G-buffer differs from the timed render's", e->label);
        free_view(&v);
    }
    return rc;
}

/* A variant's temporal measures, summed over frame pairs (compare_temporal.h). */
typedef struct temporal_sums { double change, err_normal, err_depth; int n_change, n_err; } temporal_sums;

/* Frames f-1 (a) and f (b) of a variant: its change, and its error against the
 * first reference's motion where that reference is at hand (not in a shard). */
static void add_temporal(const cmp_run *r, int f, const fs_gbuffer *a, const fs_gbuffer *b, temporal_sums *t)
{
    const cmp_ref *ref = &r->refs[0];
    int with_ref = !r->shard_n && ref->frames && ref->frames[f - 1].g.w && ref->frames[f].g.w;
    /* Pixels a solid hides in front of the reference's surface (or, without the
     * reference at hand, the variant's own) leave both measures. */
    const fs_gbuffer *g[4] = {a, b, with_ref ? &ref->frames[f - 1].g : NULL, with_ref ? &ref->frames[f].g : NULL};
    fs_gbuffer v[4];
    size_t n = (size_t)a->w * a->h;
    float *cov = r->scene.obstacles.n ? malloc(4 * n * sizeof *cov) : NULL;
    if (cov && !fs_obstacle_hide(&r->scene, &r->scene.camera, with_ref ? g + 2 : g, 2, g, with_ref ? 4 : 2, v, cov))
        for (int k = 0; k < (with_ref ? 4 : 2); k++) g[k] = &v[k];
    double d = cmp_normal_change(g[0], g[1]);
    if (isfinite(d)) t->change += d, t->n_change++;
    if (with_ref) {
        cmp_temporal_error e = cmp_temporal_error_of(g[0], g[1], g[2], g[3], r->scene.radius);
        if (isfinite(e.normal_deg)) t->err_normal += e.normal_deg, t->err_depth += e.depth_r, t->n_err++;
    }
    free(cov);
}

static void finish_temporal(const temporal_sums *t, cmp_entry *e)
{
    e->temporal_deg = t->n_change ? t->change / t->n_change : NAN;
    e->temporal_err_deg = t->n_err ? t->err_normal / t->n_err : NAN;
    e->temporal_err_depth_r = t->n_err ? t->err_depth / t->n_err : NAN;
}

/* Runs one method variant on every frame; keeps the first frame's view for
 * the panel and heatmaps, and its temporal measures. */
static int run_entry(cmp_run *r, cmp_entry *e, const fs_particles *frames_p, const fs_grid *grids,
                     const fs_gl_context *ctx)
{
    int index = (int)(e - r->entries), opened = !r->merge && renders_any(r, 0, index);
    fs_run *run = NULL;
    int rc = opened ? fs_run_open(&run, e->v.m, &r->scene, e->v.params, e->v.m->needs_gl ? ctx : NULL) : FS_OK;
    if (rc) return rc;
    if (opened) snprintf(e->renderer, sizeof e->renderer, "%s", fs_run_renderer(run));
    cmp_view cur = {0}, prev = {0};
    temporal_sums ts = {0};
    for (int f = 0; f < r->nframes && !rc; f++) {
        if (!r->merge && !cmp_renders(r, cmp_item_id(r, 0, index, f))) continue;
        rc = run_frame(r, e, run, f, &frames_p[f], &grids[f], &cur);
        if (rc) break;
        item_done(r, e->label, f);
        if (f > 0) add_temporal(r, f, &prev.g, &cur.g, &ts);
        if (f == 0) e->first = cur;
        else if (prev.rgba != e->first.rgba) free_view(&prev); /* the first frame's view stays for the panel */
        prev = cur;
        memset(&cur, 0, sizeof cur);
    }
    if (prev.rgba && prev.rgba != e->first.rgba) free_view(&prev);
    free_view(&cur);
    finish_temporal(&ts, e);
    fs_run_close(run);
    if (!rc && r->counters && opened) rc = count_entry(r, e, frames_p, grids, ctx);
    return rc;
}

/* Heatmap scales: fixed by option, else the largest 95th percentile over the
 * entries against the first reference, rounded up to 1/2/5 x 10^k. */
static void choose_scales(cmp_run *r, double normal_opt, double depth_opt)
{
    double nmax = 0, dmax = 0;
    for (int i = 0; i < r->nentries; i++) {
        const fs_metrics *mt = &r->entries[i].metrics[0];
        if (isfinite(mt->normal_p95_deg) && mt->normal_p95_deg > nmax) nmax = mt->normal_p95_deg;
        if (isfinite(mt->depth_p95_r) && mt->depth_p95_r > dmax) dmax = mt->depth_p95_r;
    }
    r->normal_scale_deg = normal_opt > 0 ? normal_opt : fs_nice_ceil(nmax > 0 ? nmax : 10);
    r->depth_scale_r = depth_opt > 0 ? depth_opt : fs_nice_ceil(dmax > 0 ? dmax : 1);
}

static void quote_command(char *buf, int size, int argc, char **argv)
{
    int n = snprintf(buf, size, "fluidsurf");
    for (int i = 0; i < argc && n < size; i++) {
        const char *a = argv[i];
        int plain = *a != 0;
        for (const char *c = a; *c; c++)
            if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=,:@%+", *c)) plain = 0;
        if (plain) n += snprintf(buf + n, size - n, " %s", a);
        else {
            n += snprintf(buf + n, size - n, " '");
            for (const char *c = a; *c && n < size; c++) n += *c == '\'' ? snprintf(buf + n, size - n, "'\\''") : snprintf(buf + n, size - n, "%c", *c);
            n += snprintf(buf + n, size - n, "'");
        }
    }
}

/* The parsed command line. */
typedef struct cmp_options {
    const char *input, *methods;
    const char *const *refspecs;
    int nrefspecs;
    const char *const *imports;
    int nimports;
    const char *const *sets;
    int nsets, w, h;
    float radius, nscale, dscale;
    cli_scene_opts field;
    fs_ctx_kind ctx_kind;
    const char *cache_dir; /* NULL: the default folder */
    int no_cache;
    int counters;
} cmp_options;

/* The variants of every method of the comma list (all registered when NULL). */
static int add_variants(cmp_run *r, const char *methods, const fs_sweep *sweeps, int nsweeps)
{
    char mlist[1024];
    if (methods) snprintf(mlist, sizeof mlist, "%s", methods);
    else {
        int n = 0;
        mlist[0] = 0;
        for (int i = 0; i < fs_method_count(); i++) n += snprintf(mlist + n, sizeof mlist - n, "%s%s", i ? "," : "", fs_method_at(i)->name);
    }
    for (char *tok = strtok(mlist, ","); tok; tok = strtok(NULL, ",")) {
        const fs_method *m = fs_method_find(tok);
        if (!m) return cli_unknown_method("compare", "--methods", tok);
        static fs_variant vars[CMP_MAX_ENTRIES];
        int n = fs_sweep_variants(m, &r->scene, sweeps, nsweeps, vars, CMP_MAX_ENTRIES - r->nentries);
        if (n < 0) return cli_error(-n);
        for (int k = 0; k < n; k++) {
            cmp_entry *e = &r->entries[r->nentries + k];
            e->v = vars[k];
            snprintf(e->name, sizeof e->name, "%s", m->name);
            memcpy(e->label, e->v.label, sizeof e->label);
            memcpy(e->variant, e->v.variant, sizeof e->variant);
        }
        r->nentries += n;
    }
    for (int i = 0; i < nsweeps; i++) {
        int used = 0;
        for (int k = 0; k < r->nentries; k++) used |= r->entries[k].v.m == sweeps[i].m;
        if (!used) return cli_usage("compare", "--set sweeps %s, which is not among the methods", sweeps[i].m->name);
    }
    return FS_OK;
}

/* metrics.csv's parameter columns: each swept parameter's name once, in --set order. */
static void param_columns(cmp_run *r, const fs_sweep *sweeps, int nsweeps)
{
    r->npcols = 0;
    for (int i = 0; i < nsweeps; i++) {
        const char *name = sweeps[i].m->params[sweeps[i].param].name;
        int seen = 0;
        for (int k = 0; k < r->npcols; k++) seen |= !strcmp(r->pcols[k], name);
        if (!seen) snprintf(r->pcols[r->npcols++], sizeof r->pcols[0], "%s", name);
    }
}

/* The scene and the variants: plain settings go to the scene, comma lists become sweeps. */
static int plan_variants(cmp_run *r, const cmp_options *o)
{
    fs_scene *s = &r->scene;
    int rc = cli_scene_from_arg(s, o->input);
    if (rc) return cli_error(rc);
    cli_scene_opts_apply(s, &o->field);
    if (o->w) s->camera.width = o->w;
    if (o->h) s->camera.height = o->h;
    if ((long)s->camera.width * s->camera.height > 16384L * 16384L / 4)
        return cli_usage("compare", "%dx%d pixels is too large", s->camera.width, s->camera.height);
    if (o->radius > 0) s->radius = o->radius;
    fs_sweep sweeps[FS_MAX_SWEEPS];
    int nsweeps = 0;
    for (int i = 0; i < o->nsets; i++) {
        fs_param_setting split;
        if ((rc = fs_param_split(o->sets[i], &split))) return cli_error(rc);
        rc = strchr(split.value, ',') ? fs_sweep_add(sweeps, &nsweeps, o->sets[i]) : fs_scene_add_set(s, o->sets[i]);
        if (rc) return cli_error(rc);
    }
    if ((rc = add_variants(r, o->methods, sweeps, nsweeps))) return rc;
    param_columns(r, sweeps, nsweeps);
    for (int i = 0; o->counters && i < r->nentries; i++)
        if ((rc = fs_run_check_counters(r->entries[i].v.m))) return cli_error(rc);
    double check[FS_MAX_PARAMS]; /* every plain --set must name a real method and parameter */
    if ((rc = fs_method_params_resolve(fs_method_at(0), s, check))) return cli_error(rc);
    return FS_OK;
}

/* The label of view i: the references first, then the entries. */
static const char *view_label(const cmp_run *r, int i)
{
    return i < r->nrefs ? r->refs[i].label : r->entries[i - r->nrefs].label;
}

/* 1 when views i and j are one view: a reference and the entry that is it (same
 * method and parameters), which write the same files. */
static int same_view(const cmp_run *r, int i, int j)
{
    if ((i < r->nrefs) == (j < r->nrefs)) return 0;
    const cmp_ref *ref = &r->refs[i < r->nrefs ? i : j];
    const cmp_entry *e = &r->entries[(i < r->nrefs ? j : i) - r->nrefs];
    return !ref->analytic && e->v.m == ref->v.m && !memcmp(e->v.params, ref->v.params, ref->v.m->nparams * sizeof e->v.params[0]);
}

/* Every view's label names its files: two views alike would overwrite each
 * other's, and one called like a summary file (panel.png, diff_*.png) would
 * overwrite it. */
static int check_labels(const cmp_run *r)
{
    int n = r->nrefs + r->nentries;
    for (int i = 0; i < n; i++) {
        const char *a = view_label(r, i);
        if (!strcmp(a, "panel") || !strncmp(a, "diff_", 5))
            return fs_fail(FS_ERR_INPUT, "%s: a view with this label would overwrite compare's own %s files", a,
                           a[0] == 'p' ? "panel" : "diff_*");
        for (int j = 0; j < i; j++)
            if (!strcmp(a, view_label(r, j)) && !same_view(r, i, j))
                return fs_fail(FS_ERR_INPUT, "two views get the file label %s (a value given twice, or two that differ "
                               "only in characters a label cannot hold)", a);
    }
    return FS_OK;
}

/* References and imports, then the output folder: all input is checked before it is made. */
static int plan_references(cmp_run *r, const cmp_options *o)
{
    const fs_scene *s = &r->scene;
    int rc = FS_OK;
    for (int i = 0; i < o->nrefspecs && !rc; i++) rc = parse_ref(r, o->refspecs[i]);
    if (!rc && !o->nrefspecs) rc = parse_ref(r, "reference");
    if (!rc && o->nimports && s->frame_first >= 0 && s->frame_last > s->frame_first)
        rc = fs_fail(FS_ERR_INPUT, "--import needs a single-frame scene");
    for (int i = 0; i < o->nimports && !rc; i++) rc = parse_import(r, o->imports[i]);
    if (!rc) rc = check_labels(r);
    if (!rc) rc = make_outdir(r->outdir, &r->made_outdir);
    /* a merge writes into its fresh staging folder; merge itself checks the output */
    if (!rc && !r->made_outdir && !r->merge) rc = cmp_outdir_claim(r->outdir, "compare", r->resume, r->force);
    if (rc) {
        for (int i = 0; i < r->nentries; i++) free_view(&r->entries[i].first);
        return cli_error(rc);
    }
    int last;
    fs_scene_frames(s, &r->first_frame, &last);
    r->sequence = s->frame_first >= 0;
    r->nframes = last - r->first_frame + 1;
    if (r->nframes > CMP_MAX_FRAMES) return cli_usage("compare", "%d frames: at most %d", r->nframes, CMP_MAX_FRAMES);
    return FS_OK;
}

/* 1 when this process renders some view of frame f. */
static int frame_needed(const cmp_run *r, int f)
{
    for (int i = -r->nrefs; i < r->nentries; i++) {
        int is_ref = i < 0, index = is_ref ? i + r->nrefs : i;
        if ((is_ref || !r->entries[index].imported) && cmp_renders(r, cmp_item_id(r, is_ref, index, f))) return 1;
    }
    return 0;
}

/* The particles and neighbour grid of every frame this process renders, shared
 * by all variants; the first frame, always loaded, settles r and the camera for
 * the whole sequence (a merge needs nothing else). */
static int load_frames(cmp_run *r, float radius, fs_particles *frames_p, fs_grid *grids)
{
    int rc = FS_OK;
    for (int f = 0; f < r->nframes && !rc; f++) {
        if (f > 0 && !frame_needed(r, f)) continue;
        rc = fs_scene_load_frame(&r->scene, r->first_frame + f, &frames_p[f]);
        if (!rc && f == 0) fs_scene_adopt_frame(&r->scene, &frames_p[0], radius, r->radius_note, sizeof r->radius_note);
        if (!rc && frame_needed(r, f)) rc = fs_grid_build(&grids[f], &frames_p[f], fs_scene_field(&r->scene).H);
    }
    return rc;
}

static int alloc_results(cmp_run *r)
{
    for (int i = 0; i < r->nentries; i++) {
        cmp_entry *e = &r->entries[i];
        e->metrics = calloc((size_t)r->nrefs * r->nframes, sizeof *e->metrics);
        e->frame_ms = calloc(r->nframes, sizeof *e->frame_ms);
        e->runs = calloc(r->repeat, sizeof *e->runs);
        e->counts = r->counters ? calloc(r->nframes, sizeof *e->counts) : NULL;
        if (!e->metrics || !e->frame_ms || !e->runs || (r->counters && !e->counts))
            return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    return FS_OK;
}

static int write_refs(const cmp_run *r)
{
    int rc = FS_OK;
    for (int k = 0; k < r->nrefs && !rc; k++) {
        fs_provenance prov = r->prov;
        char pstr[600];
        if (!r->refs[k].analytic) {
            fs_method_params_string(r->refs[k].v.m, r->refs[k].v.params, pstr, sizeof pstr);
            fs_provenance_set(&prov, "params", pstr);
        }
        fs_provenance_set(&prov, "method", r->refs[k].label);
        fs_provenance_set(&prov, "gl_renderer", "CPU");
        for (int f = 0; f < r->nframes && !rc; f++)
            if (cmp_renders(r, cmp_item_id(r, 1, k, f)))
                rc = write_view(r, r->refs[k].label, r->first_frame + f, &r->refs[k].frames[f], &prov);
    }
    return rc;
}

/* An imported G-buffer: metrics of its one frame against every reference. */
static int measure_import(cmp_run *r, cmp_entry *e)
{
    int rc = FS_OK;
    for (int k = 0; k < r->nrefs && !rc; k++)
        rc = fs_metrics_compute_in_scene(&r->scene, &r->scene.camera, &e->first.g, e->first.rgba, &r->refs[k].frames[0].g,
                                         r->refs[k].frames[0].rgba, &e->metrics[k]);
    e->frame_ms[0] = NAN;
    e->temporal_deg = e->temporal_err_deg = e->temporal_err_depth_r = NAN;
    return rc;
}

/* The work items this process renders (a merge: loads). */
static long items_here(const cmp_run *r)
{
    long n = 0;
    for (int f = 0; f < r->nframes; f++)
        for (int i = -r->nrefs; i < r->nentries; i++) {
            int is_ref = i < 0, index = is_ref ? i + r->nrefs : i;
            n += (is_ref || !r->entries[index].imported) && (r->merge || cmp_renders(r, cmp_item_id(r, is_ref, index, f)));
        }
    return n;
}

/* The references, then every variant (and import) against them; a shard
 * renders its own items only and measures nothing (merge does). */
static int render_all(cmp_run *r, const fs_particles *frames_p, const fs_grid *grids, const fs_gl_context *ctx)
{
    fs_progress_begin(r->merge ? "merge" : "compare", r->merge ? "work items loaded" : "work items", items_here(r));
    int rc = render_refs(r, frames_p, grids);
    if (!rc && !r->merge) rc = write_refs(r);
    for (int i = 0; i < r->nentries && !rc; i++) {
        cmp_entry *e = &r->entries[i];
        if (e->imported && r->shard_n) continue;
        rc = e->imported ? measure_import(r, e) : run_entry(r, e, frames_p, grids, ctx);
    }
    fs_progress_end();
    return rc;
}

/* The reference's own mean normal change between frames, beside the methods'. */
static void reference_temporal(cmp_run *r)
{
    double sum = 0;
    int n = 0;
    for (int f = 1; f < r->nframes; f++) {
        const fs_gbuffer *g[2] = {&r->refs[0].frames[f - 1].g, &r->refs[0].frames[f].g};
        fs_gbuffer v[2];
        float *cov = r->scene.obstacles.n ? malloc(2 * (size_t)g[0]->w * g[0]->h * sizeof *cov) : NULL;
        if (cov && !fs_obstacle_hide(&r->scene, &r->scene.camera, g, 2, g, 2, v, cov)) g[0] = &v[0], g[1] = &v[1];
        double d = cmp_normal_change(g[0], g[1]);
        if (isfinite(d)) { sum += d; n++; }
        free(cov);
    }
    r->ref_temporal_deg = n ? sum / n : NAN;
}

static int write_outputs(cmp_run *r, const cmp_options *o)
{
    if (r->nframes > 1) reference_temporal(r);
    choose_scales(r, o->nscale, o->dscale);
    int rc = cmp_write_metrics(r);
    if (!rc) rc = cmp_write_timings(r);
    if (!rc && r->nframes > 1) rc = cmp_write_temporal(r);
    if (!rc) rc = cmp_write_diffs(r);
    if (!rc) rc = cmp_write_panel(r);
    if (!rc && r->counters) rc = cmp_write_counters(r);
    if (!rc) rc = cmp_write_report(r);
    return rc;
}

static void free_results(cmp_run *r, fs_particles *frames_p, fs_grid *grids)
{
    for (int i = 0; i < r->nentries; i++) {
        free_view(&r->entries[i].first);
        free(r->entries[i].metrics);
        free(r->entries[i].frame_ms);
        free(r->entries[i].runs);
        free(r->entries[i].counts);
    }
    for (int k = 0; k < r->nrefs; k++) {
        for (int f = 0; r->refs[k].frames && f < r->nframes; f++) free_view(&r->refs[k].frames[f]);
        free(r->refs[k].frames);
        free(r->refs[k].made);
    }
    for (int f = 0; frames_p && f < r->nframes; f++) { fs_particles_free(&frames_p[f]); fs_grid_free(&grids[f]); }
    free(frames_p);
    free(grids);
}

static int need_gl(const cmp_run *r)
{
    for (int i = 0; i < r->nentries; i++)
        if (r->entries[i].v.m && r->entries[i].v.m->needs_gl && !r->merge && renders_any(r, 0, i)) return 1;
    return 0;
}

/* --shard: the split and a fresh start; merge: every item's record. */
static int plan_shards(cmp_run *r)
{
    if (r->merge) return cmp_merge_map(r->merge, r);
    if (!r->shard_n) return FS_OK;
    int rc = cmp_shard_plan(r);
    return rc ? rc : cmp_shard_start(r);
}

/* The provenance: a shard names itself; a merge names the shards' machines. */
static int provenance(cmp_run *r, const fs_gl_context *ctx, int have_ctx)
{
    fs_provenance_init(&r->prov, &r->scene, have_ctx ? ctx->renderer : NULL, have_ctx ? ctx->version : NULL);
    if (r->merge) cmp_merge_provenance(r->merge, &r->prov);
    if (!r->shard_n || r->merge) return FS_OK;
    char v[32];
    snprintf(v, sizeof v, "%d/%d", r->shard_k, r->shard_n);
    fs_provenance_set(&r->prov, "shard", v);
    return cmp_shard_write(r, 0);
}

/* What one process prints when it is done. */
static void done_notes(const cmp_run *r, double t_start)
{
    if (r->radius_note[0]) fs_note("%s", r->radius_note);
    if (r->resume) fs_note("--resume: %d work item(s) loaded from %s/, the rest rendered", r->resumed, r->outdir);
    if (r->merge) fs_note("merge of %d shards done in %.1f s, outputs in %s/", r->merge->n, since_s(t_start), r->merge->out_arg);
    else if (r->shard_n) fs_note("shard %d/%d done in %.1f s: %ld work item(s), outputs in %s/", r->shard_k, r->shard_n,
                                 since_s(t_start), items_here(r), r->outdir);
    else fs_note("compare done in %.1f s, outputs in %s/", since_s(t_start), r->outdir);
}

/* The plan: variants, references, frames, a GL context if any variant needs
 * one, every render, the outputs. */
static int compare(cmp_run *r, const cmp_options *o)
{
    int rc = plan_variants(r, o);
    if (!rc) rc = plan_references(r, o);
    if (rc) return rc;
    if ((rc = plan_shards(r))) return cli_error(rc);
    cli_cache_open(&r->cache, o->cache_dir, !o->no_cache, r->quiet);
    r->cache.counters = r->counters; /* the references' counts come with their views */
    fs_particles *frames_p = calloc(r->nframes, sizeof *frames_p);
    fs_grid *grids = calloc(r->nframes, sizeof *grids);
    fs_gl_context ctx = {0};
    int have_ctx = 0;
    double t_start = fs_now_ms();
    rc = !frames_p || !grids ? fs_fail(FS_ERR_RUNTIME, "out of memory") : load_frames(r, o->radius, frames_p, grids);
    if (!rc && need_gl(r)) { rc = cli_gl_context_create(&ctx, o->ctx_kind, 16, 16); have_ctx = !rc; }
    if (!rc) rc = provenance(r, &ctx, have_ctx);
    if (!rc) rc = alloc_results(r);
    if (!rc) rc = render_all(r, frames_p, grids, &ctx);
    if (!rc) rc = r->shard_n && !r->merge ? cmp_shard_write(r, 1) : write_outputs(r, o);
    if (r->merge) { int prc = cmp_merge_publish(r->merge, !rc); rc = rc ? rc : prc; }
    if (!rc) done_notes(r, t_start);
    if (rc) cli_error(rc);
    if (rc && r->made_outdir) rmdir(r->outdir); /* only if still empty: a refused context (--require-gpu) left nothing */
    free_results(r, frames_p, grids);
    if (have_ctx) fs_gl_context_destroy(&ctx);
    return rc;
}

/* compare's command line; with m, the merge of m's shards into m's staging folder. */
static int compare_main(int argc, char **argv, cmp_merge *m)
{
    static cmp_run run;
    cmp_run *r = &run;
    memset(r, 0, sizeof *r);
    const char *input = NULL, *out = NULL, *methods = NULL, *cache_dir = NULL, *shard = NULL;
    const char *refspecs[CMP_MAX_REFS + 1], *imports[CMP_MAX_ENTRIES + 1], *sets[FS_MAX_SETS];
    int nrefspecs = 0, nimports = 0, nsets = 0, w = 0, h = 0, no_cache = 0, counters = 0, require_gpu = 0, rc;
    float radius = 0, nscale = 0, dscale = 0;
    cli_scene_opts field = CLI_SCENE_OPTS_UNSET;
    fs_ctx_kind ctx_kind = fs_gl_context_default_kind();
    r->repeat = 3;
    const cli_opt opts[] = {
        CLI_OPT_OUT(out, "DIR", "the output folder (made if missing)"),
        CLI_STRING_OPT("--methods", methods, "a,b,c", "methods to run (default: every registered method)"),
        CLI_OPT_SET(sets, nsets),
        CLI_LIST_OPT("--reference", refspecs, nrefspecs, CMP_MAX_REFS, "SPEC",
                     "reference, reference:PARAM=V,... or analytic (repeatable;\n"
                     "default: reference with the scene's field); the first is\n"
                     "used for the heatmaps"),
        CLI_LIST_OPT("--import", imports, nimports, CMP_MAX_ENTRIES, "NAME=FILE.exr",
                     "compare a G-buffer EXR rendered elsewhere (same channels)"),
        CLI_INT_OPT("--repeat", r->repeat, 1, CMP_MAX_RUNS, "N", "timed runs per variant after one warm-up (default 3)"),
        CLI_FLOAT_OPT("--normal-scale", nscale, 1e-6, 180, "DEG", "heatmap scale of the normal error (default: from the data)"),
        CLI_FLOAT_OPT("--depth-scale", dscale, 1e-9, 1e9, "R", "heatmap scale of the depth error, in r (default: from the data)"),
        CLI_OPT_CACHE(cache_dir, "the folder of cached reference G-buffers (default\n"
                      "$XDG_CACHE_HOME/fluidsurf, else ~/.cache/fluidsurf)"),
        CLI_FLAG_OPT("--no-cache", no_cache, "render every reference; read and write no cache"),
        CLI_FLAG_OPT("--resume", r->resume, "load the work items an earlier run of the same command\n"
                     "finished in DIR (their EXRs) instead of rendering them"),
        CLI_FLAG_OPT("--force", r->force, "DIR holds another run's outputs: remove them first\n"
                     "(fluidsurf's own files only; without it compare refuses)"),
        CLI_STRING_OPT("--shard", shard, "K/N", "render only shard K's share of the work items (K = 1..N),\n"
                       "into DIR with a manifest and a DONE marker; 'fluidsurf merge'\n"
                       "joins the N shards' folders into this command's outputs"),
        CLI_FLAG_OPT("--counters", counters, "also count each variant's and reference's work in a\n"
                     "separate render after the timed ones: counters.csv"),
        CLI_OPT_SIZE(w, h, 1, 16384, "image", "the scene's, else 512"),
        CLI_OPT_RADIUS(radius, "the scene's, else the file's, else estimated from\n"
                       "the particle spacing (a note says so; fluidsurf info shows it)"),
        CLI_OPT_SCENE(field),
        CLI_OPT_GL(ctx_kind),
        CLI_OPT_REQUIRE_GPU(require_gpu),
        CLI_OPT_QUIET(r->quiet),
        CLI_END,
    };
    const cli_command cmd = {"compare", "SCENE.json|PARTICLES -o DIR [options]", opts,
                             {&input, NULL, 1, "more than one input ('%s' and '%s')"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_note_quiet(r->quiet);
    fs_gl_context_require_gpu(require_gpu);
    if (!input) return cli_usage("compare", "no scene or particle file given");
    if (!out) return cli_usage("compare", "no output folder given (-o DIR)");
    if (no_cache && cache_dir) return cli_usage("compare", "--cache and --no-cache: choose one");
    if (r->resume && r->force) return cli_usage("compare", "--resume and --force: choose one");
    if (strlen(out) >= sizeof r->outdir - 300) return cli_usage("compare", "output folder path too long");
    snprintf(r->outdir, sizeof r->outdir, "%s", m ? m->staging : out);
    quote_command(r->command, sizeof r->command, argc, argv);
    r->counters = counters;
    r->argc = argc, r->argv = argv, r->merge = m;
    if (shard && (rc = cmp_shard_parse(shard, &r->shard_k, &r->shard_n))) return cli_error(rc);
    const cmp_options o = {input, methods, refspecs, nrefspecs, imports, nimports, sets, nsets, w, h, radius, nscale,
                           dscale, field, ctx_kind, cache_dir, no_cache, counters};
    rc = compare(r, &o);
    free(r->owner);
    return rc;
}

int cmd_compare(int argc, char **argv) { return compare_main(argc, argv, NULL); }

int cmp_compare_merged(int argc, char **argv, cmp_merge *m)
{
    int rc = compare_main(argc, argv, m);
    if (rc) cmp_merge_publish(m, 0); /* whatever stage failed, nothing stays behind */
    return rc;
}
