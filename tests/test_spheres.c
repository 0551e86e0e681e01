/* spheres on the real OSMesa context: one sphere against the exact CPU
 * ray-sphere answer (coverage, depth, normal, thickness), then a golden image. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "golden.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "scene.h"
#include <stdlib.h>
#include <string.h>

static fs_camera camera(int w, int h, float ez)
{
    fs_camera c = {{0.3f, 0.2f, ez}, {0, 0, 0}, {0, 1, 0}, 40.0f, w, h, 0.1f, 20.0f};
    return c;
}

static void test_single_sphere(const fs_method *m)
{
    const float r = 0.25f;
    fs_particles p;
    fs_particles_alloc(&p, 1, 0);
    p.x[0] = 0.1f;
    p.y[0] = -0.05f;
    p.z[0] = 0.0f;
    fs_particles_bounds(&p);
    static fs_scene s; /* the default field (cubic spline, H = 4r, iso 0.6) at r */
    fs_scene_defaults(&s);
    s.radius = r;
    fs_run *run = NULL;
    CHECK(fs_run_open(&run, m, &s, NULL, NULL) == FS_OK, "open: %s", fs_error_message());
    if (!run) return;
    CHECK(fs_run_upload(run, &p, NULL, NULL) == FS_OK, "upload: %s", fs_error_message());
    fs_camera cam = camera(128, 96, 3.0f);
    fs_run_image im = {0};
    fs_stages st = {0};
    CHECK(fs_run_render(run, &cam, &im, &st) == FS_OK, "render: %s", fs_error_message());
    const fs_gbuffer g = im.g;
    if (!g.depth) {
        fs_run_close(run);
        fs_particles_free(&p);
        return;
    }
    int mismatched = 0, covered = 0;
    double worst_depth = 0, worst_normal = 0, worst_thick = 0;
    float rr[3], uu[3], ff[3];
    fs_camera_basis(&cam, rr, uu, ff);
    for (int y = 0; y < cam.height; y++)
        for (int x = 0; x < cam.width; x++) {
            size_t i = (size_t)y * cam.width + x;
            float d[3], oc[3] = {cam.eye[0] - p.x[0], cam.eye[1] - p.y[0], cam.eye[2] - p.z[0]};
            fs_camera_ray(&cam, x + 0.5f, y + 0.5f, d);
            float b = d[0] * oc[0] + d[1] * oc[1] + d[2] * oc[2];
            float c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r, disc = b * b - c;
            int hit = disc > 0;
            /* pixels whose ray grazes the silhouette may go either way */
            float margin = fabsf(disc) / (2 * r * fabsf(b) + 1e-9f);
            if (hit != (g.coverage[i] > 0.5f) && margin > 0.02f * r) mismatched++;
            if (!hit || g.coverage[i] < 0.5f || disc < 0.05f * r * r) continue;
            covered++;
            float t = -b - sqrtf(disc), hp[3], n[3], nv[3];
            for (int k = 0; k < 3; k++) hp[k] = cam.eye[k] + t * d[k];
            float depth = (hp[0] - cam.eye[0]) * ff[0] + (hp[1] - cam.eye[1]) * ff[1] + (hp[2] - cam.eye[2]) * ff[2];
            n[0] = (hp[0] - p.x[0]) / r;
            n[1] = (hp[1] - p.y[0]) / r;
            n[2] = (hp[2] - p.z[0]) / r;
            fs_camera_to_view_dir(&cam, n, nv);
            double dot = nv[0] * g.normal[3 * i] + nv[1] * g.normal[3 * i + 1] + nv[2] * g.normal[3 * i + 2];
            if (fabs(g.depth[i] - depth) > worst_depth) worst_depth = fabs(g.depth[i] - depth);
            if (1 - dot > worst_normal) worst_normal = 1 - dot;
            if (fabs(g.thickness[i] - 2 * sqrtf(disc)) > worst_thick)
                worst_thick = fabs(g.thickness[i] - 2 * sqrtf(disc));
        }
    printf("single sphere: %d covered, %d mismatched, depth err %.2g, 1-cos normal %.2g, thickness err %.2g\n", covered,
           mismatched, worst_depth, worst_normal, worst_thick);
    CHECK(covered > 300, "sphere covers only %d pixels", covered);
    CHECK(mismatched == 0, "%d pixels disagree with exact coverage", mismatched);
    CHECK(worst_depth < 1e-4, "depth error %g", worst_depth);
    CHECK(worst_normal < 1e-4, "normal error %g", worst_normal);
    CHECK(worst_thick < 1e-3, "thickness error %g", worst_thick);
    CHECK(st.n >= 2, "stages reported: %d", st.n);
    fs_run_image_free(&im);
    fs_run_close(run);
    fs_particles_free(&p);
}

/* Golden image: a 6x4x5 lattice block, shaded by the shared pass. */
static void test_golden(const fs_method *m)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.radius = 0.05f;
    fs_particles p;
    fs_particles_alloc(&p, 6 * 4 * 5, 0);
    size_t k = 0;
    for (int z = 0; z < 5; z++)
        for (int y = 0; y < 4; y++)
            for (int x = 0; x < 6; x++, k++) {
                p.x[k] = (x - 2.5f) * 0.1f;
                p.y[k] = y * 0.1f + 0.05f;
                p.z[k] = (z - 2.0f) * 0.1f;
            }
    fs_particles_bounds(&p);
    s.camera.width = s.camera.height = 128;
    fs_scene_finish_camera(&s, p.bmin, p.bmax);
    fs_run *run = NULL;
    fs_run_image im = {0};
    int rc = fs_run_open(&run, m, &s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &p, NULL, NULL);
    if (!rc) rc = fs_run_render(run, &s.camera, &im, NULL);
    if (!rc) rc = fs_run_shade(run, &s.camera, &im, FS_APPEARANCE_SHARED, NULL); /* floor: lowest centre - r */
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (!rc)
        CHECK(fs_golden_check("spheres_block", im.rgba, 128, 128, 1.0, 0.01) == 0,
              "golden image spheres_block differs");
    fs_run_image_free(&im);
    fs_run_close(run);
    fs_particles_free(&p);
}

int main(void)
{
    fs_methods_register_builtin();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    const fs_method *m = fs_method_find("spheres");
    CHECK(m != NULL, "spheres is not registered");
    if (m) {
        test_single_sphere(m);
        test_golden(m);
    }
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
