/* fluidsurf view: an interactive GLFW window that plays a scene's frames or
 * runs the SPH simulator live, rendering each frame with the current method
 * into a G-buffer (at a resolution scale of the window), shading it with the
 * shared shading (or the method's own appearance) and drawing the image. All
 * methods run in the window's own GL 4.5 core context. Input: view_input.c;
 * scripted input for tests: view_script.c. */
#include "cli.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_context.h"
#include "image_io.h"
#include "method.h"
#include "method_params.h"
#include "options.h"
#include "run.h"
#include "shader.h"
#include "sph.h"
#include "view.h"
#include "vec3.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* what --help says after the options */
static const char epilogue[] = "--script lines are 'frame N ACTION ARGS', an ACTION one of\n"
                               "  key NAME [shift|ctrl|alt]   drag X0 Y0 X1 Y1 [left|right|middle] [shift|ctrl]\n"
                               "  scroll DY   screenshot PATH   quit\n"
                               "keys: 1-9 method (registry order), space play/pause, N or . one frame, S screenshot,\n"
                               "      +/- resolution scale, O own/shared appearance, R reset camera, Esc/Q quit;\n"
                               "      simulator: arrows, or shift (ctrl) + left drag, move the container\n"
                               "mouse: left drag orbit, right/middle drag pan, wheel zoom\n";

typedef struct viewer {
    fs_scene scene;
    fs_view v;
    view_script script;
    fs_sph *sim;
    double dt;            /* simulated time per frame */
    float box_speed;      /* of the container now (m/s) */
    int first, last, cur; /* frames of a sequence scene */
    fs_particles p;       /* current particles: the run holds them until the next upload */
    fs_run *run;          /* the current method's run (NULL: none could be made) */
    int mi;               /* index of the method the run is for (-1 none) */
    fs_run_image im;      /* its G-buffer and shaded image */
    char why[512];        /* why the method cannot render this frame ("" when it can) */
    char said[512];       /* the reason last printed on stderr, so it is said once */
    fs_gl_context ctx;
    unsigned prog, vao, tex;
    int tw, th;
    unsigned box_prog, depth_tex; /* the simulator's container overlay */
    int dtw, dth;
    int shots, shot_failed;
    int verbose;             /* print each title on stderr */
    unsigned gen;            /* particle sets loaded so far */
    double frame_ms, sim_ms; /* whole frame; the simulator's share */
} viewer;

/* ---- particles: the next frame of the sequence or of the simulator ---- */

/* Advances one frame while the container moves towards where the user asked,
 * smoothly: at most 60 r/s (1.5 m/s at r = 0.025), speeding up and slowing
 * down at 400 r/s^2 (1 g). A wall started or stopped at once throws water up
 * at several times its speed (the impulsive-wall jet). */
static int sim_advance(viewer *w)
{
    float *d = w->v.box_move, r = fs_sph_get_params(w->sim)->r, dt = (float)w->dt;
    float len = fs_v3_len(d);
    float v = fminf(fminf(w->box_speed + 400 * r * dt, 60 * r), sqrtf(2 * 400 * r * len));
    w->box_speed = len > 0 ? v : 0;
    if (!(len > 0)) return fs_sph_advance(w->sim, w->dt);
    float take = fminf(1.0f, v * dt / len), move[3] = {d[0] * take, d[1] * take, d[2] * take};
    for (int i = 0; i < 3; i++) d[i] -= move[i];
    return fs_sph_move_box(w->sim, move, w->dt);
}

/* A method that cannot render the current frame does not end the viewer: the
 * reason goes to the title bar and, once per new reason, to stderr. */
static void method_failed(viewer *w)
{
    snprintf(w->why, sizeof w->why, "%s", fs_error_message());
    if (strcmp(w->why, w->said)) fprintf(stderr, "fluidsurf: %s\n", w->why);
    snprintf(w->said, sizeof w->said, "%s", w->why);
}

/* Loads (advance: the next) particles and hands them to the current run; the
 * previous set is freed once the run no longer holds it. Only a frame that
 * cannot be loaded ends the viewer. */
static int next_particles(viewer *w, int advance)
{
    fs_particles np = {0};
    int rc;
    if (w->sim) {
        double t0 = fs_now_ms();
        if (advance && (rc = sim_advance(w))) return rc;
        w->sim_ms = advance ? fs_now_ms() - t0 : 0;
        rc = fs_sph_get(w->sim, &np);
    } else {
        if (advance && w->first == w->last) return FS_OK; /* one still frame */
        if (advance) w->cur = w->cur < w->last ? w->cur + 1 : w->first;
        rc = fs_scene_load_frame(&w->scene, w->cur, &np);
    }
    if (rc) {
        fs_particles_free(&np);
        return rc;
    }
    if (w->run && fs_run_upload(w->run, &np, NULL, NULL)) method_failed(w);
    fs_particles_free(&w->p); /* after a failed upload the run holds no frame either */
    w->p = np;
    w->gen++;
    return FS_OK;
}

/* Opens a run of the method the user picked (when it changed) and hands it the particles. */
static void use_method(viewer *w)
{
    if (w->mi == w->v.method) return;
    fs_run_close(w->run);
    w->run = NULL;
    w->mi = w->v.method;
    w->why[0] = 0;
    if (fs_run_open(&w->run, fs_method_at(w->mi), &w->scene, NULL, &w->ctx) || fs_run_upload(w->run, &w->p, NULL, NULL))
        method_failed(w);
}

/* ---- drawing ---- */

static int present_init(viewer *w)
{
    const char *stages[] = {"view/present.vert.glsl", "view/present.frag.glsl", NULL};
    if (!(w->prog = fs_program_build(stages, NULL))) return FS_ERR_RUNTIME;
    const char *box[] = {"view/box.vert.glsl", "view/box.frag.glsl", NULL};
    if (w->sim && !(w->box_prog = fs_program_build(box, NULL))) return FS_ERR_RUNTIME;
    glCreateVertexArrays(1, &w->vao);
    return FS_OK;
}

/* A texture of size gw x gh (recreated when the size changes). */
static void sized_texture(unsigned *tex, int *tw, int *th, int gw, int gh, unsigned format, int filter)
{
    if (*tex && *tw == gw && *th == gh) return;
    if (*tex) glDeleteTextures(1, tex);
    glCreateTextures(GL_TEXTURE_2D, 1, tex);
    glTextureStorage2D(*tex, 1, format, gw, gh);
    glTextureParameteri(*tex, GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(*tex, GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(*tex, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(*tex, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    *tw = gw;
    *th = gh;
}

/* Draws the container's edges over the image, dimmed where the fluid's
 * G-buffer depth is nearer, so the user sees what a box drag moves. */
static void draw_box(viewer *w, const fs_camera *cam, int fw, int fh)
{
    int gw = w->im.g.w, gh = w->im.g.h;
    sized_texture(&w->depth_tex, &w->dtw, &w->dth, gw, gh, GL_R32F, GL_NEAREST); /* no filtering across inf */
    glTextureSubImage2D(w->depth_tex, 0, 0, 0, gw, gh, GL_RED, GL_FLOAT, w->im.g.depth);
    float lo[3], hi[3], view[16], proj[16];
    fs_sph_box(w->sim, lo, hi);
    fs_camera_view_matrix(cam, view);
    fs_camera_proj_matrix(cam, proj);
    unsigned p = w->box_prog;
    glUseProgram(p);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view"), 1, GL_FALSE, view);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_proj"), 1, GL_FALSE, proj);
    glUniform3f(glGetUniformLocation(p, "u_lo"), lo[0], lo[1], lo[2]);
    glUniform3f(glGetUniformLocation(p, "u_hi"), hi[0], hi[1], hi[2]);
    glUniform2f(glGetUniformLocation(p, "u_window"), (float)fw, (float)fh);
    glBindTextureUnit(0, w->depth_tex);
    glBindVertexArray(w->vao);
    glDrawArrays(GL_LINES, 0, 24);
    glBindVertexArray(0);
    glUseProgram(0);
}

/* Draws the linear image rgba (gw x gh) over the whole fw x fh window. */
static void present(viewer *w, int gw, int gh, int fw, int fh)
{
    sized_texture(&w->tex, &w->tw, &w->th, gw, gh, GL_RGBA32F, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(w->tex, 0, 0, 0, gw, gh, GL_RGBA, GL_FLOAT, w->im.rgba);
    /* methods leave their own state behind: reset what the draw depends on */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(w->prog);
    glBindTextureUnit(0, w->tex);
    glBindVertexArray(w->vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

/* The camera of this frame: the orbit, the G-buffer size, clip planes around
 * the particles (and the simulator's container, so they do not jump as fluid splashes). */
static fs_camera frame_camera(const viewer *w, int gw, int gh)
{
    fs_camera cam = w->scene.camera;
    cam.width = gw;
    cam.height = gh;
    fs_orbit_apply(&w->v.orbit, &cam);
    float lo[3], hi[3], H = fs_scene_field(&w->scene).H;
    for (int k = 0; k < 3; k++) {
        lo[k] = w->p.n ? w->p.bmin[k] - H : 0;
        hi[k] = w->p.n ? w->p.bmax[k] + H : 0;
    }
    if (w->sim) {
        float blo[3], bhi[3];
        fs_sph_box(w->sim, blo, bhi);
        for (int k = 0; k < 3; k++) {
            lo[k] = w->p.n ? fminf(lo[k], blo[k]) : blo[k];
            hi[k] = w->p.n ? fmaxf(hi[k], bhi[k]) : bhi[k];
        }
    }
    fs_camera_fit_clip(&cam, lo, hi);
    return cam;
}

/* Renders the current particles with the current method at the window size
 * times the scale, shades and draws them. A method that fails shows the empty
 * scene and says why. */
static int render_frame(viewer *w, int fw, int fh)
{
    int gw = (int)lroundf(fw * w->v.scale), gh = (int)lroundf(fh * w->v.scale);
    fs_camera cam = frame_camera(w, gw < 1 ? 1 : gw, gh < 1 ? 1 : gh);
    if (!w->run) { /* no method could be made: nothing to draw but the reason */
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        return FS_OK;
    }
    if (w->sim) { /* the container's floor, not the fluid's lowest point */
        float blo[3], bhi[3];
        fs_sph_box(w->sim, blo, bhi);
        fs_run_set_floor(w->run, blo[w->scene.up_axis]);
    }
    fs_stages st = {0};
    if (fs_run_render(w->run, &cam, &w->im, &st)) method_failed(w);
    else w->why[0] = 0;
    int own = w->v.own && fs_method_aov(fs_run_method(w->run), FS_AOV_OWN) && w->p.n && !w->why[0];
    int rc = fs_run_shade(w->run, &cam, &w->im, own ? FS_APPEARANCE_OWN : FS_APPEARANCE_SHARED, NULL);
    if (rc) return rc;
    present(w, cam.width, cam.height, fw, fh);
    if (w->sim) draw_box(w, &cam, fw, fh);
    return FS_OK;
}

/* Saves the window's back buffer (what the next swap shows) as a PNG. */
static int screenshot(viewer *w, int fw, int fh)
{
    char name[1100];
    if (w->v.shot_path[0]) snprintf(name, sizeof name, "%s", w->v.shot_path);
    else /* a numbered name that does not overwrite an earlier one */ do
            snprintf(name, sizeof name, "fluidsurf_view_%03d.png", ++w->shots);
        while (access(name, F_OK) == 0);
    unsigned char *pix = malloc((size_t)fw * fh * 3), *row = malloc((size_t)fw * 3);
    if (!pix || !row) {
        free(pix);
        free(row);
        return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, fw, fh, GL_RGB, GL_UNSIGNED_BYTE, pix);
    for (int y = 0; y < fh / 2; y++) { /* GL rows run bottom to top */
        memcpy(row, pix + (size_t)y * fw * 3, (size_t)fw * 3);
        memcpy(pix + (size_t)y * fw * 3, pix + (size_t)(fh - 1 - y) * fw * 3, (size_t)fw * 3);
        memcpy(pix + (size_t)(fh - 1 - y) * fw * 3, row, (size_t)fw * 3);
    }
    int rc = fs_write_png8(name, pix, fw, fh, 3);
    free(pix);
    free(row);
    if (!rc) fprintf(stderr, "fluidsurf: screenshot %s (%dx%d)\n", name, fw, fh);
    return rc;
}

static void set_title(viewer *w, int frame, int fw, int fh)
{
    const fs_method *m = fs_method_at(w->mi);
    char where[160], title[600], ms[64];
    if (w->sim) snprintf(ms, sizeof ms, "%.1f ms (simulation %.1f)", w->frame_ms, w->sim_ms);
    else snprintf(ms, sizeof ms, "%.1f ms", w->frame_ms);
    if (w->sim)
        snprintf(where, sizeof where, "t = %.3f s, %zu particles%s", fs_sph_get_stats(w->sim)->t, fs_sph_count(w->sim),
                 w->v.playing ? "" : ", paused");
    else
        snprintf(where, sizeof where, "frame %d [%d..%d]%s", w->cur, w->first, w->last, w->v.playing ? "" : ", paused");
    char why[600] = "";
    if (w->why[0]) snprintf(why, sizeof why, " | cannot render: %s", w->why);
    snprintf(title, sizeof title, "fluidsurf view | %s (%s) | %s | %s | scale %.2f (%dx%d) | %s | #%d%s", m->name,
             w->v.own && fs_method_aov(m, FS_AOV_OWN) ? "own" : "shared", ms, w->ctx.renderer, w->v.scale,
             (int)lroundf(fw * w->v.scale), (int)lroundf(fh * w->v.scale), where, frame, why);
    glfwSetWindowTitle(w->ctx.handle, title);
    if (w->verbose) fprintf(stderr, "%s\n", title);
}

/* ---- GLFW callbacks: straight into the handlers the scripts call ---- */

static fs_view *view_of(GLFWwindow *win) { return glfwGetWindowUserPointer(win); }
static void on_key(GLFWwindow *win, int key, int scancode, int action, int mods)
{
    (void)scancode;
    if (action != GLFW_RELEASE) view_key(view_of(win), key, mods);
}
static void on_button(GLFWwindow *win, int button, int action, int mods)
{
    double x, y;
    glfwGetCursorPos(win, &x, &y);
    view_button(view_of(win), button, action == GLFW_PRESS, mods, x, y);
}
static void on_refresh(GLFWwindow *win) { view_of(win)->redraw++; }
static void on_cursor(GLFWwindow *win, double x, double y) { view_cursor(view_of(win), x, y); }
static void on_scroll(GLFWwindow *win, double dx, double dy)
{
    (void)dx;
    view_scroll(view_of(win), dy);
}

static int run(viewer *w, int max_frames, int scripted)
{
    GLFWwindow *win = w->ctx.handle;
    glfwSetWindowUserPointer(win, &w->v);
    glfwSetKeyCallback(win, on_key);
    glfwSetMouseButtonCallback(win, on_button);
    glfwSetCursorPosCallback(win, on_cursor);
    glfwSetScrollCallback(win, on_scroll);
    glfwSetWindowRefreshCallback(win, on_refresh);
    glfwSwapInterval(scripted ? 0 : 1);
    int rc = present_init(w);
    struct {
        fs_orbit orbit;
        int method, own, fw, fh, redraw;
        float scale;
        unsigned gen;
    } drawn, now;
    memset(&drawn, 0, sizeof drawn); /* memset: the struct is compared bytewise */
    for (int frame = 0; !rc; frame++) {
        glfwPollEvents();
        view_script_apply(&w->script, &w->v, frame);
        if (w->v.quit || glfwWindowShouldClose(win) || (max_frames && frame >= max_frames)) break;
        double t0 = fs_now_ms();
        w->sim_ms = 0;
        if (frame > 0 && (w->v.playing || w->v.step)) {
            w->v.step = 0;
            if ((rc = next_particles(w, 1))) break;
        }
        use_method(w);
        int fw, fh, ww, wh;
        glfwGetFramebufferSize(win, &fw, &fh);
        glfwGetWindowSize(win, &ww, &wh);
        w->v.view_h = wh;
        /* nothing changed (a still frame, or paused, and no input): wait for
         * input instead of rendering the same image again with a slow method */
        memset(&now, 0, sizeof now);
        now.orbit = w->v.orbit, now.method = w->v.method, now.own = w->v.own, now.fw = fw, now.fh = fh;
        now.redraw = w->v.redraw, now.scale = w->v.scale, now.gen = w->gen;
        if (frame > 0 && !scripted && !w->v.shot && !memcmp(&now, &drawn, sizeof now)) {
            glfwWaitEventsTimeout(0.1);
            frame--;
            continue;
        }
        drawn = now;
        if ((rc = render_frame(w, fw, fh))) break;
        if (w->v.shot) {
            w->v.shot = 0;
            if (screenshot(w, fw, fh)) { /* the viewer goes on; the exit status tells */
                cli_error(FS_ERR_RUNTIME);
                w->shot_failed = 1;
            }
        }
        glfwSwapBuffers(win);
        w->frame_ms = fs_now_ms() - t0;
        set_title(w, frame, fw, fh);
    }
    return rc ? rc : w->shot_failed ? FS_ERR_RUNTIME : FS_OK;
}

/* Reads a whole text file (the script) into *out (malloc'd). */
static int read_text(const char *path, char **out)
{
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open the script", path);
    char *buf = NULL;
    size_t n = 0, cap = 0, got;
    do {
        if (n + 4096 + 1 > cap) {
            char *nb = realloc(buf, cap = 2 * cap + 8192);
            if (!nb) {
                free(buf);
                fclose(f);
                return fs_fail(FS_ERR_RUNTIME, "out of memory");
            }
            buf = nb;
        }
        got = fread(buf + n, 1, 4096, f);
        n += got;
    } while (got == 4096);
    fclose(f);
    buf[n] = 0;
    *out = buf;
    return FS_OK;
}

/* The parsed command line. */
typedef struct view_options {
    const char *input, *simulate, *script, *events;
    const char *const *sets;
    int nsets, W, H, gpu, paused, verbose, max_frames, particles, method;
    float scale, radius, dt;
    cli_scene_opts field;
} view_options;

/* Everything the user typed is checked before a window opens: the scene, the
 * settings (for every method, so a bad --set fails now, not on a key press),
 * the script, the simulator's scene name. */
static int check_input(viewer *w, const view_options *o)
{
    int rc;
    if (o->simulate) fs_scene_defaults(&w->scene);
    else if ((rc = cli_scene_from_arg(&w->scene, o->input))) return rc;
    cli_scene_opts_apply(&w->scene, &o->field);
    for (int i = 0; i < o->nsets; i++)
        if ((rc = fs_scene_add_set(&w->scene, o->sets[i]))) return rc;
    double check[FS_MAX_PARAMS];
    for (int i = 0; i < fs_method_count(); i++)
        if ((rc = fs_method_params_resolve(fs_method_at(i), &w->scene, check))) return rc;
    if (o->script || o->events) {
        char *text = NULL;
        if (o->script && (rc = read_text(o->script, &text))) return rc;
        if (!o->script && !(text = strdup(o->events))) return fs_fail(FS_ERR_RUNTIME, "out of memory");
        rc = view_script_parse(&w->script, text, o->script ? o->script : "--events");
        free(text);
        if (rc) return rc;
    }
    if (!o->simulate) return FS_OK;
    for (int i = 0; fs_sph_scene_names[i]; i++)
        if (!strcmp(fs_sph_scene_names[i], o->simulate)) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "--simulate %s: unknown scene (try 'fluidsurf view --help')", o->simulate);
}

/* A scene's first frame, which settles r and the camera. */
static int load_scene(viewer *w, const view_options *o)
{
    fs_scene_frames(&w->scene, &w->first, &w->last);
    w->cur = w->first;
    if (o->radius > 0) w->scene.radius = o->radius; /* before a synthetic scene is generated */
    int rc = next_particles(w, 0);
    char note[1024] = "";
    if (!rc) fs_scene_adopt_frame(&w->scene, &w->p, o->radius, note, sizeof note);
    if (note[0]) fs_note("%s", note);
    return rc;
}

/* The simulator, after the window: its GPU path needs the context. */
static int start_simulator(viewer *w, const view_options *o, int win_w, int win_h)
{
    fs_sph_params prm;
    fs_sph_params_default(&prm);
    if (o->radius > 0) prm.r = o->radius;
    int rc = fs_sph_create(&w->sim, o->simulate, (size_t)o->particles, &prm, o->gpu);
    if (rc) return rc;
    w->scene.radius = prm.r;
    float lo[3], hi[3];
    fs_sph_box(w->sim, lo, hi);
    w->scene.camera.width = win_w;
    w->scene.camera.height = win_h;
    fs_scene_finish_camera(&w->scene, lo, hi);
    if ((rc = next_particles(w, 0))) return rc;
    w->v.can_move_box = 1;
    w->v.box_step = 0.05f * (hi[0] - lo[0]);
    return FS_OK;
}

static void start_view(viewer *w, const view_options *o)
{
    fs_orbit_from_camera(&w->v.orbit, &w->scene.camera, w->scene.up_axis);
    w->v.home = w->v.orbit;
    w->v.nmethods = fs_method_count() < 9 ? fs_method_count() : 9;
    w->v.method = o->method;
    w->v.scale = o->scale;
    w->v.playing = !o->paused;
    fprintf(stderr, "fluidsurf: view: %s on %s (%s); %s\n", o->simulate ? o->simulate : o->input, w->ctx.renderer,
            o->simulate ? (o->gpu ? "GPU simulation" : "CPU simulation") : "playing the scene",
            "keys: 1-9 method, space play, N step, S screenshot, +/- scale, O appearance, Esc quit");
}

/* The run (its GL objects) and the window's objects go in the window's context. */
static void free_viewer(viewer *w)
{
    fs_run_close(w->run);
    fs_sph_destroy(w->sim);
    if (w->ctx.handle) {
        if (w->tex) glDeleteTextures(1, &w->tex);
        if (w->vao) glDeleteVertexArrays(1, &w->vao);
        if (w->prog) glDeleteProgram(w->prog);
        if (w->box_prog) glDeleteProgram(w->box_prog);
        if (w->depth_tex) glDeleteTextures(1, &w->depth_tex);
    }
    fs_gl_context_destroy(&w->ctx);
    fs_run_image_free(&w->im);
    fs_particles_free(&w->p);
    view_script_free(&w->script);
}

/* The plan: check the input, the first frame, the window, the simulator, the loop. */
static int view_main(const view_options *o)
{
    static viewer w;
    memset(&w, 0, sizeof w);
    w.mi = -1;
    w.dt = o->dt;
    w.verbose = o->verbose;
    int rc = check_input(&w, o);
    if (!rc && !o->simulate) rc = load_scene(&w, o);
    int win_w = o->W ? o->W : o->simulate ? 800 : w.scene.camera.width;
    int win_h = o->H ? o->H : o->simulate ? 600 : w.scene.camera.height;
    if (!rc) rc = fs_gl_context_create(&w.ctx, FS_CTX_GLFW, win_w, win_h);
    if (!rc && o->simulate) rc = start_simulator(&w, o, win_w, win_h);
    if (!rc) {
        start_view(&w, o);
        rc = run(&w, o->max_frames, o->script || o->events || o->max_frames); /* scripted runs never idle */
    }
    if (rc) cli_error(rc);
    free_viewer(&w);
    return rc;
}

int cmd_view(int argc, char **argv)
{
    const char *input = NULL, *simulate = NULL, *mname = NULL, *script = NULL, *events = NULL;
    int W = 0, H = 0, gpu = 0, paused = 0, verbose = 0, max_frames = 0, particles = 0, require_gpu = 0, rc;
    float scale = 1, radius = 0, dt = 1.0f / 60;
    cli_scene_opts field = CLI_SCENE_OPTS_UNSET;
    const char *sets[FS_MAX_SETS];
    int nsets = 0;
    const cli_opt opts[] = {
        CLI_STRING_OPT("--simulate", simulate, "NAME",
                       "run the SPH simulator live, one --dt per displayed frame\n"
                       "(dam_break, double_dam_break, drop, spouts, pool)"),
        CLI_INT_OPT("--particles", particles, 1, 100000000, "N",
                    "simulator: about N fluid particles (default: the scene's)"),
        CLI_FLAG_OPT("--gpu", gpu, "simulator: the GPU path (compute shaders) instead of C + OpenMP"),
        CLI_FLOAT_OPT("--dt", dt, 1e-6, 1, "S", "simulated seconds per displayed frame (default 1/60)"),
        CLI_STRING_OPT("--method", mname, "NAME", "method shown first (default: the first registered)"),
        CLI_OPT_SET(sets, nsets),
        CLI_OPT_SIZE(W, H, 16, 8192, "window", "the scene's image size, else 800x600"),
        CLI_FLOAT_OPT("--scale", scale, 1.0 / 16, 2, "S", "G-buffer size / window size, 1/16..2 (default 1)"),
        CLI_OPT_RADIUS(radius,
                       "the scene's, else the file's, else estimated from\n"
                       "the particle spacing (a note says so; fluidsurf info shows it)"),
        CLI_OPT_SCENE(field),
        CLI_OPT_REQUIRE_GPU(require_gpu),
        CLI_FLAG_OPT("--paused", paused, "start paused"),
        CLI_INT_OPT("--frames", max_frames, 1, 100000000, "N", "quit after N displayed frames"),
        CLI_FLAG_OPT("-v", verbose, "print the title bar (method, ms, renderer, scale, frame) each frame"),
        CLI_STRING_OPT("--script", script, "FILE", "timed input, lines 'frame N ACTION ARGS' (below)"),
        CLI_STRING_OPT("--events", events, "TEXT", "the same inline, actions separated by ';'"),
        CLI_END,
    };
    const cli_command cmd = {"view",
                             "SCENE.json|PARTICLES [options]\n--simulate NAME [options]",
                             opts,
                             {&input, NULL, 1, "more than one input ('%s' and '%s')"},
                             epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_gl_context_require_gpu(require_gpu);
    if (!input == !simulate) return cli_usage("view", "give a scene or particle file, or --simulate NAME (not both)");
    if (script && events) return cli_usage("view", "--script and --events: give one");
    if (!simulate && (gpu || particles)) return cli_usage("view", "--gpu and --particles apply to --simulate only");
    if (simulate && field.up >= 0)
        return cli_usage("view", "--up applies to a scene or particle file (the simulator's is y)");
    int mi = 0;
    if (mname) {
        for (mi = 0; mi < fs_method_count() && strcmp(fs_method_at(mi)->name, mname); mi++) {}
        if (mi == fs_method_count()) return cli_unknown_method("view", "--method", mname);
    }
    const view_options o = {input,  simulate, script,     events,    sets, nsets, W,      H,  gpu,
                            paused, verbose,  max_frames, particles, mi,   scale, radius, dt, field};
    return view_main(&o);
}
