/* fluidsurf compare: every method variant on the same particles, camera, light,
 * material and resolution; metrics against references; timings; figures. */
#include "cli.h"
#include "compare.h"
#include "fs_error.h"
#include "gl_context.h"
#include "merge.h"
#include "options.h"
#include "shard.h"
#include "study_dir.h"
#include <stdio.h>
#include <string.h>

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

static compare_args A; /* the parsed command line (the table below fills it) */

static const cli_opt opts[] = {
    CLI_OPT_OUT(A.out, "DIR", "the output folder (made if missing)"),
    CLI_STRING_OPT("--methods", A.methods, "a,b,c",
                   "methods to run (default: every registered method but the reference, the ground truth)"),
    CLI_OPT_SET(A.sets, A.nsets),
    CLI_LIST_OPT("--reference", A.refspecs, A.nrefspecs, FS_STUDY_MAX_REFS, "SPEC",
                 "reference, reference:PARAM=V,... or analytic (repeatable;\n"
                 "default: reference with the scene's field); the first is\n"
                 "used for the heatmaps"),
    CLI_LIST_OPT("--import", A.imports, A.nimports, FS_STUDY_MAX_ENTRIES, "NAME=FILE.exr",
                 "compare a G-buffer EXR rendered elsewhere (same channels)"),
    CLI_INT_OPT("--repeat", A.repeat, 1, FS_STUDY_MAX_RUNS, "N",
                "timed runs per variant after one warm-up (default 3)"),
    CLI_FLOAT_OPT("--normal-scale", A.nscale, 1e-6, 180, "DEG",
                  "heatmap scale of the normal error (default: from the data)"),
    CLI_FLOAT_OPT("--depth-scale", A.dscale, 1e-9, 1e9, "R",
                  "heatmap scale of the depth error, in r (default: from the data)"),
    CLI_OPT_CACHE(A.cache_dir,
                  "the folder of cached reference G-buffers (default\n"
                  "$XDG_CACHE_HOME/fluidsurf, else ~/.cache/fluidsurf)"),
    CLI_FLAG_OPT("--no-cache", A.no_cache, "render every reference; read and write no cache"),
    CLI_FLAG_OPT("--resume", A.resume,
                 "load the work items an earlier run of the same command\n"
                 "finished in DIR (their EXRs) instead of rendering them"),
    CLI_FLAG_OPT("--force", A.force,
                 "DIR holds another run's outputs: remove them first\n"
                 "(fluidsurf's own files only; without it compare refuses)"),
    CLI_STRING_OPT("--shard", A.shard, "K/N",
                   "render only shard K's share of the work items (K = 1..N),\n"
                   "into DIR with a manifest and a DONE marker; 'fluidsurf merge'\n"
                   "joins the N shards' folders into this command's outputs"),
    CLI_FLAG_OPT("--counters", A.counters,
                 "also count each variant's and reference's work in a\n"
                 "separate render after the timed ones: counters.csv"),
    CLI_OPT_SIZE(A.w, A.h, 1, 16384, "image", "the camera's, else the scene's, else 512"),
    CLI_OPT_RADIUS(A.radius,
                   "the scene's, else the file's, else estimated from\n"
                   "the particle spacing (a note says so; fluidsurf info shows it)"),
    CLI_OPT_SCENE(A.field),
    CLI_OPT_CAMERA(A.camera, A.camera_from),
    CLI_OPT_FRAMES(A.frames),
    CLI_OPT_GL(A.ctx_kind),
    CLI_OPT_REQUIRE_GPU(A.require_gpu),
    CLI_OPT_QUIET(A.quiet),
    CLI_END,
};

static const cli_command cmd = {"compare",
                                "SCENE.json|PARTICLES -o DIR [options]",
                                opts,
                                {&A.input, NULL, 1, "more than one input ('%s' and '%s')"},
                                epilogue};

/* The GL context of the variants that need one (study_dir.h): the command's own. */
typedef struct cli_gl {
    fs_ctx_kind kind;
    fs_gl_context ctx;
} cli_gl;

static int gl_acquire(void *user, const fs_gl_context **ctx)
{
    cli_gl *g = user;
    int rc = cli_gl_context_create(&g->ctx, g->kind, 16, 16);
    *ctx = rc ? NULL : &g->ctx;
    return rc;
}

static void gl_release(void *user) { fs_gl_context_destroy(&((cli_gl *)user)->ctx); }

/* The options that need one another. */
static int check_args(const compare_args *a)
{
    if (!a->input) return cli_usage("compare", "no scene or particle file given");
    if (!a->out) return cli_usage("compare", "no output folder given (-o DIR)");
    if (a->no_cache && a->cache_dir) return cli_usage("compare", "--cache and --no-cache: choose one");
    if (a->resume && a->force) return cli_usage("compare", "--resume and --force: choose one");
    if (strlen(a->out) >= FS_STUDY_DIR_MAX) return cli_usage("compare", "output folder path too long");
    return FS_OK;
}

/* The study planned from the command line, run into its folder. */
static int compare(fs_study *s, int argc, char **argv, fs_merge *m)
{
    static char command[4096];
    cli_gl gl = {.kind = A.ctx_kind};
    fs_study_dir_opts o = {A.out, command, argc,        argv,        A.radius, A.resume, A.force,    A.quiet,    0,
                           0,     m,       A.cache_dir, !A.no_cache, A.nscale, A.dscale, gl_acquire, gl_release, &gl};
    compare_quote_command(command, sizeof command, argc, argv);
    int rc = compare_plan(s, &A);
    if (rc) return rc;
    if (A.shard && (rc = fs_shard_parse(A.shard, &o.shard_k, &o.shard_n))) return cli_error(rc);
    rc = fs_study_dir_run(s, &o);
    return rc ? cli_error(rc) : FS_OK;
}

/* compare's command line; with m, the merge of m's shards into m's staging folder. */
static int compare_main(int argc, char **argv, fs_merge *m)
{
    memset(&A, 0, sizeof A);
    A.repeat = 3, A.field = (cli_scene_opts)CLI_SCENE_OPTS_UNSET, A.ctx_kind = fs_gl_context_default_kind();
    int rc = cli_parse(&cmd, argc, argv);
    if (rc != CLI_GO_ON) return rc;
    fs_note_quiet(A.quiet);
    fs_gl_context_require_gpu(A.require_gpu);
    if ((rc = check_args(&A))) return rc;
    static fs_study s; /* large: the plan and its results */
    memset(&s, 0, sizeof s);
    rc = compare(&s, argc, argv, m);
    fs_study_free(&s);
    return rc;
}

int cmd_compare(int argc, char **argv) { return compare_main(argc, argv, NULL); }

int compare_merged(int argc, char **argv, fs_merge *m)
{
    int rc = compare_main(argc, argv, m);
    if (rc) fs_merge_publish(m, 0); /* whatever stage failed, nothing stays behind */
    return rc;
}
