/* The three context kinds in one process (run under xvfb-run): the spheres
 * method renders the same lattice block on OSMesa, on a GLFW window (GLX,
 * llvmpipe under Xvfb) and, when Mesa offers one, on an EGL device; switching
 * back to OSMesa (which reloads the function table) must give the very same
 * G-buffer, also after the other contexts are destroyed.
 * With --expect-failures (no display, no EGL vendor) GLFW and EGL must fail
 * with one "OpenGL: ..." line each and leave OSMesa current and working. */
#include "fs_error.h"
#include "fs_test.h"
#include "gl_context.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "scene.h"
#include <stdlib.h>
#include <string.h>

#define SIZE 96

static fs_scene scene;
static fs_particles block;
static int expect_failures;

/* A 6x4x5 lattice block (as tests/test_spheres.c test_golden), framed at SIZE^2. */
static void make_block(void)
{
    fs_scene_defaults(&scene);
    scene.radius = 0.05f;
    fs_particles_alloc(&block, 6 * 4 * 5, 0);
    size_t k = 0;
    for (int z = 0; z < 5; z++)
        for (int y = 0; y < 4; y++)
            for (int x = 0; x < 6; x++, k++) {
                block.x[k] = (x - 2.5f) * 0.1f;
                block.y[k] = y * 0.1f + 0.05f;
                block.z[k] = (z - 2.0f) * 0.1f;
            }
    fs_particles_bounds(&block);
    scene.camera.width = scene.camera.height = SIZE;
    fs_scene_finish_camera(&scene, block.bmin, block.bmax);
}

/* Renders the block with `spheres` on the current context into g (allocated
 * here); the method's GL objects live and die in that context. */
static int render_block(fs_gbuffer *g)
{
    const fs_method *m = fs_method_find("spheres");
    if (!m) return fs_fail(FS_ERR_RUNTIME, "spheres is not registered");
    fs_run *run = NULL;
    fs_run_image im = {0};
    int rc = fs_run_open(&run, m, &scene, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &block, NULL, NULL);
    if (!rc) rc = fs_run_render(run, &scene.camera, &im, NULL);
    fs_run_close(run);
    *g = im.g; /* empty on failure */
    if (rc) fs_gbuffer_free(g);
    return rc;
}

static int covered_count(const fs_gbuffer *g)
{
    int n = 0;
    for (int i = 0; i < g->w * g->h; i++) n += g->coverage[i] > 0.5f;
    return n;
}

/* 1 when pixel (x, y) of g is covered and has an uncovered 4-neighbour (or the
 * other way round): the only pixels allowed to flip between renderers. */
static int on_silhouette(const fs_gbuffer *g, int x, int y)
{
    int c = g->coverage[y * g->w + x] > 0.5f;
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; k++) {
        int u = x + dx[k], v = y + dy[k];
        if (u < 0 || v < 0 || u >= g->w || v >= g->h) continue;
        if ((g->coverage[v * g->w + u] > 0.5f) != c) return 1;
    }
    return 0;
}

/* Coverage equal but for a few silhouette pixels; depth within 1e-4 relative
 * and normals within 1e-3 where both cover. */
static void compare(const char *what, const fs_gbuffer *a, const fs_gbuffer *b)
{
    int flipped = 0, inner_flips = 0, both = 0;
    double depth_rel = 0, normal = 0, thick_rel = 0;
    for (int y = 0; y < SIZE; y++)
        for (int x = 0; x < SIZE; x++) {
            int i = y * SIZE + x, ca = a->coverage[i] > 0.5f, cb = b->coverage[i] > 0.5f;
            if (ca != cb) {
                flipped++;
                inner_flips += !on_silhouette(a, x, y);
                continue;
            }
            if (!ca) continue;
            both++;
            double d = fabs(a->depth[i] - b->depth[i]) / fabs(a->depth[i]);
            if (!(d <= depth_rel)) depth_rel = d; /* NaN counts as worst */
            for (int k = 0; k < 3; k++) {
                double e = fabs(a->normal[3 * i + k] - b->normal[3 * i + k]);
                if (!(e <= normal)) normal = e;
            }
            double t = fabs(a->thickness[i] - b->thickness[i]) / (fabs(a->thickness[i]) + 1e-6);
            if (!(t <= thick_rel)) thick_rel = t;
        }
    printf("%s: %d pixels both cover, %d flipped (%d off the silhouette), depth %.2g rel, normal %.2g, "
           "thickness %.2g rel\n",
           what, both, flipped, inner_flips, depth_rel, normal, thick_rel);
    CHECK(both > SIZE * SIZE / 8, "%s: only %d pixels covered by both", what, both);
    CHECK(flipped <= 8 && inner_flips == 0, "%s: coverage differs at %d pixels (%d off the silhouette)", what, flipped,
          inner_flips);
    CHECK(depth_rel <= 1e-4, "%s: depth differs by %g relative", what, depth_rel);
    CHECK(normal <= 1e-3, "%s: normal differs by %g", what, normal);
    CHECK(thick_rel <= 1e-3, "%s: thickness differs by %g relative", what, thick_rel);
}

/* Bit-identical G-buffers (the same renderer on the same context kind). */
static void check_identical(const char *what, const fs_gbuffer *a, const fs_gbuffer *b)
{
    size_t n = (size_t)SIZE * SIZE;
    int same = !memcmp(a->coverage, b->coverage, n * sizeof(float)) && !memcmp(a->depth, b->depth, n * sizeof(float)) &&
        !memcmp(a->normal, b->normal, 3 * n * sizeof(float)) && !memcmp(a->thickness, b->thickness, n * sizeof(float));
    printf("%s: %s\n", what, same ? "identical to the first OSMesa render" : "DIFFERS");
    CHECK(same, "%s: the G-buffer differs from the first OSMesa render", what);
    CHECK(covered_count(b) == covered_count(a), "%s: %d covered pixels, first render had %d", what, covered_count(b),
          covered_count(a));
}

/* Renders on the OSMesa context (made current again first when `switch_to`):
 * must equal `ref`. */
static void osmesa_again(fs_gl_context *os, int switch_to, const fs_gbuffer *ref, const char *what)
{
    fs_gbuffer g = {0};
    int rc = switch_to ? fs_gl_context_make_current(os) : FS_OK;
    CHECK(rc == FS_OK, "%s: make_current: %s", what, fs_error_message());
    if (rc == FS_OK) {
        CHECK(strstr(os->renderer, "llvmpipe") != NULL, "%s: OSMesa renderer now '%s'", what, os->renderer);
        rc = render_block(&g);
        CHECK(rc == FS_OK, "%s: render: %s", what, fs_error_message());
        if (rc == FS_OK) check_identical(what, ref, &g);
    }
    fs_gbuffer_free(&g);
}

/* A failed create: FS_ERR_RUNTIME, one line starting with `prefix`, no
 * handle kept, and the OSMesa context still current and rendering. */
static void check_failed_create(int rc, const fs_gl_context *c, const char *prefix, fs_gl_context *os,
                                const fs_gbuffer *ref)
{
    const char *msg = fs_error_message();
    printf("%s: not available here: %s\n", fs_ctx_kind_name(c->kind), msg);
    CHECK(rc == FS_ERR_RUNTIME, "failure returned %d, not FS_ERR_RUNTIME", rc);
    CHECK(!strncmp(msg, prefix, strlen(prefix)), "failure message does not start '%s': %s", prefix, msg);
    CHECK(strchr(msg, '\n') == NULL, "failure message is not one line: %s", msg);
    CHECK(c->handle == NULL, "a failed %s context keeps a handle", fs_ctx_kind_name(c->kind));
    char what[64];
    snprintf(what, sizeof what, "OSMesa still current after the failed %s create", fs_ctx_kind_name(c->kind));
    osmesa_again(os, 0, ref, what);
}

/* EGL needs no GPU to be tested: it either works (Mesa's software device) and
 * renders what OSMesa renders, or fails with one clear line. */
static void test_egl(fs_gl_context *os, const fs_gbuffer *ref)
{
    fs_gl_context egl;
    int rc = fs_gl_context_create(&egl, FS_CTX_EGL, SIZE, SIZE);
    if (rc != FS_OK) {
        egl.kind = FS_CTX_EGL;
        check_failed_create(rc, &egl, "OpenGL: EGL: ", os, ref);
        return;
    }
    CHECK(!expect_failures, "EGL context created although no EGL vendor should be found");
    printf("EGL: GL_RENDERER %s, GL_VERSION %s\n", egl.renderer, egl.version);
    fs_gbuffer g = {0};
    rc = render_block(&g);
    CHECK(rc == FS_OK, "EGL render: %s", fs_error_message());
    if (rc == FS_OK) compare("EGL vs OSMesa", ref, &g);
    fs_gbuffer_free(&g);
    /* back to OSMesa, then destroy EGL behind its back */
    osmesa_again(os, 1, ref, "OSMesa after EGL");
    fs_gl_context_destroy(&egl);
    osmesa_again(os, 0, ref, "OSMesa still current after destroying EGL");
}

int main(int argc, char **argv)
{
    fs_methods_register_builtin();
    expect_failures = argc > 1 && !strcmp(argv[1], "--expect-failures");
    make_block();
    fs_gbuffer ref = {0}, g = {0};

    /* 1. OSMesa */
    fs_gl_context os;
    if (fs_gl_context_create(&os, FS_CTX_OSMESA, 16, 16)) {
        CHECK(0, "OSMesa context: %s", fs_error_message());
        TEST_DONE();
    }
    printf("OSMesa: GL_RENDERER %s, GL_VERSION %s\n", os.renderer, os.version);
    CHECK(strstr(os.renderer, "llvmpipe") != NULL, "OSMesa renderer is '%s'", os.renderer);
    CHECK(render_block(&ref) == FS_OK, "OSMesa render: %s", fs_error_message());
    CHECK(covered_count(&ref) > SIZE * SIZE / 8, "OSMesa render covers only %d pixels", covered_count(&ref));

    /* 2. a GLFW window on Xvfb: GLX, loaded by GLFW at run time */
    fs_gl_context win;
    int rc = fs_gl_context_create(&win, FS_CTX_GLFW, SIZE, SIZE);
    if (expect_failures) {
        CHECK(rc != FS_OK, "GLFW context created without a display");
        win.kind = FS_CTX_GLFW;
        if (rc != FS_OK) check_failed_create(rc, &win, "OpenGL: GLFW ", &os, &ref);
    } else {
        CHECK(rc == FS_OK, "GLFW context: %s", fs_error_message());
    }
    if (rc == FS_OK) {
        printf("GLFW: GL_RENDERER %s, GL_VERSION %s\n", win.renderer, win.version);
        CHECK(strstr(win.renderer, "llvmpipe") != NULL, "GLFW renderer under Xvfb is '%s'", win.renderer);
        rc = render_block(&g);
        CHECK(rc == FS_OK, "GLFW render: %s", fs_error_message());
        if (rc == FS_OK) compare("GLFW vs OSMesa", &ref, &g);
        fs_gbuffer_free(&g);
    }

    /* 3. back to OSMesa while the window lives; destroying the window must
     * leave OSMesa current and working */
    osmesa_again(&os, 1, &ref, "OSMesa after GLFW");
    if (win.handle) {
        fs_gl_context_destroy(&win);
        osmesa_again(&os, 0, &ref, "OSMesa still current after destroying GLFW");
    }

    /* 4. EGL (or its one-line failure), and OSMesa after it */
    test_egl(&os, &ref);
    osmesa_again(&os, 1, &ref, "OSMesa at the end");

    fs_gl_context_destroy(&os);
    fs_gbuffer_free(&ref);
    fs_particles_free(&block);
    TEST_DONE();
}
