#include "cli.h"
#include "counters_csv.h"
#include "frame_pattern.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "options.h"
#include "output_file.h"
#include "progress.h"
#include "ref_cache.h"
#include "render_output.h"
#include "run.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* what --help says after the options */
static const char epilogue[] = "EXR output holds R G B A depth normal.X/Y/Z thickness coverage, the AOVs the method\n"
                               "writes (fluidsurf methods lists them) and the provenance. Depth is 0 where coverage\n"
                               "is 0 (fluidsurf:empty_depth), so OpenImageIO's idiff reports finite numbers.\n";

/* What to do with the loaded frame. */
typedef struct render_job {
    const fs_method *m;
    const double *params;
    int frame;
    const char *out; /* NULL: exports only */
    const char *const *exports;
    int nexports;
    fs_appearance look;
    int timings;         /* print the stage times */
    int counters;        /* print the work counts of a counting render */
    fs_ref_cache *cache; /* --cache: the reference's view from it; NULL: none */
} render_job;

static void print_timings(const fs_run *run, const fs_stages *st)
{
    printf("stage,ms,gpu_ms,renderer\n"); /* gpu_ms: the GL clock, empty for CPU stages */
    for (int i = 0; i < st->n; i++) {
        printf("%s,%.3f,", st->name[i], st->ms[i]);
        if (!isnan(st->gpu_ms[i])) printf("%.3f", st->gpu_ms[i]);
        printf(",%s\n", fs_run_stage_renderer(run, st->name[i]));
    }
}

/* The counts as CSV on stdout, under the provenance comment line. */
static void print_counters(const fs_run *run, const render_job *job, const fs_stages *counts)
{
    fs_provenance prov;
    char line[8192];
    fs_run_provenance(run, NULL, job->frame, &prov);
    fs_provenance_line(&prov, line, sizeof line);
    printf("%s\n" FS_COUNTERS_HEADER, line);
    fs_counters_rows(stdout, job->m->name, "", job->frame, counts, job->m->counters);
}

/* The reference's view from the cache, or rendered and stored; the output file. */
static int run_cached(fs_run *run, const fs_scene *scene, const fs_particles *p, const render_job *job, fs_stages *st,
                      fs_stages *counts)
{
    fs_run_image im = {0};
    fs_provenance prov;
    fs_study_made made;
    int rc = fs_ref_cache_render(job->cache, run, scene, p, NULL, NULL, job->frame, &im, st, &made);
    if (!rc && job->counters) *counts = made.counts;
    fs_run_provenance(run, NULL, job->frame, &prov);
    if (!rc) rc = fs_write_render_in_scene(job->out, scene, &scene->camera, &im.g, im.rgba, &prov);
    if (!rc && made.hit && !job->cache->quiet)
        fprintf(stderr, "fluidsurf: note: %s from the cache, %s\n", job->m->name, made.entry);
    fs_run_image_free(&im);
    return rc;
}

/* Runs the method on one frame: exports, render, shading, the output file. */
static int run_job(fs_run *run, const fs_scene *scene, const fs_particles *p, const render_job *job, fs_stages *st,
                   fs_stages *counts)
{
    if (job->cache && job->cache->on) return run_cached(run, scene, p, job, st, counts);
    int rc = fs_run_upload(run, p, NULL, st);
    fs_run_image im = {0};
    fs_provenance prov;
    fs_run_provenance(run, NULL, job->frame, &prov);
    for (int i = 0; !rc && i < job->nexports; i++) rc = fs_run_export(run, job->exports[i], &prov);
    if (rc || !job->out) return rc;
    rc = fs_run_render(run, &scene->camera, &im, st);
    if (!rc) rc = fs_run_shade(run, &scene->camera, &im, job->look, st);
    if (!rc) rc = fs_write_render_in_scene(job->out, scene, &scene->camera, &im.g, im.rgba, &prov);
    fs_run_image_free(&im);
    return rc;
}

/* A GL context when the method needs one, the run, the job. */
static int render_one(const fs_scene *scene, const fs_particles *p, const render_job *job, fs_ctx_kind kind,
                      fs_stages *st)
{
    fs_gl_context ctx = {0};
    fs_run *run = NULL;
    fs_stages counts = {0};
    int cached = job->cache && job->cache->on;
    int rc = job->m->needs_gl ? cli_gl_context_create(&ctx, kind, 16, 16) : FS_OK;
    if (!rc) rc = fs_run_open(&run, job->m, scene, job->params, job->m->needs_gl ? &ctx : NULL);
    if (!rc) rc = run_job(run, scene, p, job, st, &counts);
    if (!rc && job->counters && !cached) { /* after the timed render, same inputs (docs/DESIGN.md, "Work counters") */
        fs_run_image im = {0};
        rc = fs_run_count(job->m, scene, job->params, job->m->needs_gl ? &ctx : NULL, p, NULL, &scene->camera, &im,
                          &counts);
        fs_run_image_free(&im);
    }
    if (!rc && job->timings) print_timings(run, st);
    if (!rc && job->counters) print_counters(run, job, &counts);
    fs_run_close(run);
    if (job->m->needs_gl) fs_gl_context_destroy(&ctx);
    return rc;
}

/* The outputs asked for fit the method and overwrite no input. */
static int check_outputs(const fs_method *m, const char *input, const char *out, const char *const *exports,
                         int nexports, int own_look)
{
    int rc;
    if (out && (rc = fs_check_render_path(out))) return cli_error(rc);
    if (nexports && !m->export_file) return cli_usage("render", "--export: method '%s' exports nothing", m->name);
    for (int i = 0; i < nexports; i++)
        if (cli_same_file(input, exports[i]))
            return cli_usage("render", "%s: export would overwrite the input", exports[i]);
    if (own_look && !fs_method_aov(m, FS_AOV_OWN))
        return cli_usage("render", "--appearance own: method '%s' has no own appearance (only the shared shading)",
                         m->name);
    if (out && cli_same_file(input, out)) return cli_usage("render", "%s: output would overwrite the input", out);
    return FS_OK;
}

/* The command line's outputs and frames, for render_frames. */
typedef struct render_plan {
    const char *out, *const *exports, *save_scene;
    int nexports;
    int first, count; /* the frames: first alone, or count of the scene's */
    float radius;
    fs_ctx_kind kind;
} render_plan;

/* --frame N (-1: the scene's first) checked against the scene's frames. */
static int frame_to_render(const fs_scene *scene, int frame, int *first)
{
    int last;
    fs_scene_frames(scene, first, &last);
    if (frame < 0) return FS_OK;
    if (scene->frame_first < 0 && !scene->synth.shape)
        return cli_usage("render", "--frame: the scene is not a sequence");
    if (scene->frame_first >= 0 && (frame < scene->frame_first || frame > scene->frame_last))
        return cli_usage("render", "--frame %d: the scene has frames %d..%d", frame, scene->frame_first,
                         scene->frame_last);
    *first = frame;
    return FS_OK;
}

/* The input's frames: a pattern's --frames (each rendered; a pattern with
 * --frame N alone is that frame), else one frame, --frame N or the first. */
static int frames_to_render(fs_scene *scene, const char *input, const char *frames, int frame, render_plan *pl)
{
    char one[40];
    if (frames && frame >= 0) return cli_usage("render", "--frame and --frames: choose one");
    /* a pattern with --frame N alone is frames N:N; a scene file's --frame is checked below */
    if (!frames && frame >= 0 && fs_is_frame_pattern(input)) {
        snprintf(one, sizeof one, "%d:%d", frame, frame);
        frames = one;
    }
    int rc = cli_scene_pattern("render", scene, input, frames);
    if (rc) return rc;
    pl->count = frames ? fs_scene_frame_count(scene) : 1;
    if (frames) pl->first = fs_scene_frame_number(scene, 0);
    if (pl->count > 1 && pl->out && !fs_is_frame_pattern(pl->out))
        return cli_usage("render", "%s: %d frames need {} or %%04d in -o", pl->out, pl->count);
    for (int i = 0; pl->count > 1 && i < pl->nexports; i++)
        if (!fs_is_frame_pattern(pl->exports[i]))
            return cli_usage("render", "%s: %d frames need {} or %%04d in --export", pl->exports[i], pl->count);
    return frames ? FS_OK : frame_to_render(scene, frame, &pl->first);
}

/* Loads the frame (timed as "load"), on the first frame settles r and the
 * camera, runs the job. */
static int load_and_render(fs_scene *scene, const render_job *job, float radius, fs_ctx_kind kind, int first)
{
    fs_particles p;
    fs_stages st = {0};
    double tl = fs_now_ms();
    if (first && radius > 0) scene->radius = radius; /* before a synthetic scene is generated */
    int rc = fs_scene_load_frame(scene, job->frame, &p);
    if (rc) return cli_error(rc);
    fs_stages_add(&st, "load", fs_now_ms() - tl);
    char note[1024] = "";
    if (first) fs_scene_adopt_frame(scene, &p, radius, note, sizeof note);
    rc = render_one(scene, &p, job, kind, &st);
    /* after success only, so a failing run prints exactly one line */
    if (!rc && note[0]) fs_note("%s", note);
    if (rc) cli_error(rc);
    fs_particles_free(&p);
    return rc;
}

/* name for frame f: a pattern's frame ({} or %d), else name itself. */
static int frame_output(const char *name, int f, char *buf, int size)
{
    char pat[4096];
    int rc = fs_is_frame_pattern(name) ? fs_frame_pattern(name, pat, sizeof pat) : FS_OK;
    if (rc) return rc;
    if (fs_is_frame_pattern(name)) return fs_frame_path(buf, size, pat, f);
    if ((int)strlen(name) >= size) return fs_fail(FS_ERR_INPUT, "%s: path too long", name);
    strcpy(buf, name);
    return FS_OK;
}

/* The scene as rendered, as a scene file: one frame of a sequence becomes the
 * scene's only frame, so the file renders that frame. */
static int save_scene(const fs_scene *scene, const render_plan *pl)
{
    static fs_scene copy;
    copy = *scene;
    if (pl->count == 1 && (copy.frame_first >= 0 || pl->first > 0))
        copy.frame_first = copy.frame_last = pl->first, copy.frame_step = 1;
    int rc = fs_scene_save(&copy, pl->save_scene);
    return rc ? cli_error(rc) : FS_OK;
}

/* Each frame through load_and_render into its outputs, then the scene file. */
static int render_frames(fs_scene *scene, render_job *job, const render_plan *pl)
{
    static char out[4096], ex[4][4096];
    const char *exv[4];
    int rc = FS_OK;
    fs_progress_begin("render", "frames", pl->count);
    for (int k = 0; k < pl->count && !rc; k++) {
        job->frame = pl->count > 1 ? fs_scene_frame_number(scene, k) : pl->first;
        if (pl->out) rc = frame_output(pl->out, job->frame, out, sizeof out);
        for (int i = 0; i < pl->nexports && !rc; i++)
            rc = frame_output(pl->exports[i], job->frame, ex[i], sizeof ex[i]);
        for (int i = 0; i < pl->nexports; i++) exv[i] = ex[i];
        job->out = pl->out ? out : NULL, job->exports = exv;
        if (rc) return cli_error(rc);
        rc = load_and_render(scene, job, pl->radius, pl->kind, k == 0);
        char what[32];
        snprintf(what, sizeof what, "frame %d", job->frame);
        if (!rc) fs_progress_item(pl->count > 1 ? what : job->m->name);
    }
    fs_progress_end();
    return !rc && pl->save_scene ? save_scene(scene, pl) : rc;
}

/* --cache DIR: only the reference is cached, and only into a file output. */
static int check_cache(const fs_method *m, const char *dir, const char *out)
{
    if (!dir) return FS_OK;
    if (m != fs_method_find("reference"))
        return cli_usage("render", "--cache: only the reference method is cached, not '%s'", m->name);
    if (!out) return cli_usage("render", "--cache needs an output (-o OUT.png|OUT.exr)");
    return FS_OK;
}

/* What the command line gives. */
typedef struct render_args {
    const char *input, *out, *mname, *format, *cache_dir, *camera, *camera_from, *save_scene, *frames;
    const char *sets[FS_MAX_SETS], *exports[4];
    int nsets, nexports, w, h, frame, timings, counters, quiet, own_look, require_gpu;
    float radius;
    cli_scene_opts sopts;
    fs_ctx_kind ctx_kind;
} render_args;

/* The option table over a; CLI_GO_ON, or the exit status. */
static int parse_args(int argc, char **argv, render_args *a)
{
    const cli_opt opts[] = {
        CLI_STRING_OPT("--method", a->mname, "NAME", "method to run (fluidsurf methods lists them); default reference"),
        CLI_OPT_OUT(a->out, "OUT.png|OUT.exr",
                    "the image: PNG, or EXR with the G-buffer and provenance\n"
                    "(with several --frames, {} or %04d for the frame number)"),
        CLI_OPT_SET(a->sets, a->nsets),
        CLI_OPT_SIZE(a->w, a->h, 1, 16384, "image", "the camera's, else the scene's, else 512"),
        CLI_OPT_RADIUS(a->radius,
                       "the scene's, else the file's, else estimated from\n"
                       "the particle spacing (a note says so; fluidsurf info shows it)"),
        CLI_OPT_SCENE(a->sopts),
        CLI_OPT_CAMERA(a->camera, a->camera_from),
        CLI_STRING_OPT("--save-scene", a->save_scene, "FILE.json",
                       "also write the scene as rendered (r, up axis, camera\n"
                       "settled) as a scene file that renders the same image"),
        CLI_STRING_OPT("--format", a->format, "FMT", "particle file format (default: from the extension)"),
        CLI_INT_OPT("--frame", a->frame, 0, 100000000, "N",
                    "frame of a sequence scene or pattern (default: its first)"),
        CLI_OPT_FRAMES(a->frames),
        CLI_OPT_GL(a->ctx_kind),
        CLI_OPT_REQUIRE_GPU(a->require_gpu),
        CLI_FLAG_OPT("--timings", a->timings, "print per-stage times and the renderer they ran on"),
        CLI_FLAG_OPT("--counters", a->counters,
                     "print per-stage work counts (CSV) of a separate counting\n"
                     "render after the timed one"),
        CLI_LIST_OPT("--export", a->exports, a->nexports, 4, "FILE",
                     "write the method's intermediate surface too (repeatable;\n"
                     "the kinds a method writes: fluidsurf methods NAME);\n"
                     "-o is then optional"),
        CLI_CHOICE_OPT("--appearance", a->own_look, "shared|own", NULL,
                       "shared (default): the harness's shading, the same for\n"
                       "every method; own: the method's own, where its paper\n"
                       "defines one (fluidsurf methods NAME says)"),
        CLI_OPT_CACHE(a->cache_dir,
                      "read and write the reference's G-buffer in this cache\n"
                      "folder, as compare does (default: no cache)"),
        CLI_OPT_QUIET(a->quiet),
        CLI_END,
    };
    const cli_command cmd = {"render",
                             "SCENE.json|PARTICLES --method NAME -o OUT.png|OUT.exr [options]",
                             opts,
                             {&a->input, NULL, 1, "more than one input ('%s' and '%s')"},
                             epilogue};
    return cli_parse(&cmd, argc, argv);
}

/* --save-scene: a .json beside which the scene file can be written, not the input. */
static int check_save_scene(const render_args *a)
{
    const char *f = a->save_scene;
    if (!f) return FS_OK;
    if (!fs_path_ends_with(f, ".json"))
        return cli_usage("render", "--save-scene %s: the scene file must end in .json", f);
    if (cli_same_file(a->input, f)) return cli_usage("render", "--save-scene %s: would overwrite the input", f);
    return FS_OK;
}

/* The checks that need no scene: an input, an output, the method, the outputs' names. */
static int check_args(const render_args *a, const fs_method **m)
{
    int rc;
    if (!a->input) return cli_usage("render", "no scene or particle file given");
    if (!a->out && !a->nexports) return cli_usage("render", "no output given (-o OUT.png|OUT.exr)");
    if (!(*m = fs_method_find(a->mname))) return cli_unknown_method("render", "--method", a->mname);
    if ((rc = check_outputs(*m, a->input, a->out, a->exports, a->nexports, a->own_look))) return rc;
    if ((rc = check_cache(*m, a->cache_dir, a->out))) return rc;
    if ((rc = check_save_scene(a))) return rc;
    return a->counters && (rc = fs_run_check_counters(*m)) ? cli_error(rc) : FS_OK;
}

/* The scene of the input with the command line's field, settings, camera and size. */
static int scene_of(const render_args *a, fs_scene *scene)
{
    int rc = cli_scene_from_arg(scene, a->input);
    if (rc) return cli_error(rc);
    cli_scene_opts_apply(scene, &a->sopts);
    if (a->format && strlen(a->format) < sizeof scene->format) strcpy(scene->format, a->format);
    for (int i = 0; i < a->nsets; i++)
        if ((rc = fs_scene_add_set(scene, a->sets[i]))) return cli_error(rc);
    if ((rc = cli_scene_camera("render", scene, a->camera, a->camera_from))) return rc;
    if (a->w) scene->camera.width = a->w;
    if (a->h) scene->camera.height = a->h;
    if ((long)scene->camera.width * scene->camera.height > 16384L * 16384L / 4)
        return cli_usage("render", "%dx%d pixels is too large", scene->camera.width, scene->camera.height);
    return FS_OK;
}

int cmd_render(int argc, char **argv)
{
    static render_args a;
    memset(&a, 0, sizeof a);
    a.mname = "reference", a.frame = -1, a.sopts = (cli_scene_opts)CLI_SCENE_OPTS_UNSET;
    a.ctx_kind = fs_gl_context_default_kind();
    int rc;
    if ((rc = parse_args(argc, argv, &a)) != CLI_GO_ON) return rc;
    fs_note_quiet(a.quiet);
    fs_gl_context_require_gpu(a.require_gpu);
    const fs_method *m = NULL;
    static fs_scene scene;
    if ((rc = check_args(&a, &m)) || (rc = scene_of(&a, &scene))) return rc;
    double params[FS_MAX_PARAMS];
    if ((rc = fs_method_params_resolve(m, &scene, params))) return cli_error(rc);
    if ((rc = cli_sets_run(a.sets, a.nsets, &m, 1))) return cli_error(rc);
    render_plan pl = {a.out, a.exports, a.save_scene, a.nexports, 0, 1, a.radius, a.ctx_kind};
    if ((rc = frames_to_render(&scene, a.input, a.frames, a.frame, &pl))) return rc;
    static fs_ref_cache cache;
    if (a.cache_dir) fs_ref_cache_open(&cache, a.cache_dir, 0, a.quiet);
    cache.counters = a.counters;
    render_job job = {m,
                      params,
                      pl.first,
                      NULL,
                      NULL,
                      a.nexports,
                      a.own_look ? FS_APPEARANCE_OWN : FS_APPEARANCE_SHARED,
                      a.timings,
                      a.counters,
                      a.cache_dir ? &cache : NULL};
    return render_frames(&scene, &job, &pl);
}
