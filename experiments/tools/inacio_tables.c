/* inacio_tables: the per-frame stage times of inacio2010's Tables I and II on the
 * SPH dam break, simulator and renderers in one GL context (as in the paper's
 * prototype and in `fluidsurf view --simulate`).
 *
 *   inacio_tables PARTICLES cpu|gpu [SETTLE [FRAMES [SIZE [GRID [LIMIT_S]]]]]
 *
 * Creates the dam break with about PARTICLES fluid particles (Tait, r = 0.025,
 * the simulator's defaults) on the CPU path (C + OpenMP) or the GPU path
 * (compute shaders on the context), advances SETTLE frames of 1/60 s untimed
 * (default 6; the first is timed against LIMIT_S, default 60 s: a cell whose first
 * frame takes longer prints one "skipped" row and stops), renders one untimed
 * warm-up image with each method (shader compilation), then FRAMES timed frames
 * (default 3). Per timed frame:
 *   simulation  fs_sph_advance(1/60 s) (adaptive steps; glFinish on the GPU path)
 *   fetch       fs_sph_get: the state into host arrays (GPU path: a read-back)
 *   Table I, volume_raycast (build=layered, grid_res GRID (default 128),
 *            thickness=off: rays stop at the surface): volume, faces, march,
 *            readback (G-buffer to the host), shade (the shared shading, C)
 *   Table II, spheres (thickness=off: opaque spheres): upload (particles into
 *            the GL buffers), splat, readback, shade
 *   I_slice, volume_raycast with build=slice (iwasaki2006's multi-pass slice
 *            splatting, then the upload into the 3D texture), for its volume stage
 *            (the other stages as Table I)
 * SIZE x SIZE pixels (default 512); the camera frames the container.
 * Prints CSV rows without a header:
 *   particles_requested,particles,boundary,path,sim_renderer,gl_renderer,frame,t,steps,table,stage,ms,gpu_ms,gl_version
 * table is "sim" (simulation, fetch), "I" or "II". ms: wall clock between glFinish
 * calls; gpu_ms: the GL clock (gl_stage.h) for the GL stages and the GPU path's
 * simulation, empty otherwise. With INACIO_TABLES_PNG=PREFIX
 * in the environment, the last frame's shaded images are written to
 * PREFIX_I.png (volume_raycast, layered), PREFIX_II.png (spheres) and
 * PREFIX_I_slice.png (to check what was timed), at most INACIO_TABLES_PNG_MAX
 * pixels a side when that is set (png_small.h). */
#include "fs_error.h"
#include "gl.h"
#include "gl_context.h"
#include "gl_stage.h"
#include "image_io.h"
#include "png_small.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "scene.h"
#include "sph.h"
#include "timing.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct renderer {
    const fs_method *m;
    fs_scene scene; /* the shared scene, plus this renderer's settings */
    fs_run *run;
    fs_run_image im;
} renderer;

static const char *row_head; /* the leading columns, filled once */
static char head[1024];
static const char *gl_version = "";

static void row(int frame, double t, long steps, const char *table, const char *stage, double ms, double gpu_ms)
{
    printf("%s,%d,%.4f,%ld,%s,%s,%.3f,", row_head, frame, t, steps, table, stage, ms);
    if (!isnan(gpu_ms)) printf("%.3f", gpu_ms);
    printf(",\"%s\"\n", gl_version);
}

static int die(const char *what)
{
    fprintf(stderr, "inacio_tables: %s: %s\n", what, fs_error_message());
    return 1;
}

/* Renders p with r (upload, render, shade), adding the stages to st (NULL: untimed). */
static int render_with(renderer *r, fs_sph *sim, const fs_camera *cam, const fs_particles *p, fs_stages *st,
                       int time_upload)
{
    fs_stages dummy = {0};
    if (!st) st = &dummy;
    glFinish();
    double t0 = fs_now_ms();
    int rc = fs_run_upload(r->run, p, NULL, NULL); /* the grid, the method's upload, all GL work finished */
    glFinish();
    if (rc) return rc;
    if (time_upload) fs_stages_add(st, "upload", fs_now_ms() - t0);
    if ((rc = fs_run_render(r->run, cam, &r->im, st))) return rc;
    float lo[3], hi[3];
    fs_sph_box(sim, lo, hi);
    fs_run_set_floor(r->run, lo[r->scene.up_axis]);
    return fs_run_shade(r->run, cam, &r->im, FS_APPEARANCE_SHARED, st);
}

/* The last frame's image of one table, when INACIO_TABLES_PNG asks for it. */
static int write_png(const float *rgba, int size, const char *table)
{
    const char *prefix = getenv("INACIO_TABLES_PNG"), *max = getenv("INACIO_TABLES_PNG_MAX");
    if (!prefix) return FS_OK;
    char path[1200];
    snprintf(path, sizeof path, "%s_%s.png", prefix, table);
    return fs_write_png_small(path, rgba, size, size, max ? atoi(max) : size);
}

int main(int argc, char **argv)
{
    fs_methods_register_builtin();
    if (argc < 3 || (strcmp(argv[2], "cpu") && strcmp(argv[2], "gpu"))) {
        fprintf(stderr, "usage: inacio_tables PARTICLES cpu|gpu [SETTLE [FRAMES [SIZE [GRID [LIMIT_S]]]]]\n");
        return 2;
    }
    long want = atol(argv[1]);
    int gpu = !strcmp(argv[2], "gpu");
    int settle = argc > 3 ? atoi(argv[3]) : 6, frames = argc > 4 ? atoi(argv[4]) : 3;
    int size = argc > 5 ? atoi(argv[5]) : 512, grid = argc > 6 ? atoi(argv[6]) : 128;
    double limit_s = argc > 7 ? atof(argv[7]) : 60;
    if (want < 64 || settle < 1 || frames < 1 || size < 8 || grid < 8) {
        fprintf(stderr, "inacio_tables: bad arguments\n");
        return 2;
    }
    const double dt = 1.0 / 60;

    fs_gl_context ctx;
    if (fs_gl_context_create(&ctx, fs_gl_context_default_kind(), 16, 16)) return die("OpenGL");
    gl_version = ctx.version;
    fs_sph_params prm;
    fs_sph_params_default(&prm);
    fs_sph *sim = NULL;
    if (fs_sph_create(&sim, "dam_break", (size_t)want, &prm, gpu)) return die("simulator");
    snprintf(head, sizeof head, "%ld,%zu,%zu,%s,\"%s\",\"%s\"", want, fs_sph_count(sim), fs_sph_boundary_count(sim),
             gpu ? "gpu" : "cpu", gpu ? ctx.renderer : "CPU (C + OpenMP)", ctx.renderer);
    row_head = head;

    /* the scene: fluidsurf's defaults (shared shading), r of the simulator, the container framed */
    static fs_scene sc;
    fs_scene_defaults(&sc);
    sc.radius = prm.r;
    char set[160];
    snprintf(set, sizeof set, "volume_raycast.grid_res=%d", grid);
    if (fs_scene_add_set(&sc, set) || fs_scene_add_set(&sc, "volume_raycast.build=layered") ||
        fs_scene_add_set(&sc, "volume_raycast.thickness=off") || fs_scene_add_set(&sc, "spheres.thickness=off"))
        return die("scene");
    float lo[3], hi[3];
    fs_sph_box(sim, lo, hi);
    sc.camera.width = size;
    sc.camera.height = size;
    fs_scene_finish_camera(&sc, lo, hi);
    fs_camera cam = sc.camera;

    enum { NR = 3 };
    static renderer rr[NR];
    const char *names[NR] = {"volume_raycast", "spheres", "volume_raycast"};
    const char *table[NR] = {"I", "II", "I_slice"};
    for (int k = 0; k < NR; k++) {
        rr[k].m = fs_method_find(names[k]);
        if (!rr[k].m) {
            fprintf(stderr, "inacio_tables: method %s not registered\n", names[k]);
            return 1;
        }
        rr[k].scene = sc;
        if (k == 2 && fs_scene_add_set(&rr[k].scene, "volume_raycast.build=slice"))
            return die("scene"); /* its volume stage */
        if (fs_run_open(&rr[k].run, rr[k].m, &rr[k].scene, NULL, &ctx)) return die(rr[k].m->name);
        fs_run_shared_only(rr[k].run, 1); /* shaded with the shared shading: no own image drawn or read */
    }

    /* settle: untimed frames; the first checked against the limit */
    for (int f = 1; f <= settle; f++) {
        double t0 = fs_now_ms();
        if (fs_sph_advance(sim, dt)) return die("advance");
        if (gpu) glFinish();
        double ms = fs_now_ms() - t0;
        fprintf(stderr, "inacio_tables: %ld %s: settle frame %d/%d: %.0f ms\n", want, argv[2], f, settle, ms);
        if (f == 1 && ms > limit_s * 1000) {
            row(f, fs_sph_get_stats(sim)->t, fs_sph_get_stats(sim)->steps, "sim", "skipped_first_frame_over_limit", ms,
                NAN);
            return 0;
        }
    }
    fs_particles p = {0};
    if (fs_sph_get(sim, &p)) return die("get");
    for (int k = 0; k < NR; k++) /* warm-up: shader compilation, first allocations */
        if (render_with(&rr[k], sim, &cam, &p, NULL, 0)) return die(rr[k].m->name);
    fflush(stdout);

    for (int f = settle + 1; f <= settle + frames; f++) {
        const fs_sph_stats *s0 = fs_sph_get_stats(sim);
        long steps0 = s0->steps;
        fs_stages sst = {0}; /* the GPU path on the GL clock too */
        double t0 = fs_gl_stage_start();
        if (fs_sph_advance(sim, dt)) return die("advance");
        if (gpu) fs_gl_stage_end(&sst, "simulation", t0);
        else fs_stages_add(&sst, "simulation", fs_now_ms() - t0);
        const fs_sph_stats *s1 = fs_sph_get_stats(sim);
        double t = s1->t;
        long steps = s1->steps - steps0;
        row(f, t, steps, "sim", "simulation", sst.ms[0], sst.gpu_ms[0]);
        /* the methods hold p until the next upload: the new set replaces it after both uploads */
        fs_particles np = {0};
        t0 = fs_now_ms();
        if (fs_sph_get(sim, &np)) return die("get");
        row(f, t, steps, "sim", "fetch", fs_now_ms() - t0, NAN);
        for (int k = 0; k < NR; k++) {
            fs_stages st = {0};
            if (render_with(&rr[k], sim, &cam, &np, &st, k == 1)) return die(rr[k].m->name);
            for (int i = 0; i < st.n; i++) row(f, t, steps, table[k], st.name[i], st.ms[i], st.gpu_ms[i]);
            if (f == settle + frames && write_png(rr[k].im.rgba, size, table[k])) return die("png");
        }
        fs_particles_free(&p);
        p = np;
        fflush(stdout);
    }
    for (int k = 0; k < NR; k++) {
        fs_run_close(rr[k].run);
        fs_run_image_free(&rr[k].im);
    }
    fs_particles_free(&p);
    fs_sph_destroy(sim);
    fs_gl_context_destroy(&ctx);
    return 0;
}
