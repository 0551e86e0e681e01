/* surfels (iwasaki2006) on the OSMesa context: surfel extraction on an exact
 * spherical field (positions on the iso-surface, radial normals, gap filling),
 * the method against the CPU reference on a real dam break (coverage IoU),
 * splat vs exact density grid giving the same surface, the own appearance and
 * caustics AOV, and the exports. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "metrics.h"
#include "particle_io.h"
#include "scene.h"
#include "../methods/surfels/surfel_extract.h"
#include "test_render.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* (a) phi = 1 - |x|^2 / 4 on a grid of spacing 0.1 around the origin: the
 * iso 0.75 surface is the unit sphere. */
static void extraction_on_sphere(void)
{
    fs_density_grid g;
    float lo[3] = {-1.5f, -1.5f, -1.5f}, hi[3] = {1.5f, 1.5f, 1.5f};
    CHECK(fs_density_grid_init(&g, lo, hi, 0.0f, 31) == FS_OK, "init: %s", fs_error_message());
    for (int k = 0; k < g.dim[2]; k++)
        for (int j = 0; j < g.dim[1]; j++)
            for (int i = 0; i < g.dim[0]; i++) {
                float x = g.origin[0] + i * g.spacing, y = g.origin[1] + j * g.spacing, z = g.origin[2] + k * g.spacing;
                g.data[fs_density_grid_index(&g, i, j, k)] = 1.0f - (x * x + y * y + z * z) / 4.0f;
            }
    fs_surfel_set set = {0};
    size_t added = 0;
    fs_surfel_extract_opts o = {0.75f, 1.0f, 0.0f};
    CHECK(fs_surfels_extract(&g, &o, &set, &added) == FS_OK, "extract: %s", fs_error_message());
    size_t plain = set.n;
    double max_r = 0, max_deg = 0;
    for (size_t i = 0; i < set.n; i++) {
        const fs_surfel *s = &set.s[i];
        float r = sqrtf(s->pos[0] * s->pos[0] + s->pos[1] * s->pos[1] + s->pos[2] * s->pos[2]);
        float c = (s->pos[0] * s->normal[0] + s->pos[1] * s->normal[1] + s->pos[2] * s->normal[2]) / r;
        max_r = fmax(max_r, fabs(r - 1.0));
        max_deg = fmax(max_deg, acos(fmin(c, 1.0)) * 180 / M_PI);
        CHECK(fabsf(s->radius - g.spacing) < 1e-6f, "radius %g", s->radius);
    }
    printf("(a) sphere: %zu surfels, |r - 1| <= %.4f, normal <= %.2f deg\n", set.n, max_r, max_deg);
    /* the sphere's area over the grid cell face area, times about 1.5 edge crossings per face */
    CHECK(set.n > 4 * M_PI / (0.1 * 0.1), "only %zu surfels", set.n);
    /* linear interpolation of a quadratic: error below spacing^2 / 8 / |grad| */
    CHECK(max_r < 0.01, "surfels off the sphere by %g", max_r);
    CHECK(max_deg < 3.0, "normal off radial by %g deg", max_deg);
    CHECK(added == 0, "gap filling off but %zu added", added);
    o.gap = 0.5f;
    CHECK(fs_surfels_extract(&g, &o, &set, &added) == FS_OK, "extract: %s", fs_error_message());
    printf("(a) with gap 0.5: %zu surfels (%zu added)\n", set.n, added);
    CHECK(added > 0 && set.n == plain + added, "gap filling: %zu + %zu vs %zu", plain, added, set.n);
    for (size_t i = plain; i < set.n; i++) {
        const fs_surfel *s = &set.s[i];
        float r = sqrtf(s->pos[0] * s->pos[0] + s->pos[1] * s->pos[1] + s->pos[2] * s->pos[2]);
        max_r = fmax(max_r, fabs(r - 1.0));
    }
    CHECK(max_r < 0.01, "gap surfels off the sphere by %g", max_r);
    fs_surfel_set_free(&set);
    fs_density_grid_free(&g);
}

static int load_dam(fs_particles *p, fs_scene *s, fs_field *f)
{
    int rc = fs_test_load_dam(p, s, f);
    CHECK(rc == FS_OK, "read: %s", fs_error_message());
    return rc;
}

/* (b) The bar at test size: coverage IoU against the reference with
 * the same field; the exact CPU grid gives the same surface as the splatted one. */
static void against_reference(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (load_dam(&p, &s, &f)) return;
    fs_gbuffer a, b, c;
    fs_gbuffer_alloc(&a, 128, 128);
    fs_gbuffer_alloc(&b, 128, 128);
    fs_gbuffer_alloc(&c, 128, 128);
    fs_stages st = {0};
    const char *splat[] = {"grid_res=128", NULL}, *exact[] = {"grid_res=128", "grid_build=exact", NULL};
    CHECK(fs_test_render("surfels", splat, &p, f, &s.camera, &a, &st) == FS_OK, "surfels: %s", fs_error_message());
    CHECK(fs_test_render("reference", NULL, &p, f, &s.camera, &b, NULL) == FS_OK, "reference: %s", fs_error_message());
    CHECK(fs_test_render("surfels", exact, &p, f, &s.camera, &c, NULL) == FS_OK, "surfels exact: %s",
          fs_error_message());
    fs_metrics mt, me;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, f.r, &mt) == FS_OK, "metrics: %s", fs_error_message());
    CHECK(fs_metrics_compute(&a, NULL, &c, NULL, f.r, &me) == FS_OK, "metrics: %s", fs_error_message());
    printf("(b) dam break 6859 at 128^2 vs reference: IoU %.4f, depth bias %.4f r, p95 %.4f r, normal %.2f deg; "
           "splat vs exact grid: IoU %.5f, normal %.3f deg\n",
           mt.mask_iou, mt.depth_bias_r, mt.depth_p95_r, mt.normal_mean_deg, me.mask_iou, me.normal_mean_deg);
    CHECK(mt.n_both > 1500, "only %zu pixels covered by both", mt.n_both);
    CHECK(mt.mask_iou >= 0.95, "IoU %g", mt.mask_iou);
    CHECK(mt.depth_p95_r <= 0.5, "depth p95 %g r", mt.depth_p95_r);
    CHECK(mt.interior_normal_mean_deg < 10, "interior normal %g deg", mt.interior_normal_mean_deg);
    CHECK(me.mask_iou > 0.999 && me.normal_mean_deg < 0.5, "splat and exact grids disagree: IoU %g, %g deg",
          me.mask_iou, me.normal_mean_deg);
    const char *want[] = {"density_grid", "extract", "caustics", "visibility", "blend", "normalize", "thickness", NULL};
    const char *missing = fs_test_missing_stage(&st, want);
    CHECK(!missing, "stage %s not reported", missing);
    double thick = 0;
    for (int i = 0; i < 128 * 128; i++) thick += a.thickness[i];
    CHECK(thick > 0, "no thickness");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    fs_gbuffer_free(&c);
    fs_particles_free(&p);
}

/* (c) The own appearance: water pixels differ from what is behind them; sky
 * pixels hold exactly the background and no caustics; some floor under the
 * water carries caustic light. (d) The exports. */
static void own_appearance_and_exports(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (load_dam(&p, &s, &f)) return;
    const fs_method *m = fs_method_find("surfels");
    static fs_scene s2; /* the same scene without the object, for the second run */
    fs_scene_add_set(&s, "surfels.grid_res=96");
    s2 = s;
    fs_scene_add_set(&s2, "surfels.object=none");
    fs_run *run = NULL;
    fs_run_image im = {0};
    int rc = fs_run_open(&run, m, &s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &p, NULL, NULL);
    if (!rc) rc = fs_run_render(run, &s.camera, &im, NULL);
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (rc) {
        fs_run_close(run);
        fs_run_image_free(&im);
        fs_particles_free(&p);
        return;
    }
    const fs_gbuffer g = im.g;
    const float *own = fs_gbuffer_aov(&g, FS_AOV_OWN), *caustics = fs_gbuffer_aov(&g, FS_AOV_CAUSTICS);
    CHECK(own && caustics, "the declared AOVs own and caustics are there");
    if (!own || !caustics) {
        fs_run_close(run);
        fs_run_image_free(&im);
        fs_particles_free(&p);
        return;
    }
    size_t water = 0, caustic_water = 0, sky = 0, sky_caustic = 0;
    for (int i = 0; i < 128 * 128; i++) {
        const float *o = own + 4 * i;
        CHECK(isfinite(o[0]) && isfinite(o[1]) && isfinite(o[2]) && o[3] == 1.0f, "pixel %d not finite", i);
        if (g.coverage[i] > 0) {
            water++;
            caustic_water += caustics[i] > 0;
        } else if (i < 128 * 8) { /* the top rows see the sky */
            sky++;
            sky_caustic += caustics[i] != 0;
        }
    }
    printf("(c) own appearance: %zu water px (%zu see caustic light), %zu sky px\n", water, caustic_water, sky);
    CHECK(water > 1500, "only %zu water pixels", water);
    CHECK(caustic_water > water / 4, "only %zu of %zu water pixels see lit floor", caustic_water, water);
    CHECK(sky > 0 && sky_caustic == 0, "%zu of %zu sky pixels carry caustics", sky_caustic, sky);

    /* the object under the water changes the own image, never the G-buffer */
    fs_run *plain = NULL;
    fs_run_image him = {0};
    rc = fs_run_open(&plain, m, &s2, NULL, NULL);
    if (!rc) rc = fs_run_upload(plain, &p, NULL, NULL);
    if (!rc) rc = fs_run_render(plain, &s.camera, &him, NULL);
    CHECK(rc == FS_OK, "render without object: %s", fs_error_message());
    const fs_gbuffer h = him.g;
    const float *hown = fs_gbuffer_aov(&h, FS_AOV_OWN);
    size_t changed = 0, gdiff = 0;
    for (int i = 0; !rc && i < 128 * 128; i++) {
        float d = fabsf(own[4 * i] - hown[4 * i]) + fabsf(own[4 * i + 2] - hown[4 * i + 2]);
        changed += d > 0.02f;
        gdiff += g.coverage[i] != h.coverage[i] || (g.coverage[i] > 0 && g.depth[i] != h.depth[i]);
    }
    printf("(c) object box vs none: %zu own pixels change, %zu G-buffer pixels\n", changed, gdiff);
    CHECK(changed > 20, "the object shows in only %zu pixels", changed);
    CHECK(gdiff == 0, "the object changed %zu G-buffer pixels", gdiff);
    fs_run_close(plain);
    fs_run_image_free(&him);

    const char *ply = FS_TEST_OUT "/surfels_export.ply", *vdb = FS_TEST_OUT "/surfels_export.vdb";
    unlink(ply);
    unlink(vdb);
    CHECK(fs_run_export(run, ply, NULL) == FS_OK, "ply: %s", fs_error_message());
    fs_particles q;
    CHECK(fs_particles_read(&q, ply, NULL) == FS_OK, "read ply back: %s", fs_error_message());
    CHECK(q.n > 1000, "only %zu surfels in the PLY", q.n);
    fs_particles_free(&q);
#if FS_WITH_OPENVDB
    CHECK(fs_run_export(run, vdb, NULL) == FS_OK, "vdb: %s", fs_error_message());
    fs_density_grid d;
    CHECK(fs_density_grid_read_vdb(&d, vdb, "density") == FS_OK, "read vdb back: %s", fs_error_message());
    fs_density_grid_free(&d);
#else
    int vrc = fs_run_export(run, vdb, NULL);
    CHECK_REFUSED(vrc, fs_error_message(), vdb, "FS_WITH_OPENVDB");
#endif
    CHECK(fs_run_export(run, FS_TEST_OUT "/surfels_export.txt", NULL) == FS_ERR_INPUT, "a .txt export must be refused");
    CHECK(access(FS_TEST_OUT "/surfels_export.txt", F_OK) != 0, "a refused export left a file");
    fs_run_close(run);
    fs_run_image_free(&im);
    fs_particles_free(&p);
}

int main(void)
{
    fs_methods_register_builtin();
    extraction_on_sphere();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    against_reference();
    own_appearance_and_exports();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
