/* Far strays (docs/DESIGN.md, "Neighbour grid"): the bundled dam break plus
 * three particles 2000-5000 m away. Every registered method renders the frame
 * without error, and its image of the bulk (the clean frame's camera) matches
 * its image of the clean frame; the auto-framed camera of the stray frame is
 * the clean frame's. Renders at 128x128 on the real OSMesa context. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "method.h"
#include "builtin_methods.h"
#include "metrics.h"
#include "particles.h"
#include "scene.h"
#include "test_render.h"
#include <math.h>
#include <string.h>

static const float STRAYS[3][3] = {{2000, 0, 0}, {-1500, 3000, 800}, {0, -4000, -3000}};

/* p plus the three strays (at their positions in order after p's particles). */
static int with_strays(const fs_particles *p, fs_particles *q)
{
    if (fs_particles_alloc(q, p->n + 3, 0)) return 1;
    memcpy(q->x, p->x, p->n * sizeof *q->x);
    memcpy(q->y, p->y, p->n * sizeof *q->y);
    memcpy(q->z, p->z, p->n * sizeof *q->z);
    for (int s = 0; s < 3; s++) {
        q->x[p->n + s] = STRAYS[s][0];
        q->y[p->n + s] = STRAYS[s][1];
        q->z[p->n + s] = STRAYS[s][2];
    }
    fs_particles_bounds(q);
    return 0;
}

/* The auto-framed camera of q equals p's (scene s framed on p). */
static void check_framing(const fs_scene *s, const fs_particles *q)
{
    fs_scene t;
    fs_scene_defaults(&t);
    t.radius = s->radius;
    t.volume_scale = s->volume_scale;
    t.camera.width = t.camera.height = 128;
    fs_scene_frame_particles(&t, q);
    const fs_camera *a = &s->camera, *b = &t.camera;
    double d = 0, ext = 0;
    for (int i = 0; i < 3; i++) {
        d = fmax(d, fabs(a->eye[i] - b->eye[i]));
        d = fmax(d, fabs(a->target[i] - b->target[i]));
        ext = fmax(ext, fabs(a->eye[i] - a->target[i]));
    }
    printf("framing: eye/target differ by %.3g (camera distance %.3g); near %g vs %g, far %g vs %g\n", d, ext, a->znear,
           b->znear, a->zfar, b->zfar);
    CHECK(d <= 1e-4 * ext, "the strays moved the auto-framed camera by %g", d);
    CHECK(fabsf(a->znear - b->znear) <= 1e-4f * a->znear && fabsf(a->zfar - b->zfar) <= 1e-4f * a->zfar,
          "the strays moved the clip planes: near %g vs %g, far %g vs %g", a->znear, b->znear, a->zfar, b->zfar);
}

/* Method m on the clean frame p and the stray frame q, same camera. */
static void check_method(const char *m, const fs_particles *p, const fs_particles *q, fs_field f, const fs_camera *cam)
{
    fs_gbuffer a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    int rc = fs_test_render(m, NULL, p, f, cam, &a, NULL);
    CHECK(rc == FS_OK, "%s on the clean frame: %s", m, fs_error_message());
    int rs = rc ? rc : fs_test_render(m, NULL, q, f, cam, &b, NULL);
    CHECK(rs == FS_OK, "%s with far strays: %s", m, fs_error_message());
    if (!rc && !rs) {
        fs_metrics mt;
        CHECK(fs_metrics_compute(&b, NULL, &a, NULL, f.r, &mt) == FS_OK, "%s metrics: %s", m, fs_error_message());
        printf("%-15s strays vs clean: IoU %.6f (%zu px), depth bias %.2g r, p95 %.2g r, normal mean %.3g deg\n", m,
               mt.mask_iou, mt.n_union, mt.depth_bias_r, mt.depth_p95_r, mt.normal_mean_deg);
        CHECK(mt.n_union > 1000, "%s drew only %zu px of the bulk", m, mt.n_union);
        CHECK(mt.mask_iou >= 0.999, "%s: coverage IoU %g with strays", m, mt.mask_iou);
        CHECK(fabs(mt.depth_bias_r) <= 1e-3 && mt.depth_p95_r <= 1e-2, "%s: depth bias %g r, p95 %g r with strays", m,
              mt.depth_bias_r, mt.depth_p95_r);
        CHECK(mt.normal_mean_deg <= 0.05, "%s: normals moved %g deg with strays", m, mt.normal_mean_deg);
    }
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

int main(void)
{
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    fs_particles p, q;
    fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) {
        CHECK(0, "load: %s", fs_error_message());
        TEST_DONE();
    }
    if (with_strays(&p, &q)) {
        CHECK(0, "alloc");
        TEST_DONE();
    }
    check_framing(&s, &q);
    fs_methods_register_builtin();
    for (int i = 0; i < fs_method_count(); i++) check_method(fs_method_at(i)->name, &p, &q, f, &s.camera);
    fs_particles_free(&q);
    fs_particles_free(&p);
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
