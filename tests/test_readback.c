/* The read back through pixel pack buffers (common/gl/gl_readback.c) against the
 * old synchronous path (FLUIDSURF_READBACK=sync), on the OSMesa context: every
 * GL method renders the 6,859-particle dam break through both, each view is
 * written to an EXR (as `fluidsurf render -o x.exr` writes it), and the two files'
 * channels must be equal bit for bit. At two sizes, one not square, so that a
 * wrong row flip or a buffer kept too small from the first size shows. A run
 * that leaves out the own look's layers (fs_run_shared_only) must give the same
 * core layers and no own layer. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "image_io.h"
#include "builtin_methods.h"
#include "render_output.h"
#include "run.h"
#include "scene.h"
#include "test_render.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static const char *const methods[] = {"spheres", "raycast_pca", "aniso_ssf", "surfels", "volume_raycast", "mesh"};

/* Renders and shades one view through a fresh run of m, sync or not, into EXR path. */
static int render_exr(const fs_method *m, const fs_scene *s, const fs_particles *p, const fs_camera *cam, int sync,
                      int shared_only, const char *path, fs_run_image *im)
{
    if (sync) setenv("FLUIDSURF_READBACK", "sync", 1);
    else unsetenv("FLUIDSURF_READBACK");
    fs_run *run = NULL;
    int rc = fs_run_open(&run, m, s, NULL, NULL);
    if (!rc) fs_run_shared_only(run, shared_only);
    if (!rc) rc = fs_run_upload(run, p, NULL, NULL);
    if (!rc) rc = fs_run_render(run, cam, im, NULL);
    if (!rc) rc = fs_run_shade(run, cam, im, FS_APPEARANCE_SHARED, NULL);
    fs_provenance prov;
    if (!rc) fs_run_provenance(run, NULL, 0, &prov);
    if (!rc) rc = fs_write_render(path, &im->g, im->rgba, &prov);
    fs_run_close(run);
    unsetenv("FLUIDSURF_READBACK");
    return rc;
}

/* Channels of a that differ from b's bit for bit (or are missing there). */
static int differing_channels(const fs_image *a, const fs_image *b, const char *what)
{
    int bad = 0;
    size_t n = (size_t)a->w * a->h;
    for (int c = 0; c < a->nch; c++) {
        int k = fs_image_channel(b, a->chnames[c]);
        size_t diff = k < 0 ? n : 0;
        for (size_t i = 0; k >= 0 && i < n; i++) {
            uint32_t x, y;
            memcpy(&x, &a->pix[i * a->nch + c], 4);
            memcpy(&y, &b->pix[i * b->nch + k], 4);
            diff += x != y;
        }
        if (diff) printf("  %s: channel %s: %zu of %zu pixels differ\n", what, a->chnames[c], diff, n);
        bad += diff != 0;
    }
    return bad;
}

/* Two EXRs, channel by channel; extra: channels a has beyond b's (the own look). */
static void compare_files(const char *pa, const char *pb, int extra, const char *what)
{
    fs_image a = {0}, b = {0};
    int rc = fs_read_image(pa, &a);
    if (!rc) rc = fs_read_image(pb, &b);
    CHECK(rc == FS_OK, "%s: read: %s", what, fs_error_message());
    if (!rc) {
        CHECK(a.w == b.w && a.h == b.h && a.nch == b.nch + extra, "%s: %dx%dx%d against %dx%dx%d", what, a.w, a.h,
              a.nch, b.w, b.h, b.nch);
        int bad = a.w == b.w && a.h == b.h ? differing_channels(&b, &a, what) : 1;
        CHECK(bad == 0, "%s: %d channels differ", what, bad);
    }
    fs_image_free(&a);
    fs_image_free(&b);
}

/* One method at one size: the old path, the new one, the new one without the own look. */
static void one(const fs_method *m, const fs_scene *s, const fs_particles *p, int w, int h)
{
    fs_camera cam = s->camera;
    cam.width = w;
    cam.height = h;
    char paths[3][512], what[128];
    const char *tag[3] = {"sync", "async", "shared"};
    fs_run_image im[3];
    memset(im, 0, sizeof im);
    int rc = FS_OK;
    for (int k = 0; k < 3 && !rc; k++) {
        snprintf(paths[k], sizeof paths[k], "%s/readback_%s_%dx%d_%s.exr", FS_TEST_OUT, m->name, w, h, tag[k]);
        rc = render_exr(m, s, p, &cam, k == 0, k == 2, paths[k], &im[k]);
    }
    snprintf(what, sizeof what, "%s %dx%d", m->name, w, h);
    CHECK(rc == FS_OK, "%s: %s", what, fs_error_message());
    size_t covered = 0;
    for (size_t i = 0; !rc && i < (size_t)w * h; i++) covered += im[1].g.coverage[i] > 0;
    int own_layers =
        !rc && fs_gbuffer_aov(&im[1].g, FS_AOV_OWN) ? 4 + (fs_gbuffer_aov(&im[1].g, FS_AOV_CAUSTICS) != 0) : 0;
    printf("%s: %zu pixels covered, %d own-look channels\n", what, covered, own_layers);
    CHECK(rc || covered > (size_t)w * h / 20, "%s: only %zu pixels covered", what, covered);
    CHECK(rc || !fs_gbuffer_aov(&im[2].g, FS_AOV_OWN), "%s: a shared-only run has an own layer", what);
    if (!rc) {
        compare_files(paths[0], paths[1], 0, what);
        compare_files(paths[1], paths[2], own_layers, what);
    }
    for (int k = 0; k < 3; k++) fs_run_image_free(&im[k]);
}

/* Every GL method of this build at the two sizes. */
static void all_methods(void)
{
    fs_particles p;
    static fs_scene s;
    fs_field f;
    CHECK(fs_test_load_dam(&p, &s, &f) == FS_OK, "dam break: %s", fs_error_message());
    /* coarse grids keep surfels and volume_raycast fast on llvmpipe */
    fs_scene_add_set(&s, "surfels.grid_res=64");
    fs_scene_add_set(&s, "surfels.caustic_map=64");
    fs_scene_add_set(&s, "volume_raycast.grid_res=64");
    for (size_t i = 0; i < sizeof methods / sizeof *methods && p.n; i++) {
        const fs_method *m = fs_method_find(methods[i]);
        if (!m) { /* mesh: not in a build without OpenVDB */
            printf("%s: not in this build\n", methods[i]);
            continue;
        }
        one(m, &s, &p, 64, 64);
        one(m, &s, &p, 72, 40);
    }
    fs_particles_free(&p);
}

int main(void)
{
    fs_methods_register_builtin();
    fs_gl_context ctx;
    if (!fs_test_gl_context(&ctx)) {
        all_methods();
        fs_gl_context_destroy(&ctx);
    }
    TEST_DONE();
}
