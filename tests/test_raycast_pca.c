/* raycast_pca on the OSMesa context: against the CPU reference on a small real
 * dam break (coverage IoU, depth), the normal switches and the bilateral
 * filter on a jittered slab against its analytic surface, colour tracking on
 * two coloured blocks, the stages it reports, and its splatted thickness against
 * the exact chord through a jittered slab. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "method.h"
#include "builtin_methods.h"
#include "test_render.h"
#include "metrics.h"
#include "particle_io.h"
#include "scene.h"
#include "analytic.h"
#include "percentile.h"
#include <stdlib.h>
#include <string.h>

/* (a) The 6,859-particle SPlisHSPlasH dam break: the bar (IoU >= 0.97,
 * depth p95 <= 0.1 r against the reference with the same field). */
static void against_reference(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    int rc = fs_test_load_dam(&p, &s, &f);
    CHECK(rc == FS_OK, "read: %s", fs_error_message());
    if (rc) return;
    fs_gbuffer a, b;
    fs_gbuffer_alloc(&a, 128, 128);
    fs_gbuffer_alloc(&b, 128, 128);
    fs_stages st = {0};
    CHECK(fs_test_render("raycast_pca", NULL, &p, f, &s.camera, &a, &st) == FS_OK, "raycast_pca: %s",
          fs_error_message());
    CHECK(fs_test_render("reference", NULL, &p, f, &s.camera, &b, NULL) == FS_OK, "reference: %s", fs_error_message());
    fs_metrics mt;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, f.r, &mt) == FS_OK, "metrics: %s", fs_error_message());
    printf("(a) dam break 6859 at 128^2 vs reference: IoU %.4f, depth bias %.4f r, p95 %.4f r, normal mean %.2f deg "
           "(interior %.2f), %zu px\n",
           mt.mask_iou, mt.depth_bias_r, mt.depth_p95_r, mt.normal_mean_deg, mt.interior_normal_mean_deg, mt.n_both);
    CHECK(mt.n_both > 1500, "only %zu pixels covered by both", mt.n_both);
    CHECK(mt.mask_iou >= 0.97, "IoU %g", mt.mask_iou);
    CHECK(fabs(mt.depth_bias_r) + mt.depth_p95_r <= 0.1, "depth bias %g r, p95 %g r", mt.depth_bias_r, mt.depth_p95_r);
    const char *want[] = {"splat", "march", "normals", "filter", "thickness", "readback", NULL};
    const char *missing = fs_test_missing_stage(&st, want);
    CHECK(!missing, "stage %s not reported", missing);
    double thick = 0;
    for (int i = 0; i < 128 * 128; i++) thick += a.thickness[i];
    CHECK(thick > 0, "no thickness");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    fs_particles_free(&p);
}

/* Mean angle (deg) between the normals of a and b over pixels both cover. */
static double mean_angle(const fs_gbuffer *a, const fs_gbuffer *b, const unsigned char *mask)
{
    double sum = 0;
    int n = 0;
    for (int i = 0; i < a->w * a->h; i++) {
        if (!a->coverage[i] || !b->coverage[i] || (mask && !mask[i])) continue;
        const float *u = &a->normal[3 * i], *v = &b->normal[3 * i];
        sum += acos(fmin(1.0, u[0] * v[0] + u[1] * v[1] + u[2] * v[2])) * 180 / FS_PI;
        n++;
    }
    return n ? sum / n : NAN;
}

/* Mean angle between horizontally adjacent covered normals: how rough the map is. */
static double roughness(const fs_gbuffer *a)
{
    double sum = 0;
    int n = 0;
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x + 1 < a->w; x++) {
            size_t i = (size_t)y * a->w + x;
            if (!a->coverage[i] || !a->coverage[i + 1] || fabsf(a->depth[i] - a->depth[i + 1]) > 0.05f) continue;
            const float *u = &a->normal[3 * i], *v = &a->normal[3 * i + 3];
            sum += acos(fmin(1.0, u[0] * v[0] + u[1] * v[1] + u[2] * v[2])) * 180 / FS_PI;
            n++;
        }
    return n ? sum / n : NAN;
}

/* (b) Jittered slab against its analytic surface: basic, pca and blend give
 * different normals, PCA-based ones are closer on the flat top; the filter
 * smooths the map. */
static void normal_switches(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.synth.shape = FS_SYNTH_SLAB;
    s.synth.jitter = 0.1f;
    s.synth.seed = 5;
    fs_particles p;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_OK, "slab: %s", fs_error_message());
    float r = s.radius;
    fs_camera cam = {{0, 50 * r, 45 * r}, {0, 12 * r, 0}, {0, 1, 0}, 40.0f, 128, 128, 0.1f, 10.0f};
    fs_field f = fs_scene_field(&s);
    fs_gbuffer ana, g[4];
    fs_gbuffer_alloc(&ana, 128, 128);
    fs_synthetic_analytic(&s, 0, &cam, &ana);
    const char *basic[] = {"normals=basic", "normal_filter=off", NULL},
               *pca[] = {"normals=pca", "normal_filter=off", NULL};
    const char *blend[] = {"normals=blend", "normal_filter=off", NULL}, *filt[] = {"normals=blend", NULL};
    const char *const *sets[4] = {basic, pca, blend, filt};
    for (int k = 0; k < 4; k++) {
        fs_gbuffer_alloc(&g[k], 128, 128);
        CHECK(fs_test_render("raycast_pca", sets[k], &p, f, &cam, &g[k], NULL) == FS_OK, "render %d: %s", k,
              fs_error_message());
    }
    unsigned char *in = malloc(128 * 128);
    fs_interior_mask(&g[0], &ana, 3, in);
    double e[4], rough[4];
    for (int k = 0; k < 4; k++) {
        e[k] = mean_angle(&g[k], &ana, in);
        rough[k] = roughness(&g[k]);
    }
    double d_bp = mean_angle(&g[0], &g[1], NULL), d_bb = mean_angle(&g[0], &g[2], NULL);
    printf("(b) slab interior normal error vs analytic: basic %.3f, pca %.3f, blend %.3f, blend+filter %.3f deg; "
           "roughness %.3f %.3f %.3f %.3f deg; basic-pca %.3f, basic-blend %.3f deg\n",
           e[0], e[1], e[2], e[3], rough[0], rough[1], rough[2], rough[3], d_bp, d_bb);
    CHECK(d_bp > 0.1 && d_bb > 0.1, "the normals switch changes nothing (%g, %g deg)", d_bp, d_bb);
    CHECK(e[1] < e[0] && e[2] < e[0], "PCA (%g) and blend (%g) not closer than basic (%g)", e[1], e[2], e[0]);
    CHECK(e[3] < 2.0, "filtered blend off by %g deg on the flat top", e[3]);
    CHECK(rough[3] < rough[2], "the filter does not smooth the normal map (%g vs %g)", rough[3], rough[2]);
    CHECK(mean_angle(&g[2], &g[3], NULL) > 0.05, "the filter changes nothing");
    free(in);
    for (int k = 0; k < 4; k++) fs_gbuffer_free(&g[k]);
    fs_gbuffer_free(&ana);
    fs_particles_free(&p);
}

/* (c) Two blocks meeting at x = 0, red (x < 0) and blue: the G-buffer colour
 * on each side matches its block; the seam is a blend. */
static void colour_tracking(void)
{
    const float r = 0.025f;
    enum { NX = 24, NY = 8, NZ = 8 };
    fs_particles p;
    fs_particles_alloc(&p, NX * NY * NZ, FS_HAS_COLOR);
    size_t k = 0;
    for (int z = 0; z < NZ; z++)
        for (int y = 0; y < NY; y++)
            for (int x = 0; x < NX; x++, k++) {
                p.x[k] = (x - (NX - 1) / 2.0f) * 2 * r;
                p.y[k] = (y + 0.5f) * 2 * r;
                p.z[k] = (z - (NZ - 1) / 2.0f) * 2 * r;
                float *c = p.color + 3 * k;
                c[0] = p.x[k] < 0;
                c[1] = 0;
                c[2] = p.x[k] > 0;
            }
    fs_particles_bounds(&p);
    fs_field f = {r, 0.8f * 8 * r * r * r, FS_KERNEL_CUBIC, 4 * r, 0.6f};
    fs_camera cam = {{0, 8 * r, 60 * r}, {0, 8 * r, 0}, {0, 1, 0}, 40.0f, 128, 64, 0.1f, 10.0f};
    fs_gbuffer g;
    fs_gbuffer_alloc(&g, 128, 64);
    CHECK(fs_test_render("raycast_pca", NULL, &p, f, &cam, &g, NULL) == FS_OK, "render: %s", fs_error_message());
    float rt[3], up[3], fwd[3];
    fs_camera_basis(&cam, rt, up, fwd);
    int red = 0, blue = 0, wrong = 0, mixed = 0;
    for (int y = 0; y < g.h; y++)
        for (int x = 0; x < g.w; x++) {
            size_t i = (size_t)y * g.w + x;
            if (!g.coverage[i]) continue;
            float d[3];
            fs_camera_ray(&cam, x + 0.5f, y + 0.5f, d);
            float wx = cam.eye[0] + g.depth[i] / (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]) * d[0];
            const float *c = fs_gbuffer_aov(&g, FS_AOV_COLOR) + 4 * i;
            if (wx < -5 * r) {
                red++;
                wrong += !(c[0] > 0.999f && c[2] < 0.001f && c[3] == 1);
            } else if (wx > 5 * r) {
                blue++;
                wrong += !(c[2] > 0.999f && c[0] < 0.001f && c[3] == 1);
            } else if (fabsf(wx) < 0.3f * r) mixed += c[0] > 0.2f && c[2] > 0.2f;
        }
    printf("(c) colour: %d red-side px, %d blue-side px, %d wrong, %d mixed at the seam\n", red, blue, wrong, mixed);
    CHECK(red > 300 && blue > 300, "sides covered: %d %d", red, blue);
    CHECK(wrong == 0, "%d pixels with the other block's colour", wrong);
    CHECK(mixed > 0, "no blend at the seam");
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

/* (d) Thickness through a jittered slab against the exact chord through the
 * ideal slab (analytic), over the interior mask: the splatted estimate (3.4,
 * spheres weighted by V / their volume) keeps the mean within 10% and the p95 of
 * the per-pixel error within 15% of the mean chord. The bare chord sum of
 * spheres of r on the 2r lattice (thick_weight=chord) is about pi/6 of it. */
static void thickness_vs_chord(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.synth.shape = FS_SYNTH_SLAB;
    s.synth.jitter = 0.1f;
    s.synth.seed = 7;
    fs_particles p;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_OK, "slab: %s", fs_error_message());
    float r = s.radius;
    fs_camera cam = {{0, 50 * r, 45 * r}, {0, 12 * r, 0}, {0, 1, 0}, 40.0f, 96, 96, 0.1f, 10.0f};
    fs_field f = fs_scene_field(&s);
    fs_gbuffer ana, g, bare;
    fs_gbuffer_alloc(&ana, 96, 96);
    fs_gbuffer_alloc(&g, 96, 96);
    fs_gbuffer_alloc(&bare, 96, 96);
    fs_synthetic_analytic(&s, 0, &cam, &ana);
    const char *chord[] = {"thick_weight=chord", "thick_radius=1", NULL};
    CHECK(fs_test_render("raycast_pca", NULL, &p, f, &cam, &g, NULL) == FS_OK, "render: %s", fs_error_message());
    CHECK(fs_test_render("raycast_pca", chord, &p, f, &cam, &bare, NULL) == FS_OK, "render: %s", fs_error_message());
    unsigned char *in = malloc(96 * 96);
    double *err = malloc(96 * 96 * sizeof *err);
    fs_interior_mask(&g, &ana, 3, in);
    double se = 0, sm = 0, sb = 0;
    size_t n = 0;
    for (int i = 0; i < 96 * 96; i++) {
        if (!in[i] || !(ana.thickness[i] > 0)) continue;
        se += ana.thickness[i], sm += g.thickness[i], sb += bare.thickness[i];
        err[n++] = fabs(g.thickness[i] - ana.thickness[i]);
    }
    CHECK(n > 1000, "only %zu interior pixels", n);
    if (n) {
        double mean = se / n, ratio = sm / se, p95 = fs_percentile(err, n, 95);
        printf("(d) slab thickness vs the exact chord over %zu px: mean %.2f r, ratio %.4f (bare chord %.4f), "
               "p95 |error| %.2f r\n",
               n, mean / r, ratio, sb / se, p95 / r);
        CHECK(fabs(ratio - 1) <= 0.1, "mean thickness %g of the exact chord's", ratio);
        CHECK(p95 <= 0.15 * mean, "p95 error %g r, mean chord %g r", p95 / r, mean / r);
        CHECK(sb / se < 0.7, "the bare chord sum is %g of the exact chord: the weight changes nothing?", sb / se);
    }
    free(in), free(err);
    fs_gbuffer_free(&ana), fs_gbuffer_free(&g), fs_gbuffer_free(&bare);
    fs_particles_free(&p);
}

int main(void)
{
    fs_methods_register_builtin();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    against_reference();
    normal_switches();
    colour_tracking();
    thickness_vs_chord();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
