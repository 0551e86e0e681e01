/* Synthetic scenes (synthetic.h): particle counts, jitter bounds, placement,
 * determinism, motion, and the analytic G-buffer against hand-computed values. */
#include "fs_error.h"
#include "fs_test.h"
#include "analytic.h"
#include <string.h>

static fs_scene scene(fs_synth_shape shape, float jitter, unsigned seed)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.synth.shape = shape;
    s.synth.jitter = jitter;
    s.synth.seed = seed;
    return s;
}

static int same(const fs_particles *a, const fs_particles *b)
{
    return a->n == b->n && !memcmp(a->x, b->x, a->n * 4) && !memcmp(a->y, b->y, a->n * 4) &&
        !memcmp(a->z, b->z, a->n * 4);
}

static void counts_and_jitter(void)
{
    const fs_synth_shape shapes[] = {FS_SYNTH_SLAB, FS_SYNTH_BOX, FS_SYNTH_SPHERE};
    const char *names[] = {"slab", "box", "sphere"};
    for (int si = 0; si < 3; si++) {
        fs_scene s = scene(shapes[si], 0, 7), sj = scene(shapes[si], 0.1f, 7);
        fs_particles p0, p1;
        CHECK(fs_synthetic_generate(&s, 0, &p0) == FS_OK, "%s: %s", names[si], fs_error_message());
        CHECK(fs_synthetic_generate(&sj, 0, &p1) == FS_OK, "%s: %s", names[si], fs_error_message());
        float r = s.radius;
        if (si == 0) CHECK(p0.n == 48 * 6 * 48, "slab count %zu", p0.n);
        if (si == 1) CHECK(p0.n == 16 * 16 * 16, "box count %zu", p0.n);
        if (si == 2) { /* diameter 20: about the ball's volume over (2r)^3 */
            double expect = 4.0 / 3.0 * FS_PI * 1000.0;
            CHECK(fabs(p0.n - expect) < 0.03 * expect, "sphere count %zu vs %g", p0.n, expect);
        }
        CHECK(p1.n == p0.n, "%s: jitter keeps the count", names[si]);
        double maxoff = 0, mean[3] = {0, 0, 0};
        float lo = INFINITY;
        for (size_t i = 0; i < p0.n; i++) {
            float off[3] = {p1.x[i] - p0.x[i], p1.y[i] - p0.y[i], p1.z[i] - p0.z[i]};
            for (int a = 0; a < 3; a++) {
                if (fabs(off[a]) > maxoff) maxoff = fabs(off[a]);
                mean[a] += off[a];
            }
            lo = fminf(lo, p0.y[i]);
        }
        printf("%s: %zu particles, max jitter %.4f r, mean jitter (%.4f %.4f %.4f) r\n", names[si], p0.n, maxoff / r,
               mean[0] / p0.n / r, mean[1] / p0.n / r, mean[2] / p0.n / r);
        CHECK(maxoff <= 0.1 * r * 1.0001 && maxoff > 0.09 * r, "%s: jitter %g r outside (0.09, 0.1]", names[si],
              maxoff / r);
        for (int a = 0; a < 3; a++) CHECK(fabs(mean[a] / p0.n) < 0.01 * r, "%s: jitter mean", names[si]);
        /* Ideal bottom at 0 (lowest centre at r), centred horizontally. */
        if (si < 2) CHECK_NEAR(lo, r, 1e-6, "lowest centre at r");
        CHECK_NEAR(0.5 * (p0.bmin[0] + p0.bmax[0]), 0, 1e-6, "centred in x");
        CHECK_NEAR(0.5 * (p0.bmin[2] + p0.bmax[2]), 0, 1e-6, "centred in z");
        fs_particles_free(&p0);
        fs_particles_free(&p1);
    }
}

static void determinism(void)
{
    fs_scene s = scene(FS_SYNTH_BOX, 0.1f, 3);
    fs_particles a, b, c, d;
    fs_synthetic_generate(&s, 2, &a);
    fs_synthetic_generate(&s, 2, &b);
    fs_synthetic_generate(&s, 3, &c);
    s.synth.seed = 4;
    fs_synthetic_generate(&s, 2, &d);
    CHECK(same(&a, &b), "same seed and frame give the same particles");
    CHECK(!same(&a, &c), "another frame re-jitters");
    CHECK(!same(&a, &d), "another seed re-jitters");
    fs_particles_free(&a);
    fs_particles_free(&b);
    fs_particles_free(&c);
    fs_particles_free(&d);
    /* moving: frame 3 is frame 0 shifted by 3 * 2r along x. */
    s = scene(FS_SYNTH_SLAB, 0, 1);
    s.synth.moving = 1;
    fs_synthetic_generate(&s, 0, &a);
    fs_synthetic_generate(&s, 3, &b);
    double worst = 0;
    for (size_t i = 0; i < a.n; i++)
        worst = fmax(worst, fabs(b.x[i] - a.x[i] - 6 * s.radius) + fabs(b.y[i] - a.y[i]) + fabs(b.z[i] - a.z[i]));
    CHECK(worst < 1e-5, "moving slab shifts by 2r per frame (off by %g)", worst);
    fs_particles_free(&a);
    fs_particles_free(&b);
    /* Custom sizes and the z-up convention. */
    s = scene(FS_SYNTH_SLAB, 0, 1);
    s.synth.size[0] = 5;
    s.synth.size[1] = 3;
    s.synth.size[2] = 4;
    s.up_axis = 2;
    fs_synthetic_generate(&s, 0, &a);
    CHECK(a.n == 60, "5x3x4 slab has %zu", a.n);
    CHECK_NEAR(a.bmin[2], s.radius, 1e-6, "z-up rests on z = 0");
    fs_particles_free(&a);
}

static fs_camera down_camera(float height)
{
    fs_camera c = {{0, height, 0}, {0, 0, 0}, {0, 0, -1}, 30.0f, 129, 129, 0.1f, 10.0f};
    return c;
}

static void analytic(void)
{
    fs_scene s = scene(FS_SYNTH_SLAB, 0.1f, 1);
    float r = s.radius, top = 12 * r, eye = 100 * r;
    fs_camera cam = down_camera(eye);
    fs_gbuffer gb;
    fs_gbuffer_alloc(&gb, cam.width, cam.height);
    CHECK(fs_synthetic_analytic(&s, 0, &cam, &gb) == FS_OK, "analytic: %s", fs_error_message());
    size_t mid = 64 * 129 + 64; /* the centre pixel's ray is vertical */
    CHECK(gb.coverage[mid] == 1, "centre covered");
    CHECK_NEAR(gb.depth[mid], eye - top, 1e-4 * r, "depth over the slab");
    CHECK_NEAR(gb.thickness[mid], top, 1e-4 * r, "vertical thickness = slab height");
    CHECK_NEAR(gb.normal[3 * mid + 2], 1, 1e-6, "normal faces the camera");
    /* Eye-space depth of a plane facing the camera is the same at every pixel,
     * while the ray length grows towards the corners. */
    size_t covered = 0, off = 0;
    for (size_t i = 0; i < (size_t)129 * 129; i++) {
        if (!gb.coverage[i]) {
            CHECK(isinf(gb.depth[i]), "empty pixel depth");
            continue;
        }
        covered++;
        if (fabsf(gb.depth[i] - (eye - top)) > 1e-4f * r) off++;
    }
    printf("slab from above: %zu pixels covered, %zu off the plane depth\n", covered, off);
    CHECK(covered > 0 && off == 0, "planar depth");
    /* The slab spans 96r of 2*88r*tan(15 deg) = 47r visible: fully covered. */
    CHECK(covered == (size_t)129 * 129, "slab fills the view");

    /* Sphere from above: depth to the top, thickness = diameter. */
    s = scene(FS_SYNTH_SPHERE, 0.1f, 1);
    fs_particles p;
    fs_synthetic_generate(&s, 0, &p);
    double R = 2 * r * cbrt(3.0 * p.n / (4 * FS_PI));
    fs_particles_free(&p);
    CHECK(fs_synthetic_analytic(&s, 0, &cam, &gb) == FS_OK, "sphere analytic");
    CHECK_NEAR(gb.depth[mid], eye - 2 * R, 1e-4 * r, "sphere depth");
    CHECK_NEAR(gb.thickness[mid], 2 * R, 1e-4 * r, "sphere thickness = diameter");
    CHECK(R > 19.5 * r && R < 20.5 * r, "ideal radius %g r (diameter 20 particles of 2r)", R / r);

    /* Camera inside the solid: no crossing from outside, no coverage. */
    s = scene(FS_SYNTH_BOX, 0.1f, 1);
    fs_camera in = down_camera(4 * r);
    in.width = in.height = 16;
    fs_gbuffer small;
    fs_gbuffer_alloc(&small, 16, 16);
    CHECK(fs_synthetic_analytic(&s, 0, &in, &small) == FS_OK, "inside camera");
    float cov = 0;
    for (int i = 0; i < 256; i++) cov += small.coverage[i];
    CHECK(cov == 0, "camera inside sees no crossing from outside (%g)", cov);
    /* Wrong size and bad scenes are refused. */
    CHECK(fs_synthetic_analytic(&s, 0, &cam, &small) != FS_OK, "size mismatch refused");
    s.synth.shape = FS_SYNTH_NONE;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_ERR_INPUT, "no shape refused");
    s = scene(FS_SYNTH_BOX, -1, 1);
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_ERR_INPUT, "negative jitter refused");
    s = scene(FS_SYNTH_BOX, 0.1f, 1);
    s.synth.size[1] = -3;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_ERR_INPUT, "negative size refused");
    fs_gbuffer_free(&small);
    fs_gbuffer_free(&gb);
}

int main(void)
{
    counts_and_jitter();
    determinism();
    analytic();
    TEST_DONE();
}
