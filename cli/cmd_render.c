#include "cli.h"
#include "counters_csv.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "options.h"
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

/* Loads the frame (timed as "load"), settles r and the camera, runs the job. */
static int load_and_render(fs_scene *scene, const render_job *job, float radius, fs_ctx_kind kind)
{
    fs_particles p;
    fs_stages st = {0};
    double tl = fs_now_ms();
    if (radius > 0) scene->radius = radius; /* before a synthetic scene is generated */
    int rc = fs_scene_load_frame(scene, job->frame, &p);
    if (rc) return cli_error(rc);
    fs_stages_add(&st, "load", fs_now_ms() - tl);
    char note[1024];
    fs_scene_adopt_frame(scene, &p, radius, note, sizeof note);
    fs_progress_begin("render", "frames", 1);
    rc = render_one(scene, &p, job, kind, &st);
    if (!rc) fs_progress_item(job->m->name);
    fs_progress_end();
    /* after success only, so a failing run prints exactly one line */
    if (!rc && note[0]) fs_note("%s", note);
    if (rc) cli_error(rc);
    fs_particles_free(&p);
    return rc;
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

int cmd_render(int argc, char **argv)
{
    const char *input = NULL, *out = NULL, *mname = "reference", *format = NULL, *cache_dir = NULL;
    int w = 0, h = 0, frame = -1, timings = 0, counters = 0, quiet = 0, own_look = 0, require_gpu = 0, rc;
    float radius = 0;
    cli_scene_opts sopts = CLI_SCENE_OPTS_UNSET;
    fs_ctx_kind ctx_kind = fs_gl_context_default_kind();
    static fs_scene scene;
    const char *sets[FS_MAX_SETS], *exports[4];
    int nsets = 0, nexports = 0;
    const cli_opt opts[] = {
        CLI_STRING_OPT("--method", mname, "NAME", "method to run (fluidsurf methods lists them); default reference"),
        CLI_OPT_OUT(out, "OUT.png|OUT.exr", "the image: PNG, or EXR with the G-buffer and provenance"),
        CLI_OPT_SET(sets, nsets),
        CLI_OPT_SIZE(w, h, 1, 16384, "image", "the scene's, else 512"),
        CLI_OPT_RADIUS(radius,
                       "the scene's, else the file's, else estimated from\n"
                       "the particle spacing (a note says so; fluidsurf info shows it)"),
        CLI_OPT_SCENE(sopts),
        CLI_STRING_OPT("--format", format, "FMT", "particle file format (default: from the extension)"),
        CLI_INT_OPT("--frame", frame, 0, 100000000, "N", "frame of a sequence scene (default: its first)"),
        CLI_OPT_GL(ctx_kind),
        CLI_OPT_REQUIRE_GPU(require_gpu),
        CLI_FLAG_OPT("--timings", timings, "print per-stage times and the renderer they ran on"),
        CLI_FLAG_OPT("--counters", counters,
                     "print per-stage work counts (CSV) of a separate counting\n"
                     "render after the timed one"),
        CLI_LIST_OPT("--export", exports, nexports, 4, "FILE",
                     "write the method's intermediate surface too (repeatable;\n"
                     "the kinds a method writes: fluidsurf methods NAME);\n"
                     "-o is then optional"),
        CLI_CHOICE_OPT("--appearance", own_look, "shared|own", NULL,
                       "shared (default): the harness's shading, the same for\n"
                       "every method; own: the method's own, where its paper\n"
                       "defines one (fluidsurf methods NAME says)"),
        CLI_OPT_CACHE(cache_dir,
                      "read and write the reference's G-buffer in this cache\n"
                      "folder, as compare does (default: no cache)"),
        CLI_OPT_QUIET(quiet),
        CLI_END,
    };
    const cli_command cmd = {"render",
                             "SCENE.json|PARTICLES --method NAME -o OUT.png|OUT.exr [options]",
                             opts,
                             {&input, NULL, 1, "more than one input ('%s' and '%s')"},
                             epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_note_quiet(quiet);
    fs_gl_context_require_gpu(require_gpu);
    if (!input) return cli_usage("render", "no scene or particle file given");
    if (!out && !nexports) return cli_usage("render", "no output given (-o OUT.png|OUT.exr)");
    const fs_method *m = fs_method_find(mname);
    if (!m) return cli_unknown_method("render", "--method", mname);
    if ((rc = check_outputs(m, input, out, exports, nexports, own_look))) return rc;
    if ((rc = check_cache(m, cache_dir, out))) return rc;
    if (counters && (rc = fs_run_check_counters(m))) return cli_error(rc);
    if ((rc = cli_scene_from_arg(&scene, input))) return cli_error(rc);
    cli_scene_opts_apply(&scene, &sopts);
    if (format && strlen(format) < sizeof scene.format) strcpy(scene.format, format);
    for (int i = 0; i < nsets; i++)
        if ((rc = fs_scene_add_set(&scene, sets[i]))) return cli_error(rc);
    if (w) scene.camera.width = w;
    if (h) scene.camera.height = h;
    if ((long)scene.camera.width * scene.camera.height > 16384L * 16384L / 4)
        return cli_usage("render", "%dx%d pixels is too large", scene.camera.width, scene.camera.height);
    double params[FS_MAX_PARAMS];
    if ((rc = fs_method_params_resolve(m, &scene, params))) return cli_error(rc);
    int first;
    if ((rc = frame_to_render(&scene, frame, &first))) return rc;
    static fs_ref_cache cache;
    if (cache_dir) fs_ref_cache_open(&cache, cache_dir, 0, quiet);
    cache.counters = counters;
    const render_job job = {m,
                            params,
                            first,
                            out,
                            exports,
                            nexports,
                            own_look ? FS_APPEARANCE_OWN : FS_APPEARANCE_SHARED,
                            timings,
                            counters,
                            cache_dir ? &cache : NULL};
    return load_and_render(&scene, &job, radius, ctx_kind);
}
