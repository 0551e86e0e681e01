/* The accelerated reference (accel=on: sub-cell bounds, gathered arrays,
 * vectorised sums, tiles) against the plain march it replaces (accel=off), on
 * the bundled dam break (also with H = 6r, and at 16x16, where no sub-cell
 * bounds are built), a synthetic box, the bundled 24k
 * frame, the 97k splash frame of the benchmark and the dam break with three
 * strays thousands of metres away, thickness on, 128x128:
 * coverage IoU >= 0.9999, depth within 2e-4 r, thickness within 2e-4 r per
 * crossing and normals within 0.01 degrees wherever both cover. Pixels whose
 * coverage differs may only be ones where a crossing shorter than step_min is
 * found on one path and missed on the other; each is printed with its thickness. */
#include "fs_error.h"
#include "fs_test.h"
#include "particle_io.h"
#include "scene.h"
#include "synthetic.h"
#include "test_render.h"
#include <stdlib.h>
#include <string.h>

/* Most inside intervals a ray of these scenes crosses, for the thickness tolerance. */
#define MAX_CROSSINGS 16

static void compare_one(const char *what, const char *const *on, const fs_particles *p, fs_field f,
                        const fs_camera *cam)
{
    const char *off[] = {"accel=off", NULL};
    fs_gbuffer a = {0}, b = {0};
    int rc = fs_test_render("reference", off, p, f, cam, &a, NULL);
    if (!rc) rc = fs_test_render("reference", on, p, f, cam, &b, NULL);
    CHECK(!rc, "%s: renders (%s)", what, fs_error_message());
    if (rc) {
        fs_gbuffer_free(&a);
        fs_gbuffer_free(&b);
        return;
    }
    size_t n = (size_t)a.w * a.h, both = 0, either = 0;
    double dd = 0, dt = 0, dn = 0;
    for (size_t i = 0; i < n; i++) {
        int ca = a.coverage[i] > 0, cb = b.coverage[i] > 0;
        either += ca || cb;
        if (ca != cb) {
            printf("%s: pixel (%zu, %zu) covered by %s only, thickness %.3g r / %.3g r (step_min 0.02 r)\n", what,
                   i % a.w, i / a.w, ca ? "accel=off" : "accel=on", a.thickness[i] / f.r, b.thickness[i] / f.r);
            continue;
        }
        if (!ca) continue;
        both++;
        double d = fabs(a.depth[i] - b.depth[i]) / f.r, t = fabs(a.thickness[i] - b.thickness[i]) / f.r;
        const float *na = a.normal + 3 * i, *nb = b.normal + 3 * i;
        double cx = (double)na[1] * nb[2] - (double)na[2] * nb[1], cy = (double)na[2] * nb[0] - (double)na[0] * nb[2],
               cz = (double)na[0] * nb[1] - (double)na[1] * nb[0];
        double dot = (double)na[0] * nb[0] + (double)na[1] * nb[1] + (double)na[2] * nb[2];
        double ang = atan2(sqrt(cx * cx + cy * cy + cz * cz), dot) * 180.0 / FS_PI; /* exact for small angles */
        dd = d > dd ? d : dd;
        dt = t > dt ? t : dt;
        dn = ang > dn ? ang : dn;
    }
    double iou = either ? (double)both / (double)either : 1;
    printf("%s: %zu pixels covered, IoU %.6f, max |depth| %.2g r, max |thickness| %.2g r, max normal %.2g deg\n", what,
           both, iou, dd, dt, dn);
    CHECK(both > n / 20, "%s: the fluid covers the image (%zu pixels)", what, both);
    CHECK(iou >= 0.9999, "%s: IoU %.6f", what, iou);
    CHECK(dd <= 2e-4, "%s: depth differs by %.3g r", what, dd);
    CHECK(dt <= 2e-4 * MAX_CROSSINGS, "%s: thickness differs by %.3g r", what, dt);
    CHECK(dn <= 0.01, "%s: normal differs by %.3g degrees", what, dn);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

/* accel=on with and without the fine interior bounds, each against accel=off. */
static void compare_paths(const char *what, const fs_particles *p, fs_field f, const fs_camera *cam)
{
    const char *with[] = {"accel=on", "interior=on", NULL}, *without[] = {"accel=on", "interior=off", NULL};
    char name[128];
    snprintf(name, sizeof name, "%s, interior on", what);
    compare_one(name, with, p, f, cam);
    snprintf(name, sizeof name, "%s, interior off", what);
    compare_one(name, without, p, f, cam);
}

/* The bundled frame at path, framed at 128x128 by the scene defaults. */
static int load_frame(const char *path, float r, float volume_scale, fs_particles *p, fs_field *f, fs_camera *cam)
{
    int rc = fs_particles_read(p, path, NULL);
    if (rc) return rc;
    fs_particles_bounds(p);
    static fs_scene s;
    fs_scene_defaults(&s);
    s.radius = r;
    s.volume_scale = volume_scale;
    s.camera.width = s.camera.height = 128;
    fs_scene_frame_particles(&s, p);
    *f = fs_scene_field(&s);
    *cam = s.camera;
    return FS_OK;
}

/* p plus three particles 2000 to 5000 m away. */
static int add_strays(const fs_particles *p, fs_particles *out)
{
    int rc = fs_particles_alloc(out, p->n + 3, 0);
    if (rc) return rc;
    memcpy(out->x, p->x, p->n * sizeof *p->x);
    memcpy(out->y, p->y, p->n * sizeof *p->y);
    memcpy(out->z, p->z, p->n * sizeof *p->z);
    const float far[3][3] = {{2000, 0, 0}, {0, 3000, -1000}, {-5000, 10, 4000}};
    for (int k = 0; k < 3; k++) {
        out->x[p->n + k] = far[k][0];
        out->y[p->n + k] = far[k][1];
        out->z[p->n + k] = far[k][2];
    }
    fs_particles_bounds(out);
    return FS_OK;
}

int main(void)
{
    fs_particles p = {0}, q = {0};
    fs_scene s;
    fs_field f;
    int rc = fs_test_load_dam(&p, &s, &f);
    CHECK(!rc, "dam break loads (%s)", fs_error_message());
    if (!rc) {
        compare_paths("dam break", &p, f, &s.camera);
        fs_field wide = f; /* cells of 6r: 4 coarse sub-cells an edge */
        wide.H = 6.0f * f.r;
        compare_paths("dam break, H = 6r", &p, wide, &s.camera);
        fs_camera small = s.camera; /* too few rays for the sub-cell bounds to pay: none are built */
        small.width = small.height = 16;
        compare_paths("dam break, 16x16", &p, f, &small);
        rc = add_strays(&p, &q);
        CHECK(!rc, "strays added");
        if (!rc) compare_paths("dam break with strays", &q, f, &s.camera);
    }
    fs_particles_free(&p);
    fs_particles_free(&q);

    fs_camera cam;
#if FS_WITH_VTK /* the lean build reads no VTK; the PLY frame below still runs */
    rc = load_frame(FS_TEST_DATA "/splashsurf/dam_break_frame_23_24389_particles.vtk", 0.025f, 0.8f, &p, &f, &cam);
    CHECK(!rc, "24k frame loads (%s)", fs_error_message());
    if (!rc) compare_paths("24k frame", &p, f, &cam);
    fs_particles_free(&p);
#endif

    rc = load_frame(FS_TEST_DATA "/splash/dam_break_splash_100k.ply", 0.025f, 1.0f, &p, &f, &cam);
    CHECK(!rc, "splash frame loads (%s)", fs_error_message());
    if (!rc) compare_paths("97k splash frame", &p, f, &cam);
    fs_particles_free(&p);

    static fs_scene box;
    fs_scene_defaults(&box);
    box.synth.shape = FS_SYNTH_BOX;
    box.camera.width = box.camera.height = 128;
    rc = fs_synthetic_generate(&box, 0, &p);
    CHECK(!rc, "box generates (%s)", fs_error_message());
    if (!rc) {
        fs_scene_frame_particles(&box, &p);
        compare_paths("box", &p, fs_scene_field(&box), &box.camera);
    }
    fs_particles_free(&p);
    TEST_DONE();
}
