/* volume_raycast's march over the layered build and over the slice build of the
 * same particles hits the same surface (issue 52, part 3): the frame of
 * experiments/tools/inacio_tables' Table I cells (the SPH dam break, grid_res 128,
 * thickness=off: the rays stop at the surface, the container framed), whose
 * march timed 0.1 ms on the layered volume and 2-5 ms on the slice one on an
 * H200. Every pixel both builds cover has hit depths within one grid spacing,
 * the masks nearly agree, and the surface covers a real part of the image but
 * not the whole box: an empty, clipped or saturated layered volume fails here.
 * The exact CPU grid is checked the same way, as the third witness. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "builtin_methods.h"
#include "density_grid.h"
#include "method.h"
#include "run.h"
#include "scene.h"
#include "sph.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { SIZE = 128, GRID = 128 };

/* One G-buffer of volume_raycast with build `build` on p into im; FS_OK or the error. */
static int render_build(const fs_scene *base, const char *build, const fs_particles *p, fs_run_image *im)
{
    static fs_scene sc; /* fs_run keeps a pointer to it until closed */
    sc = *base;
    char set[64];
    snprintf(set, sizeof set, "volume_raycast.build=%s", build);
    fs_run *run = NULL;
    int rc = fs_scene_add_set(&sc, set);
    if (!rc) rc = fs_run_open(&run, fs_method_find("volume_raycast"), &sc, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, p, NULL, NULL);
    if (!rc) rc = fs_run_render(run, &sc.camera, im, NULL);
    fs_run_close(run);
    CHECK(rc == FS_OK, "%s: %s", build, fs_error_message());
    return rc;
}

/* b against a: the masks and the hit depths where both hit. */
static void compare_builds(const char *name, const fs_gbuffer *a, const fs_gbuffer *b, double spacing)
{
    size_t n = (size_t)SIZE * SIZE, na = 0, nb = 0, both = 0, over = 0;
    double worst = 0;
    for (size_t i = 0; i < n; i++) {
        int ha = a->coverage[i] > 0, hb = b->coverage[i] > 0;
        na += ha, nb += hb;
        if (!ha || !hb) continue;
        both++;
        double d = fabs((double)a->depth[i] - b->depth[i]);
        if (d > worst) worst = d;
        over += d > spacing;
    }
    double iou = (na + nb - both) ? (double)both / (double)(na + nb - both) : 0;
    printf("%s vs layered: covered %zu / %zu of %zu pixels, IoU %.5f, worst depth difference %.3g (spacing %.3g), "
           "%zu beyond\n",
           name, nb, na, n, iou, worst, spacing, over);
    /* a surface, not nothing and not the whole box (a saturated volume would hit at every entry) */
    CHECK(na >= n / 20 && na <= n * 3 / 4, "layered covers %zu of %zu pixels", na, n);
    CHECK(iou >= 0.99, "%s: mask IoU %.5f against layered", name, iou);
    CHECK(over == 0, "%s: %zu pixels' hit depths differ from layered's by more than the spacing %g (worst %g)", name,
          over, spacing, worst);
}

/* The three builds of inacio_tables' frame, each against the layered one. */
static void check_builds(void)
{
    /* inacio_tables' frame: the dam break, one settled frame of 1/60 s, the CPU path */
    fs_sph_params prm;
    fs_sph_params_default(&prm);
    fs_sph *sim = NULL;
    fs_particles p = {0};
    CHECK(fs_sph_create(&sim, "dam_break", 1024, &prm, 0) == FS_OK, "simulator: %s", fs_error_message());
    CHECK(sim && fs_sph_advance(sim, 1.0 / 60) == FS_OK && fs_sph_get(sim, &p) == FS_OK, "advance: %s",
          fs_error_message());
    static fs_scene sc;
    fs_scene_defaults(&sc);
    sc.radius = prm.r;
    char set[64];
    snprintf(set, sizeof set, "volume_raycast.grid_res=%d", GRID);
    CHECK(fs_scene_add_set(&sc, set) == FS_OK && fs_scene_add_set(&sc, "volume_raycast.thickness=off") == FS_OK,
          "scene: %s", fs_error_message());
    float lo[3], hi[3];
    if (sim) fs_sph_box(sim, lo, hi);
    sc.camera.width = sc.camera.height = SIZE;
    fs_scene_finish_camera(&sc, lo, hi);
    /* the volume's spacing: the method's grid over the same particles */
    fs_field f = fs_scene_field(&sc);
    fs_density_grid shape = {0};
    CHECK(p.n && fs_density_grid_init(&shape, p.bmin, p.bmax, f.H, GRID) == FS_OK, "grid: %s", fs_error_message());
    fs_run_image im[3] = {0};
    const char *builds[3] = {"layered", "slice", "exact"};
    int ok = p.n > 0;
    for (int k = 0; k < 3 && ok; k++) ok = render_build(&sc, builds[k], &p, &im[k]) == FS_OK;
    if (ok)
        for (int k = 1; k < 3; k++) compare_builds(builds[k], &im[0].g, &im[k].g, shape.spacing);
    for (int k = 0; k < 3; k++) fs_run_image_free(&im[k]);
    fs_density_grid_free(&shape);
    fs_particles_free(&p);
    fs_sph_destroy(sim);
}

int main(void)
{
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx) == FS_OK) {
        fs_methods_register_builtin();
        check_builds();
        fs_gl_context_destroy(&ctx);
    }
    TEST_DONE();
}
