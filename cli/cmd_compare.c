/* fluidsurf compare: every method variant on the same particles, camera, light,
 * material and resolution; metrics against references; timings; figures. */
#include "cli.h"
#include "compare.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "options.h"
#include "render_output.h"
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
    "<label>_own.png for a method with its own appearance (surfels, volume_raycast),\n"
    "report.md (and temporal.csv for a sequence).\n";

static void free_view(cmp_view *v) { fs_gbuffer_free(&v->g); free(v->rgba); v->rgba = NULL; }

static int make_outdir(const char *dir)
{
    struct stat st;
    if (stat(dir, &st) != 0) {
        if (mkdir(dir, 0755) != 0) return fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", dir, strerror(errno));
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
            size_t l = strlen(ref->label);
            snprintf(ref->label + l, sizeof ref->label - l, "_%s", tok);
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
    for (const char *c = e->name; *c; c++)
        if (*c == '/' || *c == ' ') return fs_fail(FS_ERR_INPUT, "--import %s: NAME must not contain '/' or spaces", spec);
    strcpy(e->label, e->name); /* name is shorter than label */
    snprintf(e->variant, sizeof e->variant, "import");
    e->imported = 1;
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

/* Renders the references of every frame (before any method, so metrics and
 * temporal stability can be computed frame by frame). */
static int render_refs(cmp_run *r, fs_particles *frames_p, const fs_grid *grids)
{
    for (int k = 0; k < r->nrefs; k++) {
        cmp_ref *ref = &r->refs[k];
        ref->frames = calloc(r->nframes, sizeof *ref->frames);
        if (!ref->frames) return fs_fail(FS_ERR_RUNTIME, "out of memory");
        void *self = NULL;
        fs_method_setup setup = {fs_scene_field(&r->scene), ref->v.params, &r->scene};
        if (!ref->analytic && !(self = ref->v.m->create(&setup))) return FS_ERR_RUNTIME;
        for (int f = 0; f < r->nframes; f++) {
            cmp_view *v = &ref->frames[f];
            int rc = fs_gbuffer_alloc(&v->g, r->scene.camera.width, r->scene.camera.height, 0);
            if (!rc && !(v->rgba = malloc((size_t)v->g.w * v->g.h * 4 * sizeof(float)))) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
            double t0 = fs_now_ms();
            fs_stages st = {0};
            if (!rc && ref->analytic) rc = fs_synthetic_analytic(&r->scene, r->first_frame + f, &r->scene.camera, &v->g);
            else if (!rc) {
                rc = ref->v.m->upload(self, &frames_p[f], &grids[f]);
                if (!rc) rc = ref->v.m->render(self, &r->scene.camera, &v->g, &st);
            }
            if (f == 0) ref->frame_ms = fs_now_ms() - t0;
            if (rc) { if (self) ref->v.m->destroy(self); return rc; }
            fs_shade(&r->scene, &r->scene.camera, &v->g, fs_scene_floor(&r->scene, &frames_p[f]), v->rgba);
        }
        if (self) ref->v.m->destroy(self);
    }
    return FS_OK;
}

static double mean_normal_change(const fs_gbuffer *a, const fs_gbuffer *b)
{
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)a->w * a->h; i++) {
        if (a->coverage[i] < 0.5f || b->coverage[i] < 0.5f) continue;
        double d = a->normal[3 * i] * b->normal[3 * i] + a->normal[3 * i + 1] * b->normal[3 * i + 1] +
                   a->normal[3 * i + 2] * b->normal[3 * i + 2];
        sum += acos(d > 1 ? 1 : d < -1 ? -1 : d) * 180 / M_PI;
        n++;
    }
    return n ? sum / n : NAN;
}

static int write_view(const cmp_run *r, const char *label, int frame, const cmp_view *v, const fs_provenance *prov)
{
    char name[300], path[1400];
    for (int ext = 0; ext < 2; ext++) {
        if (r->sequence) snprintf(name, sizeof name, "%s_f%04d.%s", label, frame, ext ? "exr" : "png");
        else snprintf(name, sizeof name, "%s.%s", label, ext ? "exr" : "png");
        cmp_path(r, name, path, sizeof path);
        int rc = fs_write_render(path, &v->g, v->rgba, prov);
        if (rc) return rc;
    }
    if (!v->g.own) return FS_OK;
    /* the method's own appearance beside the shared shading */
    if (r->sequence) snprintf(name, sizeof name, "%s_own_f%04d.png", label, frame);
    else snprintf(name, sizeof name, "%s_own.png", label);
    cmp_path(r, name, path, sizeof path);
    return fs_write_render(path, &v->g, v->g.own, prov);
}

/* Runs one method variant on every frame: upload, a warm-up render, `repeat`
 * timed renders; metrics against every reference; writes its images. */
static int run_entry(cmp_run *r, cmp_entry *e, fs_particles *frames_p, const fs_grid *grids, const fs_gl_context *ctx,
                     int index, int total, double t_start)
{
    const fs_method *m = e->v.m;
    fs_method_setup setup = {fs_scene_field(&r->scene), e->v.params, &r->scene};
    void *self = m->create(&setup);
    if (!self) return FS_ERR_RUNTIME;
    snprintf(e->renderer, sizeof e->renderer, "%s", m->needs_gl ? ctx->renderer : "CPU");
    fs_provenance prov = r->prov;
    char pstr[600], fstr[32];
    fs_method_params_string(m, e->v.params, pstr, sizeof pstr);
    fs_provenance_set(&prov, "method", m->name);
    fs_provenance_set(&prov, "params", pstr);
    fs_provenance_set(&prov, "gl_renderer", e->renderer);
    cmp_view cur = {0}, prev = {0};
    double tsum = 0;
    int tn = 0, rc = FS_OK;
    for (int f = 0; f < r->nframes && !rc; f++) {
        if (!r->quiet) {
            double el = since_s(t_start), done = (double)(index * r->nframes + f) / (total * r->nframes);
            fprintf(stderr, "compare: variant %d/%d %s, frame %d/%d, elapsed %.1f s, remaining ~%.0f s\n", index + 1,
                    total, e->label, f + 1, r->nframes, el, done > 0 ? el / done - el : 0.0);
        }
        rc = fs_gbuffer_alloc(&cur.g, r->scene.camera.width, r->scene.camera.height, fs_method_wants_color(m, &frames_p[f]));
        if (!rc && m->writes_own) rc = fs_gbuffer_alloc_own(&cur.g);
        if (!rc && !(cur.rgba = malloc((size_t)cur.g.w * cur.g.h * 4 * sizeof(float)))) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
        if (!rc) rc = m->upload(self, &frames_p[f], &grids[f]);
        double times[CMP_MAX_RUNS];
        for (int run = 0; run <= r->repeat && !rc; run++) { /* run 0 is the warm-up */
            fs_stages st = {0};
            fs_gbuffer_clear(&cur.g);
            rc = m->render(self, &r->scene.camera, &cur.g, &st);
            if (run == 0) continue;
            times[run - 1] = fs_stages_total(&st);
            if (f == 0) e->runs[e->nruns++] = st;
        }
        if (rc) break;
        e->frame_ms[f] = fs_median(times, r->repeat);
        fs_shade(&r->scene, &r->scene.camera, &cur.g, fs_scene_floor(&r->scene, &frames_p[f]), cur.rgba);
        for (int k = 0; k < r->nrefs && !rc; k++)
            rc = fs_metrics_compute(&cur.g, cur.rgba, &r->refs[k].frames[f].g, r->refs[k].frames[f].rgba, r->scene.radius,
                                    &e->metrics[k * r->nframes + f]);
        snprintf(fstr, sizeof fstr, "%d", r->first_frame + f);
        fs_provenance_set(&prov, "frame", fstr);
        if (!rc) rc = write_view(r, e->label, r->first_frame + f, &cur, &prov);
        if (f > 0) {
            double d = mean_normal_change(&prev.g, &cur.g);
            if (isfinite(d)) { tsum += d; tn++; }
        }
        if (f == 0) e->first = cur;
        else if (prev.rgba != e->first.rgba) free_view(&prev); /* the first frame's view stays for the panel */
        prev = cur;
        memset(&cur, 0, sizeof cur);
    }
    if (prev.rgba && prev.rgba != e->first.rgba) free_view(&prev);
    free_view(&cur);
    e->temporal_deg = tn ? tsum / tn : NAN;
    m->destroy(self);
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

int cmd_compare(int argc, char **argv)
{
    static cmp_run run;
    cmp_run *r = &run;
    memset(r, 0, sizeof *r);
    const char *input = NULL, *out = NULL, *methods = NULL;
    const char *refspecs[CMP_MAX_REFS + 1], *imports[CMP_MAX_ENTRIES + 1], *sets[FS_MAX_SETS];
    int nrefspecs = 0, nimports = 0, nsets = 0, w = 0, h = 0, rc;
    float radius = 0, nscale = 0, dscale = 0;
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
        CLI_OPT_SIZE(w, h, 1, 16384, "image", "the scene's, else 512"),
        CLI_OPT_RADIUS(radius, "the scene's, else the file's, else 0.025"),
        CLI_OPT_GL(ctx_kind),
        CLI_OPT_QUIET(r->quiet),
        CLI_END,
    };
    const cli_command cmd = {"compare", "SCENE.json|PARTICLES -o DIR [options]", opts,
                             {&input, NULL, 1, "more than one input ('%s' and '%s')"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    if (!input) return cli_usage("compare", "no scene or particle file given");
    if (!out) return cli_usage("compare", "no output folder given (-o DIR)");
    if (strlen(out) >= sizeof r->outdir - 300) return cli_usage("compare", "output folder path too long");
    snprintf(r->outdir, sizeof r->outdir, "%s", out);
    quote_command(r->command, sizeof r->command, argc, argv);

    fs_scene *s = &r->scene;
    if ((rc = cli_scene_from_arg(s, input))) return cli_error(rc);
    if (w) s->camera.width = w;
    if (h) s->camera.height = h;
    if ((long)s->camera.width * s->camera.height > 16384L * 16384L / 4)
        return cli_usage("compare", "%dx%d pixels is too large", s->camera.width, s->camera.height);
    if (radius > 0) s->radius = radius;
    /* plain settings go to the scene, comma lists become sweeps */
    fs_sweep sweeps[FS_MAX_SWEEPS];
    int nsweeps = 0;
    for (int i = 0; i < nsets; i++) {
        const char *eq = strchr(sets[i], '=');
        rc = eq && strchr(eq, ',') ? fs_sweep_add(sweeps, &nsweeps, sets[i]) : fs_scene_add_set(s, sets[i]);
        if (rc) return cli_error(rc);
    }
    /* methods and their variants */
    char mlist[1024];
    if (methods) snprintf(mlist, sizeof mlist, "%s", methods);
    else {
        int n = 0;
        mlist[0] = 0;
        for (int i = 0; i < fs_method_count(); i++) n += snprintf(mlist + n, sizeof mlist - n, "%s%s", i ? "," : "", fs_method_at(i)->name);
    }
    for (char *tok = strtok(mlist, ","); tok; tok = strtok(NULL, ",")) {
        const fs_method *m = fs_method_find(tok);
        if (!m) return cli_usage("compare", "unknown method '%s' (see 'fluidsurf methods')", tok);
        static fs_variant vars[CMP_MAX_ENTRIES];
        int n = fs_sweep_variants(m, s, sweeps, nsweeps, vars, CMP_MAX_ENTRIES - r->nentries);
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
    double check[FS_MAX_PARAMS]; /* every plain --set must name a real method and parameter */
    if ((rc = fs_method_params_resolve(fs_method_at(0), s, check))) return cli_error(rc);
    /* references and imports: all input is checked before the output folder is made */
    for (int i = 0; i < nrefspecs && !rc; i++) rc = parse_ref(r, refspecs[i]);
    if (!rc && !nrefspecs) rc = parse_ref(r, "reference");
    if (!rc && nimports && s->frame_first >= 0 && s->frame_last > s->frame_first)
        rc = fs_fail(FS_ERR_INPUT, "--import needs a single-frame scene");
    for (int i = 0; i < nimports && !rc; i++) rc = parse_import(r, imports[i]);
    if (!rc) rc = make_outdir(out);
    if (rc) {
        for (int i = 0; i < r->nentries; i++) free_view(&r->entries[i].first);
        return cli_error(rc);
    }

    int last;
    fs_scene_frames(s, &r->first_frame, &last);
    r->sequence = s->frame_first >= 0;
    r->nframes = last - r->first_frame + 1;
    if (r->nframes > CMP_MAX_FRAMES) return cli_usage("compare", "%d frames: at most %d", r->nframes, CMP_MAX_FRAMES);

    fs_particles *frames_p = calloc(r->nframes, sizeof *frames_p);
    fs_grid *grids = calloc(r->nframes, sizeof *grids);
    fs_gl_context ctx = {0};
    int have_ctx = 0;
    double t_start = fs_now_ms();
    rc = !frames_p || !grids ? fs_fail(FS_ERR_RUNTIME, "out of memory") : FS_OK;
    for (int f = 0; f < r->nframes && !rc; f++) {
        rc = fs_scene_load_frame(s, r->first_frame + f, &frames_p[f]);
        if (!rc && f == 0) {
            if (!s->path[0] && radius <= 0 && frames_p[0].radius > 0) s->radius = frames_p[0].radius;
            fs_scene_frame_particles(s, &frames_p[0]); /* one camera for the whole sequence */
        }
        if (!rc) rc = fs_grid_build(&grids[f], &frames_p[f], fs_scene_field(s).H);
    }
    int need_gl = 0;
    for (int i = 0; i < r->nentries; i++) need_gl |= r->entries[i].v.m && r->entries[i].v.m->needs_gl;
    if (!rc && need_gl) { rc = fs_gl_context_create(&ctx, ctx_kind, 16, 16); have_ctx = !rc; }
    if (!rc) {
        fs_provenance_init(&r->prov, s, have_ctx ? ctx.renderer : NULL, have_ctx ? ctx.version : NULL);
        for (int i = 0; i < r->nentries && !rc; i++) {
            cmp_entry *e = &r->entries[i];
            e->metrics = calloc((size_t)r->nrefs * r->nframes, sizeof *e->metrics);
            e->frame_ms = calloc(r->nframes, sizeof *e->frame_ms);
            e->runs = calloc(r->repeat, sizeof *e->runs);
            if (!e->metrics || !e->frame_ms || !e->runs) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
        }
    }
    if (!rc) {
        if (!r->quiet) fprintf(stderr, "compare: rendering %d reference(s) on %d frame(s)\n", r->nrefs, r->nframes);
        rc = render_refs(r, frames_p, grids);
    }
    for (int k = 0; k < r->nrefs && !rc; k++) {
        fs_provenance prov = r->prov;
        char pstr[600];
        if (!r->refs[k].analytic) {
            fs_method_params_string(r->refs[k].v.m, r->refs[k].v.params, pstr, sizeof pstr);
            fs_provenance_set(&prov, "params", pstr);
        }
        fs_provenance_set(&prov, "method", r->refs[k].label);
        fs_provenance_set(&prov, "gl_renderer", "CPU");
        for (int f = 0; f < r->nframes && !rc; f++) rc = write_view(r, r->refs[k].label, r->first_frame + f, &r->refs[k].frames[f], &prov);
    }
    int nmethod = 0;
    for (int i = 0; i < r->nentries; i++) nmethod += !r->entries[i].imported;
    for (int i = 0, idx = 0; i < r->nentries && !rc; i++) {
        cmp_entry *e = &r->entries[i];
        if (e->imported) {
            for (int k = 0; k < r->nrefs && !rc; k++)
                rc = fs_metrics_compute(&e->first.g, e->first.rgba, &r->refs[k].frames[0].g, r->refs[k].frames[0].rgba,
                                        s->radius, &e->metrics[k]);
            e->frame_ms[0] = NAN;
            e->temporal_deg = NAN;
            continue;
        }
        rc = run_entry(r, e, frames_p, grids, &ctx, idx++, nmethod, t_start);
    }
    if (!rc && r->nframes > 1) {
        double sum = 0;
        int n = 0;
        for (int f = 1; f < r->nframes; f++) {
            double d = mean_normal_change(&r->refs[0].frames[f - 1].g, &r->refs[0].frames[f].g);
            if (isfinite(d)) { sum += d; n++; }
        }
        r->ref_temporal_deg = n ? sum / n : NAN;
    }
    if (!rc) {
        choose_scales(r, nscale, dscale);
        rc = cmp_write_metrics(r);
        if (!rc) rc = cmp_write_timings(r);
        if (!rc && r->nframes > 1) rc = cmp_write_temporal(r);
        if (!rc) rc = cmp_write_diffs(r);
        if (!rc) rc = cmp_write_panel(r);
        if (!rc) rc = cmp_write_report(r);
    }
    if (!rc && !r->quiet) fprintf(stderr, "compare: done in %.1f s, outputs in %s/\n", since_s(t_start), out);
    if (rc) cli_error(rc);
    for (int i = 0; i < r->nentries; i++) {
        free_view(&r->entries[i].first);
        free(r->entries[i].metrics);
        free(r->entries[i].frame_ms);
        free(r->entries[i].runs);
    }
    for (int k = 0; k < r->nrefs; k++) {
        for (int f = 0; r->refs[k].frames && f < r->nframes; f++) free_view(&r->refs[k].frames[f]);
        free(r->refs[k].frames);
    }
    for (int f = 0; frames_p && f < r->nframes; f++) { fs_particles_free(&frames_p[f]); fs_grid_free(&grids[f]); }
    free(frames_p);
    free(grids);
    if (have_ctx) fs_gl_context_destroy(&ctx);
    return rc;
}
