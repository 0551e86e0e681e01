/* render_bench: one method's stage times on one particle set at several image
 * sizes and parameter variants, the set loaded (or generated) once, so a large
 * synthetic set costs its generation once per process, not once per cell.
 *
 *   render_bench SCENE.json LABEL METHOD SIZES RUNS [VARIANT ...]
 *   render_bench --probe
 *   render_bench --limits
 *
 * SIZES: comma list of square image sizes ("512,1024"). VARIANT: ';'-joined
 * "method.param=value" settings on top of the scene's ("-" or none: the
 * defaults). Per variant the method is opened and the frame uploaded (stages
 * grid and upload, run 0); per size one untimed warm-up render (shader
 * compilation, target allocation), then RUNS timed renders. Only the method's
 * own stages are timed: no shading, no file output, and the layers of a
 * method's own look are left out (fs_run_shared_only). Prints CSV rows without a
 * header, each flushed at once (so a run cut short by a time limit keeps its
 * finished rows):
 *   label,particles,method,variant,size,run,stage,ms,gpu_ms,gl_renderer,gl_version
 * ms: wall clock between glFinish calls; gpu_ms: the GL clock (gl_stage.h),
 * empty for CPU stages. --probe prints the default context's GL_RENDERER and
 * GL_VERSION on two lines; --limits the context's value of every GL limit fluidsurf
 * relies on, as CSV "limit,value,need,what" (gl_limits.h). With RENDER_BENCH_PNG=PREFIX, the last render of each
 * variant and size is shaded and written to PREFIX_<variant>_<size>.png, to look
 * at what was timed; RENDER_BENCH_PNG_SIZE=N writes it for size N only, and
 * RENDER_BENCH_PNG_MAX=M shrinks it to at most M pixels a side (png_small.h). */
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "gl_limits.h"
#include "image_io.h"
#include "png_small.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "study.h"
#include "scene.h"
#include "timing.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct bench {
    const char *label, *variant;
    const fs_method *m;
    const fs_particles *p;
    const fs_gl_context *ctx;
} bench;

static int die(const char *what)
{
    fprintf(stderr, "render_bench: %s: %s\n", what, fs_error_message());
    return 1;
}

static void rows(const bench *b, const fs_run *run, int size, int r, const fs_stages *st)
{
    for (int i = 0; i < st->n; i++) {
        printf("%s,%zu,%s,\"%s\",%d,%d,%s,%.3f,", b->label, b->p->n, b->m->name, b->variant, size, r, st->name[i],
               st->ms[i]);
        if (!isnan(st->gpu_ms[i])) printf("%.3f", st->gpu_ms[i]);
        printf(",\"%s\",\"%s\"\n", fs_run_stage_renderer(run, st->name[i]), b->ctx ? b->ctx->version : "");
    }
    fflush(stdout);
}

static int write_png(fs_run *run, const fs_camera *cam, fs_run_image *im, const char *variant, int size)
{
    const char *prefix = getenv("RENDER_BENCH_PNG"), *only = getenv("RENDER_BENCH_PNG_SIZE"),
               *max = getenv("RENDER_BENCH_PNG_MAX");
    if (!prefix || (only && atoi(only) != size)) return FS_OK;
    char path[1200], v[256];
    snprintf(v, sizeof v, "%s", variant);
    for (char *c = v; *c; c++)
        if (!strchr("abcdefghijklmnopqrstuvwxyz0123456789_.-", *c)) *c = '_';
    snprintf(path, sizeof path, "%s_%s_%d.png", prefix, v, size);
    int rc = fs_run_shade(run, cam, im, FS_APPEARANCE_SHARED, NULL);
    return rc ? rc : fs_write_png_small(path, im->rgba, size, size, max ? atoi(max) : size);
}

/* One size: a warm-up render, then runs timed ones (fs_study_time_renders), one row per run and stage. */
static int bench_size(const bench *b, fs_run *run, const fs_scene *base, int size, int runs)
{
    static fs_scene s; /* large: not on the stack */
    s = *base;
    s.camera.width = s.camera.height = size;
    char note[1024];
    fs_scene_adopt_frame(&s, b->p, 0, note, sizeof note);
    fs_run_image im = {0};
    static fs_stages st[FS_STUDY_MAX_RUNS];
    double median;
    int rc = fs_study_time_renders(run, &s.camera, &im, runs, st, &median); /* the study's protocol */
    for (int r = 1; !rc && r <= runs; r++) rows(b, run, size, r, &st[r - 1]);
    if (!rc) rc = write_png(run, &s.camera, &im, b->variant, size);
    fs_run_image_free(&im);
    return rc;
}

/* One variant: its settings on a copy of the scene, the run, every size. */
static int bench_variant(bench *b, const fs_scene *scene, const char *sizes, int runs)
{
    static fs_scene s;
    s = *scene;
    char sets[1024];
    snprintf(sets, sizeof sets, "%s", b->variant);
    for (char *set = strtok(sets, ";"); set; set = strtok(NULL, ";"))
        if (strcmp(set, "-") && fs_scene_add_set(&s, set)) return die(set);
    fs_run *run = NULL;
    fs_stages st = {0};
    int rc = fs_run_open(&run, b->m, &s, NULL, b->ctx);
    if (!rc) fs_run_shared_only(run, 1); /* no EXR, the shared shading: the own image is neither drawn nor read */
    if (!rc) rc = fs_run_upload(run, b->p, NULL, &st);
    if (!rc) rows(b, run, 0, 0, &st);
    char list[512];
    snprintf(list, sizeof list, "%s", sizes);
    for (char *tok = list, *next; !rc && tok && *tok; tok = next) {
        next = strchr(tok, ',');
        if (next) *next++ = 0;
        int size = atoi(tok);
        rc = size > 0 && size <= 8192 ? bench_size(b, run, &s, size, runs) : fs_fail(FS_ERR_INPUT, "size '%s'", tok);
    }
    fs_run_close(run);
    return rc ? die(b->variant) : 0;
}

static int probe(void)
{
    fs_gl_context ctx;
    if (fs_gl_context_create(&ctx, fs_gl_context_default_kind(), 16, 16)) return die("OpenGL");
    printf("%s\n%s\n", ctx.renderer, ctx.version);
    fs_gl_context_destroy(&ctx);
    return 0;
}

/* The driver's value of each limit beside fluidsurf's need (docs/DESIGN.md, "GL limits"). */
static int limits(void)
{
    fs_gl_context ctx;
    if (fs_gl_context_create(&ctx, fs_gl_context_default_kind(), 16, 16)) return die("OpenGL");
    int n = 0;
    const fs_gl_limit *t = fs_gl_limits(&n);
    long long *have = malloc(n * sizeof *have);
    if (!have) return die("out of memory");
    fs_gl_limits_query(have);
    printf("limit,value,need,what\n");
    for (int i = 0; i < n; i++) printf("%s,%lld,%lld,\"%s\"\n", t[i].name, have[i], t[i].need, t[i].what);
    free(have);
    fs_gl_context_destroy(&ctx);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "--probe")) return probe();
    if (argc == 2 && !strcmp(argv[1], "--limits")) return limits();
    if (argc < 6) {
        fprintf(stderr, "usage: render_bench SCENE.json LABEL METHOD SIZES RUNS [VARIANT ...] | --probe | --limits\n");
        return 2;
    }
    fs_methods_register_builtin();
    bench b = {argv[2], "-", fs_method_find(argv[3]), NULL, NULL};
    int runs = atoi(argv[5]);
    if (!b.m || runs < 1) {
        fprintf(stderr, "render_bench: unknown method '%s' or bad RUNS '%s'\n", argv[3], argv[5]);
        return 2;
    }
    static fs_scene scene;
    fs_particles p;
    double t0 = fs_now_ms();
    if (fs_scene_load(&scene, argv[1]) || fs_scene_load_frame(&scene, 0, &p)) return die(argv[1]);
    char note[1024];
    fs_scene_adopt_frame(&scene, &p, 0, note, sizeof note);
    if (note[0]) fprintf(stderr, "render_bench: note: %s\n", note);
    b.p = &p;
    fs_gl_context ctx = {0};
    if (b.m->needs_gl && fs_gl_context_create(&ctx, fs_gl_context_default_kind(), 16, 16)) return die("OpenGL");
    b.ctx = b.m->needs_gl ? &ctx : NULL;
    printf("%s,%zu,%s,\"\",0,0,load,%.3f,,\"CPU\",\"%s\"\n", b.label, p.n, b.m->name, fs_now_ms() - t0, ctx.version);
    static char *const defaults[] = {"-"};
    char *const *variants = argc > 6 ? argv + 6 : defaults;
    int nvariants = argc > 6 ? argc - 6 : 1, rc = 0;
    for (int v = 0; !rc && v < nvariants; v++) {
        b.variant = variants[v];
        rc = bench_variant(&b, &scene, argv[4], runs);
    }
    if (b.m->needs_gl) fs_gl_context_destroy(&ctx);
    fs_particles_free(&p);
    return rc;
}
