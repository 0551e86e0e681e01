/* fluidsurf compare: every method variant on the same particles, camera, light,
 * material and resolution; metrics against references; timings; figures. */
#include "cli.h"
#include "compare.h"
#include "compare_merge.h"
#include "compare_outdir.h"
#include "compare_shard.h"
#include "fs_error.h"
#include "gl_context.h"
#include "options.h"
#include "progress.h"
#include "report_html.h"
#include "scene_provenance.h"
#include "stats.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* what --help says after the options */
static const char epilogue[] = "--set M.P=v1,v2,... sweeps the parameter over the values.\n"
                               "Writes DIR/<label>.png|.exr, diff_<label>.png, metrics.csv, timings.csv, panel.png,\n"
                               "<label>_own.png for a method with its own appearance (fluidsurf methods says which),\n"
                               "heat_normal_<label>.png and heat_depth_<label>.png (the heatmaps alone, image-sized),\n"
                               "report.md, report.html (the interactive page: fluidsurf report --help), and\n"
                               "temporal.csv for a sequence; with --counters also counters.csv.\n"
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

static double since_s(double t0) { return (fs_now_ms() - t0) / 1000.0; }

/* Heatmap scales: fixed by option, else the largest 95th percentile over the
 * entries against the first reference, rounded up to 1/2/5 x 10^k. */
static void choose_scales(cmp_run *r, double normal_opt, double depth_opt)
{
    double nmax = 0, dmax = 0;
    for (int i = 0; i < r->s.nentries; i++) {
        const fs_metrics *mt = &r->s.entries[i].metrics[0];
        if (isfinite(mt->normal_p95_deg) && mt->normal_p95_deg > nmax) nmax = mt->normal_p95_deg;
        if (isfinite(mt->depth_p95_r) && mt->depth_p95_r > dmax) dmax = mt->depth_p95_r;
    }
    r->normal_scale_deg = normal_opt > 0 ? normal_opt : fs_nice_ceil(nmax > 0 ? nmax : 10);
    r->depth_scale_r = depth_opt > 0 ? depth_opt : fs_nice_ceil(dmax > 0 ? dmax : 1);
}

static int write_outputs(cmp_run *r, const cmp_options *o)
{
    choose_scales(r, o->nscale, o->dscale);
    int rc = cmp_write_table(r, "metrics");
    if (!rc) rc = cmp_write_table(r, "timings");
    if (!rc && r->s.nframes > 1) rc = cmp_write_table(r, "temporal");
    if (!rc) rc = cmp_write_diffs(r);
    if (!rc) rc = cmp_write_panel(r);
    if (!rc && r->s.counters) rc = cmp_write_table(r, "counters");
    if (!rc) rc = cmp_write_report(r);
    if (!rc) rc = cmp_write_report_html(r->outdir, 1); /* last: the page is built from the files above */
    return rc;
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
    fs_provenance_init(&r->s.prov, &r->s.scene, have_ctx ? ctx->renderer : NULL, have_ctx ? ctx->version : NULL);
    if (r->merge) cmp_merge_provenance(r->merge, &r->s.prov);
    if (!r->shard_n || r->merge) return FS_OK;
    char v[32];
    snprintf(v, sizeof v, "%d/%d", r->shard_k, r->shard_n);
    fs_provenance_set(&r->s.prov, "shard", v);
    return cmp_shard_write(r, 0);
}

/* What one process prints when it is done. */
static void done_notes(const cmp_run *r, const fs_study_io *io, double t_start)
{
    if (r->radius_note[0]) fs_note("%s", r->radius_note);
    if (r->resume) fs_note("--resume: %d work item(s) loaded from %s/, the rest rendered", r->resumed, r->outdir);
    if (r->merge)
        fs_note("merge of %d shards done in %.1f s, outputs in %s/", r->merge->n, since_s(t_start), r->merge->out_arg);
    else if (r->shard_n)
        fs_note("shard %d/%d done in %.1f s: %ld work item(s), outputs in %s/", r->shard_k, r->shard_n,
                since_s(t_start), fs_study_items_here(&r->s, io), r->outdir);
    else fs_note("compare done in %.1f s, outputs in %s/", since_s(t_start), r->outdir);
}

/* The first frame (it settles r and the camera), a GL context if any variant
 * needs one, the provenance, then every work item through the study. */
static int execute(cmp_run *r, const cmp_options *o, const fs_study_io *io, fs_gl_context *ctx, int *have_ctx)
{
    int rc = fs_study_load_first(&r->s, o->radius, r->radius_note, sizeof r->radius_note);
    if (!rc && fs_study_needs_gl(&r->s, io)) {
        rc = cli_gl_context_create(ctx, o->ctx_kind, 16, 16);
        *have_ctx = !rc;
    }
    if (!rc) rc = provenance(r, ctx, *have_ctx);
    if (!rc) rc = fs_study_alloc(&r->s);
    if (rc) return rc;
    fs_progress_begin(r->merge ? "merge" : "compare", r->merge ? "work items loaded" : "work items",
                      fs_study_items_here(&r->s, io));
    rc = fs_study_execute(&r->s, io, *have_ctx ? ctx : NULL);
    fs_progress_end();
    return rc;
}

/* The plan, the work items, the outputs. */
static int compare(cmp_run *r, const cmp_options *o)
{
    int rc = cmp_plan(r, o);
    if (rc) {
        fs_study_free(&r->s);
        return rc;
    }
    if ((rc = plan_shards(r))) {
        fs_study_free(&r->s);
        return cli_error(rc);
    }
    cli_cache_open(&r->cache, o->cache_dir, !o->no_cache, r->quiet);
    r->cache.counters = r->s.counters; /* the references' counts come with their views */
    fs_study_io io = cmp_io(r);
    fs_gl_context ctx = {0};
    int have_ctx = 0;
    double t_start = fs_now_ms();
    rc = execute(r, o, &io, &ctx, &have_ctx);
    if (!rc) rc = r->shard_n && !r->merge ? cmp_shard_write(r, 1) : write_outputs(r, o);
    if (r->merge) {
        int prc = cmp_merge_publish(r->merge, !rc);
        rc = rc ? rc : prc;
    }
    if (!rc) done_notes(r, &io, t_start);
    if (rc) cli_error(rc);
    if (rc && r->made_outdir)
        rmdir(r->outdir); /* only if still empty: a refused context (--require-gpu) left nothing */
    fs_study_free(&r->s);
    if (have_ctx) fs_gl_context_destroy(&ctx);
    return rc;
}

/* The options that need one another. */
static int check_args(const cmp_run *r, const char *input, const char *out, int no_cache, const char *cache_dir)
{
    if (!input) return cli_usage("compare", "no scene or particle file given");
    if (!out) return cli_usage("compare", "no output folder given (-o DIR)");
    if (no_cache && cache_dir) return cli_usage("compare", "--cache and --no-cache: choose one");
    if (r->resume && r->force) return cli_usage("compare", "--resume and --force: choose one");
    if (strlen(out) >= sizeof r->outdir - 300) return cli_usage("compare", "output folder path too long");
    return FS_OK;
}

/* The output folder (a merge's staging folder) and the command line, for the report and a shard's manifest. */
static void keep_command(cmp_run *r, const char *out, cmp_merge *m, int argc, char **argv)
{
    snprintf(r->outdir, sizeof r->outdir, "%s", m ? m->staging : out);
    cmp_quote_command(r->command, sizeof r->command, argc, argv);
    r->argc = argc, r->argv = argv, r->merge = m;
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
    r->s.repeat = 3;
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
        CLI_INT_OPT("--repeat", r->s.repeat, 1, CMP_MAX_RUNS, "N",
                    "timed runs per variant after one warm-up (default 3)"),
        CLI_FLOAT_OPT("--normal-scale", nscale, 1e-6, 180, "DEG",
                      "heatmap scale of the normal error (default: from the data)"),
        CLI_FLOAT_OPT("--depth-scale", dscale, 1e-9, 1e9, "R",
                      "heatmap scale of the depth error, in r (default: from the data)"),
        CLI_OPT_CACHE(cache_dir,
                      "the folder of cached reference G-buffers (default\n"
                      "$XDG_CACHE_HOME/fluidsurf, else ~/.cache/fluidsurf)"),
        CLI_FLAG_OPT("--no-cache", no_cache, "render every reference; read and write no cache"),
        CLI_FLAG_OPT("--resume", r->resume,
                     "load the work items an earlier run of the same command\n"
                     "finished in DIR (their EXRs) instead of rendering them"),
        CLI_FLAG_OPT("--force", r->force,
                     "DIR holds another run's outputs: remove them first\n"
                     "(fluidsurf's own files only; without it compare refuses)"),
        CLI_STRING_OPT("--shard", shard, "K/N",
                       "render only shard K's share of the work items (K = 1..N),\n"
                       "into DIR with a manifest and a DONE marker; 'fluidsurf merge'\n"
                       "joins the N shards' folders into this command's outputs"),
        CLI_FLAG_OPT("--counters", counters,
                     "also count each variant's and reference's work in a\n"
                     "separate render after the timed ones: counters.csv"),
        CLI_OPT_SIZE(w, h, 1, 16384, "image", "the scene's, else 512"),
        CLI_OPT_RADIUS(radius,
                       "the scene's, else the file's, else estimated from\n"
                       "the particle spacing (a note says so; fluidsurf info shows it)"),
        CLI_OPT_SCENE(field),
        CLI_OPT_GL(ctx_kind),
        CLI_OPT_REQUIRE_GPU(require_gpu),
        CLI_OPT_QUIET(r->quiet),
        CLI_END,
    };
    const cli_command cmd = {"compare",
                             "SCENE.json|PARTICLES -o DIR [options]",
                             opts,
                             {&input, NULL, 1, "more than one input ('%s' and '%s')"},
                             epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_note_quiet(r->quiet);
    fs_gl_context_require_gpu(require_gpu);
    if ((rc = check_args(r, input, out, no_cache, cache_dir))) return rc;
    keep_command(r, out, m, argc, argv);
    if (shard && (rc = cmp_shard_parse(shard, &r->shard_k, &r->shard_n))) return cli_error(rc);
    const cmp_options o = {input, methods, refspecs, nrefspecs, imports, nimports, sets,      nsets,    w,
                           h,     radius,  nscale,   dscale,    field,   ctx_kind, cache_dir, no_cache, counters};
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
