/* The run layer with a test-only method registered through the same API as the
 * built-in table (fs_method_register, hidden from the listing): render, shade,
 * provenance, an EXR written and read back with the AOV the method declares (and
 * none for a method that declares none); the particle-lifetime rule (the
 * method keeps the pointers it was given while the caller's struct goes out of
 * scope); a failed upload; an empty frame; the grid built only for a method
 * that reads it; a GL method without a context.
 * Links the run and image layers only, not methods/. */
#include "fs_error.h"
#include "fs_test.h"
#include "image_io.h"
#include "method.h"
#include "render_output.h"
#include "run.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* "flat": every pixel whose ray passes within the particles' box (seen along
 * the view axis) is covered, at the depth of the box's nearest face; it keeps
 * the particle set it was given, as surfels and volume_raycast do. It declares
 * one AOV, "test_aov", holding each pixel's index. */
typedef struct flat_params {
    double depth_scale;
} flat_params;
static const fs_param_def flat_table[] = {
    {"depth_scale", offsetof(flat_params, depth_scale), FS_CTYPE_DOUBLE, FS_PARAM_FLOAT, 1.0, 0.1, 10, NULL,
     "scales the depth"},
};
typedef struct flat {
    flat_params prm;
    const fs_particles *p;
    int renders;
} flat;
static flat the_flat;

static void *flat_create(const fs_method_setup *setup)
{
    memset(&the_flat, 0, sizeof the_flat);
    return fs_method_params_copy("flat", setup, &the_flat.prm, sizeof the_flat.prm) ? NULL : &the_flat;
}
static int flat_upload(void *self, const fs_particles *p, const fs_grid *g)
{
    (void)g;
    if (p->n > 1000) return fs_fail(FS_ERR_INPUT, "flat: %zu particles: too many", p->n);
    ((flat *)self)->p = p; /* read again in render */
    return FS_OK;
}
static float aov_value(size_t i) { return (float)i + 0.25f; }
static int flat_render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    flat *F = self;
    F->renders++;
    const fs_particles *p = F->p;
    float *aov = fs_gbuffer_aov(out, "test_aov"); /* NULL for the copy that declares none */
    for (int y = 0; y < out->h; y++)
        for (int x = 0; x < out->w; x++) {
            if (aov) aov[(size_t)y * out->w + x] = aov_value((size_t)y * out->w + x);
            float d[3];
            fs_camera_ray(cam, x + 0.5f, y + 0.5f, d);
            float t = (p->bmax[2] - cam->eye[2]) / d[2], hx = cam->eye[0] + t * d[0], hy = cam->eye[1] + t * d[1];
            if (hx < p->bmin[0] || hx > p->bmax[0] || hy < p->bmin[1] || hy > p->bmax[1]) continue;
            size_t i = (size_t)y * out->w + x;
            out->depth[i] = (float)(F->prm.depth_scale * (cam->eye[2] - p->bmax[2]));
            out->normal[3 * i + 2] = 1;
            out->coverage[i] = 1;
        }
    fs_stages_add(st, "flat", 0.0);
    return FS_OK;
}
static void flat_destroy(void *self) { ((flat *)self)->p = NULL; }

static const fs_aov_def flat_aovs[] = {{"test_aov", 1, 0}};
static const fs_method flat_method = {
    .name = "test_flat",
    .description = "test-only: the particles' box as a flat face",
    .paper = "",
    .aovs = flat_aovs,
    .naovs = 1,
    .params = flat_table,
    .nparams = 1,
    .params_size = sizeof(flat_params),
    .create = flat_create,
    .upload = flat_upload,
    .render = flat_render,
    .destroy = flat_destroy,
};

/* What the grid_use variants saw at upload: the grid pointer and its count. */
static const fs_grid *seen_grid;
static size_t seen_grid_n;
static int grid_upload(void *self, const fs_particles *p, const fs_grid *g)
{
    seen_grid = g;
    seen_grid_n = g ? g->n : 0;
    return flat_upload(self, p, g);
}

static const fs_method gl_method = {
    .name = "test_needs_gl", .needs_gl = 1, .params_size = 0, .create = flat_create, .destroy = flat_destroy};

/* A square of n x n particles in the plane z = 0, half-size h. */
static void square(fs_particles *p, int n, float h)
{
    fs_particles_alloc(p, (size_t)n * n, 0);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            p->x[j * n + i] = -h + 2 * h * i / (n - 1);
            p->y[j * n + i] = -h + 2 * h * j / (n - 1);
            p->z[j * n + i] = 0;
        }
    fs_particles_bounds(p);
}

static fs_scene scene;
static fs_camera camera(void)
{
    fs_camera c = {{0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 40.0f, 64, 64, 0.1f, 10.0f};
    return c;
}

static size_t covered(const fs_gbuffer *g)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)g->w * g->h; i++) n += g->coverage[i] > 0;
    return n;
}

/* Uploads a frame from a particle struct that lives only in this function. */
static int upload_from_stack(fs_run *run, float h, fs_particles *arrays)
{
    fs_particles local;
    square(&local, 8, h);
    int rc = fs_run_upload(run, &local, NULL, NULL);
    *arrays = local; /* the caller keeps the arrays alive; the struct's address dies here */
    volatile unsigned char *v = (volatile unsigned char *)&local; /* a store the compiler keeps */
    for (size_t i = 0; i < sizeof local; i++) v[i] = 0x5a;
    return rc;
}

static void registry(void)
{
    int listed = fs_method_count();
    CHECK(fs_method_register(&flat_method, FS_METHOD_HIDDEN) == FS_OK, "register: %s", fs_error_message());
    CHECK(fs_method_register(&flat_method, FS_METHOD_HIDDEN) == FS_OK, "registering again is a no-op");
    fs_method twin = flat_method;
    CHECK(fs_method_register(&twin, 0) == FS_ERR_INPUT && strstr(fs_error_message(), "registered twice"),
          "a second method of the same name is refused: %s", fs_error_message());
    CHECK(fs_method_find("test_flat") == &flat_method, "found by name");
    CHECK(fs_method_count() == listed, "a hidden method is not listed (%d vs %d)", fs_method_count(), listed);
    for (int i = 0; i < fs_method_count(); i++) CHECK(fs_method_at(i) != &flat_method, "listed at %d", i);
}

/* The EXR at path holds the core channels plus "test_aov" when want_aov, and
 * reads back with exactly that AOV and its values. */
static void check_exr_aovs(const char *path, int want_aov)
{
    fs_image img;
    CHECK(fs_read_image(path, &img) == FS_OK, "read %s: %s", path, fs_error_message());
    CHECK(img.nch == 10 + want_aov && (fs_image_channel(&img, "test_aov") >= 0) == want_aov,
          "%s: %d channels, test_aov %s", path, img.nch, want_aov ? "missing" : "there");
    fs_image_free(&img);
    fs_gbuffer back;
    float *rgba = NULL, r = 0;
    CHECK(fs_read_render(path, &back, &rgba, &r) == FS_OK, "read back: %s", fs_error_message());
    if (!rgba) return;
    const float *aov = fs_gbuffer_aov(&back, "test_aov");
    CHECK(back.naovs == want_aov && (aov != NULL) == want_aov, "%s: %d AOVs read back", path, back.naovs);
    size_t same = 0, n = (size_t)back.w * back.h;
    for (size_t i = 0; aov && i < n; i++) same += aov[i] == aov_value(i);
    CHECK(!aov || same == n, "%zu of %zu test_aov pixels read back as written", same, n);
    fs_gbuffer_free(&back);
    free(rgba);
}

/* Render, shade, provenance, EXR written and read back (with the declared AOV). */
static void render_and_read_back(void)
{
    fs_scene_defaults(&scene);
    scene.radius = 0.05f;
    CHECK(fs_scene_add_set(&scene, "test_flat.depth_scale=2") == FS_OK, "set by name: %s", fs_error_message());
    fs_particles p;
    square(&p, 8, 0.3f);
    fs_run *run = NULL;
    fs_run_image im = {0};
    fs_camera cam = camera();
    fs_stages st = {0};
    int rc = fs_run_open(&run, &flat_method, &scene, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &p, NULL, &st);
    if (!rc) rc = fs_run_render(run, &cam, &im, &st);
    if (!rc) rc = fs_run_shade(run, &cam, &im, FS_APPEARANCE_SHARED, &st);
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (rc) {
        fs_run_close(run);
        fs_particles_free(&p);
        return;
    }
    CHECK(fs_run_values(run)[0] == 2 && !strcmp(fs_run_renderer(run), "CPU"), "values and renderer");
    CHECK(fs_run_shade(run, &cam, &im, FS_APPEARANCE_OWN, NULL) == FS_ERR_INPUT, "no own appearance to show");
    const char *want[] = {"grid", "upload", "flat", "shade"};
    for (int k = 0; k < 4; k++) {
        int found = 0;
        for (int i = 0; i < st.n; i++) found |= !strcmp(st.name[i], want[k]);
        CHECK(found, "stage %s reported", want[k]);
    }
    size_t n = covered(&im.g);
    CHECK(n > 200 && n < 64 * 64 / 2, "the face covers %zu px", n);
    CHECK(im.g.naovs == 1 && fs_gbuffer_aov(&im.g, "test_aov"), "the run allocated the declared AOV (%d AOVs)",
          im.g.naovs);
    fs_provenance prov;
    fs_run_provenance(run, NULL, 7, &prov);
    const char *path = FS_TEST_OUT "/test_run_flat.exr";
    unlink(path);
    CHECK(fs_write_render(path, &im.g, im.rgba, &prov) == FS_OK, "write: %s", fs_error_message());
    fs_gbuffer back;
    float *rgba = NULL, r = 0;
    CHECK(fs_read_render(path, &back, &rgba, &r) == FS_OK, "read back: %s", fs_error_message());
    if (rgba) {
        size_t same = 0;
        for (size_t i = 0; i < 64 * 64; i++)
            same += back.coverage[i] == im.g.coverage[i] &&
                (!back.coverage[i] || (back.depth[i] == im.g.depth[i] && back.normal[3 * i + 2] == 1));
        CHECK(same == 64 * 64, "%zu of %d pixels read back as written", same, 64 * 64);
        CHECK(fabsf(im.g.depth[32 * 64 + 32] - 4.0f) < 1e-5f, "depth_scale=2 doubles the depth: %g",
              im.g.depth[32 * 64 + 32]);
        CHECK(fabsf(r - 0.05f) < 1e-7f, "r in the provenance: %g", r);
    }
    char attr[64];
    check_exr_aovs(path, 1);
    CHECK(fs_read_image_attr(path, "fluidsurf:method", attr, sizeof attr) == 1 && !strcmp(attr, "test_flat"),
          "method in the EXR: %s", attr);
    CHECK(fs_read_image_attr(path, "fluidsurf:frame", attr, sizeof attr) == 1 && !strcmp(attr, "7"), "frame: %s", attr);
    CHECK(fs_read_image_attr(path, "fluidsurf:params", attr, sizeof attr) == 1 && !strcmp(attr, "depth_scale=2"),
          "params: %s", attr);
    fs_gbuffer_free(&back);
    free(rgba);
    fs_run_image_free(&im);
    fs_run_close(run);
    fs_particles_free(&p);
}

/* The same method declaring no AOV: the G-buffer and the EXR have none. */
static void without_aovs(void)
{
    static fs_method plain;
    plain = flat_method;
    plain.name = "test_flat_plain";
    plain.aovs = NULL, plain.naovs = 0;
    fs_particles p;
    square(&p, 8, 0.3f);
    fs_run *run = NULL;
    fs_run_image im = {0};
    fs_camera cam = camera();
    int rc = fs_run_open(&run, &plain, &scene, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &p, NULL, NULL);
    if (!rc) rc = fs_run_render(run, &cam, &im, NULL);
    if (!rc) rc = fs_run_shade(run, &cam, &im, FS_APPEARANCE_SHARED, NULL);
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (!rc) {
        CHECK(im.g.naovs == 0 && !fs_gbuffer_aov(&im.g, "test_aov"), "%d AOVs without a declaration", im.g.naovs);
        fs_provenance prov;
        fs_run_provenance(run, NULL, 0, &prov);
        const char *path = FS_TEST_OUT "/test_run_plain.exr";
        unlink(path);
        CHECK(fs_write_render(path, &im.g, im.rgba, &prov) == FS_OK, "write: %s", fs_error_message());
        check_exr_aovs(path, 0);
    }
    fs_run_image_free(&im);
    fs_run_close(run);
    fs_particles_free(&p);
}

/* The G-buffer's AOV list: added once, shapes checked, cleared; a 4-component
 * AOV written as NAME.R/G/B/A and read back by name. */
static void aov_list(void)
{
    fs_gbuffer g;
    CHECK(fs_gbuffer_alloc(&g, 4, 2) == FS_OK && g.naovs == 0 && !fs_gbuffer_aov(&g, FS_AOV_OWN), "none at first");
    CHECK(fs_gbuffer_add_aov(&g, FS_AOV_OWN, 4) == FS_OK && fs_gbuffer_add_aov(&g, "extra", 1) == FS_OK &&
              fs_gbuffer_add_aov(&g, FS_AOV_OWN, 4) == FS_OK && g.naovs == 2,
          "added once each: %d", g.naovs);
    CHECK(fs_gbuffer_add_aov(&g, FS_AOV_COLOR, 1) == FS_ERR_INPUT, "color has 4 components");
    CHECK(fs_gbuffer_add_aov(&g, "a.b", 1) == FS_ERR_INPUT && fs_gbuffer_add_aov(&g, "x", 3) == FS_ERR_INPUT,
          "no '.' in a name, 1 or 4 components");
    float *own = fs_gbuffer_aov(&g, FS_AOV_OWN), *extra = fs_gbuffer_aov(&g, "extra");
    for (int i = 0; i < 8; i++) extra[i] = (float)i, own[4 * i + 3] = 0.5f;
    float rgba[32] = {0};
    fs_provenance prov = {0};
    const char *path = FS_TEST_OUT "/test_run_aovs.exr";
    CHECK(fs_write_render(path, &g, rgba, &prov) == FS_OK, "write: %s", fs_error_message());
    fs_gbuffer back;
    float *brgba = NULL, r;
    CHECK(fs_read_render(path, &back, &brgba, &r) == FS_OK, "read back: %s", fs_error_message());
    if (brgba) {
        CHECK(back.naovs == 2, "%d AOVs read back", back.naovs); /* in the file's order: EXR sorts channels */
        const float *bo = fs_gbuffer_aov(&back, FS_AOV_OWN), *be = fs_gbuffer_aov(&back, "extra");
        CHECK(bo && be && bo[4 * 7 + 3] == 0.5f && bo[4 * 7] == 0 && be[7] == 7, "values read back");
        fs_gbuffer_free(&back);
        free(brgba);
    }
    fs_gbuffer_clear(&g);
    CHECK(extra[7] == 0 && own[3] == 0, "clear zeroes the AOVs");
    fs_gbuffer_free(&g);
}

/* The method keeps the pointer it was given at upload; the caller's struct is
 * gone by render (the viewer's old bug). A bigger frame must show bigger. */
static void lifetime_and_failures(void)
{
    fs_run *run = NULL;
    fs_run_image im = {0};
    fs_camera cam = camera();
    fs_particles a = {0}, b = {0}, big, empty = {0};
    CHECK(fs_run_open(&run, &flat_method, &scene, NULL, NULL) == FS_OK, "open: %s", fs_error_message());
    if (!run) return;
    CHECK(fs_run_render(run, &cam, &im, NULL) == FS_ERR_RUNTIME && strstr(fs_error_message(), "no frame uploaded"),
          "render before any upload says so: %s", fs_error_message());
    CHECK(upload_from_stack(run, 0.2f, &a) == FS_OK && fs_run_render(run, &cam, &im, NULL) == FS_OK, "small: %s",
          fs_error_message());
    size_t small = covered(&im.g);
    CHECK(upload_from_stack(run, 0.4f, &b) == FS_OK && fs_run_render(run, &cam, &im, NULL) == FS_OK, "large: %s",
          fs_error_message());
    size_t large = covered(&im.g);
    CHECK(small > 50 && large > 3 * small, "the method saw each frame: %zu then %zu px", small, large);
    fs_particles_free(&a); /* the first frame's arrays: no longer held */

    square(&big, 40, 0.3f); /* 1600 particles: the method refuses them */
    CHECK(fs_run_upload(run, &big, NULL, NULL) == FS_ERR_INPUT, "upload refused");
    CHECK(fs_run_render(run, &cam, &im, NULL) == FS_ERR_RUNTIME && strstr(fs_error_message(), "too many"),
          "after a failed upload, render refuses with the reason: %s", fs_error_message());
    CHECK(im.g.w == cam.width && im.g.h == cam.height && covered(&im.g) == 0, "and leaves an empty image to show");
    fs_run *fresh = NULL; /* a first upload that fails: the image is still sized to the camera */
    fs_run_image im2 = {0};
    CHECK(fs_run_open(&fresh, &flat_method, &scene, NULL, NULL) == FS_OK &&
              fs_run_upload(fresh, &big, NULL, NULL) != FS_OK && fs_run_render(fresh, &cam, &im2, NULL) != FS_OK &&
              im2.g.w == cam.width && covered(&im2.g) == 0,
          "a failed first upload: %dx%d image", im2.g.w, im2.g.h);
    fs_run_close(fresh);
    fs_run_image_free(&im2);
    CHECK(fs_run_upload(run, &b, NULL, NULL) == FS_OK && fs_run_render(run, &cam, &im, NULL) == FS_OK &&
              covered(&im.g) == large,
          "the next upload recovers: %s", fs_error_message());

    int before = the_flat.renders;
    CHECK(fs_run_upload(run, &empty, NULL, NULL) == FS_OK && fs_run_render(run, &cam, &im, NULL) == FS_OK,
          "an empty frame renders: %s", fs_error_message());
    CHECK(covered(&im.g) == 0 && the_flat.renders == before, "empty image, the method not called");
    fs_particles unbounded = b;
    unbounded.bmin[0] = 1, unbounded.bmax[0] = -1;
    CHECK(fs_run_upload(run, &unbounded, NULL, NULL) == FS_ERR_INPUT && strstr(fs_error_message(), "bounding box"),
          "a frame without bounds is refused: %s", fs_error_message());
    fs_run_close(run);
    fs_run_image_free(&im);
    fs_particles_free(&b);
    fs_particles_free(&big);
}

/* The run builds a grid only for a method that reads it, and hands it over
 * whole; an FS_GRID_AT_UPLOAD method still renders once the run has freed it. */
static void grid_use(void)
{
    static const int uses[] = {FS_GRID_KEPT, FS_GRID_AT_UPLOAD, FS_GRID_UNUSED};
    fs_particles p;
    square(&p, 8, 0.3f);
    fs_camera cam = camera();
    for (int u = 0; u < 3; u++) {
        fs_method m = flat_method;
        m.name = "test_flat_grid";
        m.grid_use = uses[u];
        m.upload = grid_upload;
        fs_run *run = NULL;
        fs_run_image im = {0};
        fs_stages st = {0};
        seen_grid = (const fs_grid *)&p; /* anything but NULL */
        int rc = fs_run_open(&run, &m, &scene, NULL, NULL);
        if (!rc) rc = fs_run_upload(run, &p, NULL, &st);
        if (!rc) rc = fs_run_render(run, &cam, &im, NULL);
        CHECK(rc == FS_OK && covered(&im.g) > 200, "grid_use %d renders: %s", uses[u], fs_error_message());
        int timed = 0;
        for (int i = 0; i < st.n; i++) timed |= !strcmp(st.name[i], "grid");
        if (uses[u] == FS_GRID_UNUSED)
            CHECK(seen_grid == NULL && !timed, "unused: no grid built (%p, stage %d)", (const void *)seen_grid, timed);
        else
            CHECK(seen_grid && seen_grid_n == p.n && timed, "grid_use %d: a grid of all %zu particles (%zu)", uses[u],
                  p.n, seen_grid_n);
        fs_run_close(run);
        fs_run_image_free(&im);
    }
    fs_particles_free(&p);
}

static void gl_without_context(void)
{
    fs_run *run = NULL;
    CHECK(fs_run_open(&run, &gl_method, &scene, NULL, NULL) == FS_ERR_RUNTIME && run == NULL &&
              strstr(fs_error_message(), "needs a current OpenGL 4.5 context"),
          "a GL method without a context: %s", fs_error_message());
}

int main(void)
{
    registry();
    render_and_read_back();
    without_aovs();
    aov_list();
    lifetime_and_failures();
    grid_use();
    gl_without_context();
    TEST_DONE();
}
