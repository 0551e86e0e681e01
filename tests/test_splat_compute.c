/* The compute splatter (common/gl/gl_splat.h) gives the raster's G-buffer: for
 * every method with the splat parameter (spheres; raycast_pca's entry and
 * thickness spheres; aniso_ssf's ellipsoids, and its spheres with anisotropy
 * off) on the demo's frame (the 24,389-particle dam break) and the front of the
 * shared DualSPHysics frame (experiments/data/dualsphysics/), splat=compute
 * against splat=raster on llvmpipe, the methods' whole output: the same mask
 * (IoU 1), depth within 1e-6 relative, normals within 0.01 degrees, thickness
 * within 1e-3 r per pixel; also with every sprite of more than one pixel split
 * over a workgroup (splat_large_px=1). The comparison is shown to catch one sprite
 * left out, and the compute stages to be named apart from the raster's. */
#include "fs_error.h"
#include "frame_source.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "particle_io.h"
#include "builtin_methods.h"
#include "scene.h"
#include "test_render.h"
#include <math.h>
#include <stdlib.h>

#define SIZE 112 /* pixels: the sprites of both frames span 1 to about 10 pixels across */

typedef struct frame {
    const char *name;
    fs_particles p;
    fs_field f;
    fs_camera cam;
} frame;

/* The largest differences of b from a over the pixels both cover. */
typedef struct diff {
    double iou, depth_rel, normal_deg, thick_r;
} diff;

static diff compare(const fs_gbuffer *a, const fs_gbuffer *b, float r)
{
    diff d = {0, 0, 0, 0};
    size_t both = 0, any = 0, n = (size_t)a->w * a->h;
    for (size_t i = 0; i < n; i++) {
        int ca = a->coverage[i] >= 0.5f, cb = b->coverage[i] >= 0.5f;
        both += ca && cb;
        any += ca || cb;
        d.thick_r = fmax(d.thick_r, fabs((double)a->thickness[i] - b->thickness[i]) / r);
        if (!(ca && cb)) continue;
        d.depth_rel = fmax(d.depth_rel, fabs((double)a->depth[i] - b->depth[i]) / fabs((double)a->depth[i]));
        const float *na = a->normal + 3 * i, *nb = b->normal + 3 * i;
        double dot = (na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2]) /
            sqrt((na[0] * na[0] + na[1] * na[1] + na[2] * na[2]) * (nb[0] * nb[0] + nb[1] * nb[1] + nb[2] * nb[2]));
        d.normal_deg = fmax(d.normal_deg, acos(fmin(1.0, dot)) * 180.0 / M_PI);
    }
    d.iou = any ? (double)both / any : 1.0;
    return d;
}

static int equal_output(diff d)
{
    return d.iou == 1.0 && d.depth_rel <= 1e-6 && d.normal_deg <= 0.01 && d.thick_r <= 1e-3;
}

static void print_diff(const char *what, diff d)
{
    printf("%-44s IoU %.6f  depth %.2g rel  normal %.2g deg  thickness %.2g r\n", what, d.iou, d.depth_rel,
           d.normal_deg, d.thick_r);
}

/* Renders method on p with the NULL-terminated settings. */
static int render(const frame *fr, const fs_particles *p, const char *method, const char *const *sets, fs_gbuffer *g,
                  fs_stages *st)
{
    int rc = fs_test_render(method, sets, p, fr->f, &fr->cam, g, st);
    CHECK(rc == FS_OK, "%s %s on %s: %s", method, sets[0], fr->name, fs_error_message());
    return rc;
}

/* The stage names of a compute render: splat_compute and thickness_compute,
 * never the raster's. */
static void check_stages(const fs_stages *st, const char *what)
{
    const char *want[] = {"splat_compute", "thickness_compute", NULL};
    const char *miss = fs_test_missing_stage(st, want);
    CHECK(!miss, "%s: no stage %s", what, miss ? miss : "");
    for (int k = 0; k < st->n; k++)
        CHECK(strcmp(st->name[k], "splat") && strcmp(st->name[k], "thickness"), "%s: a raster stage %s", what,
              st->name[k]);
}

/* splat=compute against splat=raster, both with setting `both` (may be NULL),
 * the compute render also with `extra` (may be NULL). */
static void test_equal(const frame *fr, const char *method, const char *both, const char *extra)
{
    fs_gbuffer a = {0}, b = {0};
    fs_stages st = {0};
    char what[128];
    snprintf(what, sizeof what, "%s%s%s, %s%s%s", method, both ? " " : "", both ? both : "", fr->name,
             extra ? ", " : "", extra ? extra : "");
    const char *raster[] = {"splat=raster", both, NULL};
    const char *compute[] = {"splat=compute", both ? both : extra, both ? extra : NULL, NULL};
    if (!render(fr, &fr->p, method, raster, &a, NULL) && !render(fr, &fr->p, method, compute, &b, &st)) {
        diff d = compare(&a, &b, fr->f.r);
        print_diff(what, d);
        CHECK(equal_output(d), "%s: the compute splatter's G-buffer differs from the raster's", what);
        check_stages(&st, what);
    }
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

/* The particle nearest the camera left out of the compute render: the
 * comparison must see it (so a dropped sprite cannot pass). */
static void test_dropped_sprite(const frame *fr)
{
    float v[16];
    fs_camera_view_matrix(&fr->cam, v);
    size_t near = 0;
    double best = INFINITY;
    for (size_t i = 0; i < fr->p.n; i++) {
        double z = -(v[2] * fr->p.x[i] + v[6] * fr->p.y[i] + v[10] * fr->p.z[i] + v[14]);
        if (z < best) best = z, near = i;
    }
    fs_particles q;
    CHECK(fs_particles_alloc(&q, fr->p.n - 1, 0) == FS_OK, "alloc");
    for (size_t i = 0, k = 0; i < fr->p.n; i++)
        if (i != near) q.x[k] = fr->p.x[i], q.y[k] = fr->p.y[i], q.z[k++] = fr->p.z[i];
    fs_particles_bounds(&q);
    fs_gbuffer a = {0}, b = {0};
    const char *raster[] = {"splat=raster", NULL}, *compute[] = {"splat=compute", NULL};
    if (!render(fr, &fr->p, "spheres", raster, &a, NULL) && !render(fr, &q, "spheres", compute, &b, NULL)) {
        diff d = compare(&a, &b, fr->f.r);
        print_diff("spheres, one sprite left out (must differ)", d);
        CHECK(!equal_output(d), "%s: a missing sprite passes the comparison", fr->name);
    }
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    fs_particles_free(&q);
}

/* The demo's frame and camera (experiments/scenes/dam_break.json) at SIZE^2. */
static int load_demo(frame *fr)
{
    static fs_scene s;
    fr->name = "demo dam break";
    int rc = fs_scene_load(&s, FS_TEST_DATA "/../scenes/dam_break.json");
    if (!rc) rc = fs_scene_load_frame(&s, 0, &fr->p);
    if (rc) return rc;
    s.camera.width = s.camera.height = SIZE;
    fs_scene_frame_particles(&s, &fr->p);
    fr->f = fs_scene_field(&s);
    fr->cam = s.camera;
    return FS_OK;
}

/* The DualSPHysics front (z up, r = 0.00365 m as its README gives), framed. */
static int load_dualsphysics(frame *fr)
{
    static fs_scene s;
    fr->name = "DualSPHysics front";
    int rc = fs_particles_read(&fr->p, FS_TEST_DATA "/dualsphysics/dambreak200k_t0.300_front.ply", NULL);
    if (rc) return rc;
    fs_particles_bounds(&fr->p);
    fs_scene_defaults(&s);
    s.radius = 0.00365f;
    s.up_axis = 2;
    s.camera.width = s.camera.height = SIZE;
    fs_scene_frame_particles(&s, &fr->p);
    fr->f = fs_scene_field(&s);
    fr->cam = s.camera;
    return FS_OK;
}

int main(void)
{
    fs_methods_register_builtin();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    frame frames[2] = {{0}};
    int (*load[2])(frame *) = {load_demo, load_dualsphysics};
    for (int k = 0; k < 2; k++) {
        frame *fr = &frames[k];
        if (load[k](fr) != FS_OK) {
            CHECK(0, "frame %d: %s", k, fs_error_message());
            continue;
        }
        test_equal(fr, "spheres", NULL, NULL);
        test_equal(fr, "raycast_pca", NULL, NULL);
        test_equal(fr, "aniso_ssf", NULL, NULL);
        test_equal(fr, "aniso_ssf", "anisotropy=off", NULL);
        fs_particles_free(&fr->p);
    }
    /* sprites of more than one pixel split over workgroups */
    if (load_demo(&frames[0]) == FS_OK) {
        test_equal(&frames[0], "spheres", NULL, "splat_large_px=1");
        test_equal(&frames[0], "raycast_pca", NULL, "splat_large_px=1"); /* 2.5 r thickness spheres */
        test_equal(&frames[0], "aniso_ssf", NULL, "splat_large_px=1");
        test_dropped_sprite(&frames[0]);
        fs_particles_free(&frames[0].p);
    }
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
