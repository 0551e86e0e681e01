/* volume_raycast (inacio2010) on the OSMesa context: the single-pass layered
 * density grid against the exact CPU grid (also with several draws, when a
 * particle reaches more layers than one geometry-shader draw emits); the method
 * against the CPU reference on a real dam break; layered, slice and exact builds
 * giving the same image; the translucent transfer function; the .vdb export. */
#include "density_splat.h"
#include "fs_error.h"
#include "fs_test.h"
#include "gl.h"
#include "test_gl_context.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "metrics.h"
#include "particle_io.h"
#include "scene.h"
#include "test_render.h"
#include "timing.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int load_dam(fs_particles *p, fs_scene *s, fs_field *f)
{
    int rc = fs_test_load_dam(p, s, f);
    CHECK(rc == FS_OK, "read: %s", fs_error_message());
    return rc;
}

/* Layered grid (read back) vs the exact CPU grid of the same shape. */
static double layered_vs_exact(const fs_particles *p, const fs_field *f, int res, double *ms, size_t *points)
{
    fs_density_grid a, b;
    double err = INFINITY;
    fs_grid ng;
    CHECK(fs_grid_build(&ng, p, f->H) == FS_OK, "grid: %s", fs_error_message());
    CHECK(fs_density_grid_init(&a, p->bmin, p->bmax, f->H, res) == FS_OK, "init: %s", fs_error_message());
    CHECK(fs_density_grid_init(&b, p->bmin, p->bmax, f->H, res) == FS_OK, "init: %s", fs_error_message());
    fs_layered_splat *ls = fs_layered_splat_create();
    CHECK(ls != NULL, "create: %s", fs_error_message());
    unsigned tex = fs_density_texture_create(&a);
    CHECK(tex != 0, "texture: %s", fs_error_message());
    if (ls && tex && a.data && b.data) {
        glFinish();
        double t0 = fs_now_ms();
        int rc = fs_layered_splat_run(ls, &a, p, f, tex);
        glFinish();
        *ms = fs_now_ms() - t0;
        CHECK(rc == FS_OK, "layered splat: %s", fs_error_message());
        CHECK(fs_density_texture_read(tex, &a) == FS_OK, "read back: %s", fs_error_message());
        CHECK(fs_density_grid_exact(&b, p, &ng, f) == FS_OK, "exact: %s", fs_error_message());
        err = fs_density_grid_rel_l2(&a, &b);
        *points = fs_layered_splat_points(ls);
        printf("  %zu particles, %dx%dx%d grid, %zu points drawn (%.0f ms): rel L2 %.3g\n", p->n, a.dim[0], a.dim[1],
               a.dim[2], fs_layered_splat_points(ls), *ms, err);
    }
    if (tex) glDeleteTextures(1, &tex);
    fs_layered_splat_destroy(ls);
    fs_density_grid_free(&a);
    fs_density_grid_free(&b);
    fs_grid_free(&ng);
    return err;
}

static void layered_grid(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (load_dam(&p, &s, &f)) return;
    double ms;
    size_t pts = 0;
    printf("(a) layered vs exact grid\n");
    double e = layered_vs_exact(&p, &f, 128, &ms, &pts);
    CHECK(e < 1e-5, "dam break, cubic: rel L2 %g", e);
    f.kernel = FS_KERNEL_POLY6; /* the paper's kernel */
    e = layered_vs_exact(&p, &f, 96, &ms, &pts);
    CHECK(e < 1e-5, "dam break, poly6: rel L2 %g", e);
    fs_particles_free(&p);
    /* three particles on a fine grid: each reaches ~260 layers, more than one
     * draw covers, so the draw repeats with a layer offset */
    fs_particles q;
    CHECK(fs_particles_alloc(&q, 3, 0) == FS_OK, "alloc");
    for (int i = 0; i < 3; i++) {
        q.x[i] = 0.001f * i;
        q.y[i] = 0.002f * (i == 1);
        q.z[i] = -0.001f * i;
    }
    fs_particles_bounds(&q);
    f.kernel = FS_KERNEL_CUBIC;
    e = layered_vs_exact(&q, &f, 262, &ms, &pts);
    CHECK(e < 1e-5, "fine grid: rel L2 %g", e);
    CHECK(pts == 2 * q.n, "fine grid: %zu points drawn, want two draws of %zu", pts, q.n);
    fs_particles_free(&q);
}

/* (b) The bar at test size, stages, layered / slice / exact builds. */
static void against_reference(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (load_dam(&p, &s, &f)) return;
    fs_gbuffer a, b, c, e;
    fs_gbuffer_alloc(&a, 128, 128);
    fs_gbuffer_alloc(&b, 128, 128);
    fs_gbuffer_alloc(&c, 128, 128);
    fs_gbuffer_alloc(&e, 128, 128);
    fs_stages st = {0};
    const char *layered[] = {"grid_res=128", NULL}, *slice[] = {"grid_res=128", "build=slice", NULL},
               *exact[] = {"grid_res=128", "build=exact", NULL};
    CHECK(fs_test_render("volume_raycast", layered, &p, f, &s.camera, &a, &st) == FS_OK, "layered: %s",
          fs_error_message());
    CHECK(fs_test_render("reference", NULL, &p, f, &s.camera, &b, NULL) == FS_OK, "reference: %s", fs_error_message());
    CHECK(fs_test_render("volume_raycast", slice, &p, f, &s.camera, &c, NULL) == FS_OK, "slice: %s",
          fs_error_message());
    CHECK(fs_test_render("volume_raycast", exact, &p, f, &s.camera, &e, NULL) == FS_OK, "exact: %s",
          fs_error_message());
    fs_metrics mt, ms, me;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, f.r, &mt) == FS_OK, "metrics: %s", fs_error_message());
    CHECK(fs_metrics_compute(&c, NULL, &a, NULL, f.r, &ms) == FS_OK, "metrics: %s", fs_error_message());
    CHECK(fs_metrics_compute(&e, NULL, &a, NULL, f.r, &me) == FS_OK, "metrics: %s", fs_error_message());
    printf("(b) dam break 6859 at 128^2, grid 128 vs reference: IoU %.4f, depth bias %.4f r, p95 %.4f r, normal %.2f "
           "deg (interior %.2f)\n",
           mt.mask_iou, mt.depth_bias_r, mt.depth_p95_r, mt.normal_mean_deg, mt.interior_normal_mean_deg);
    printf("(b) slice vs layered: IoU %.6f, depth p95 %.2g r, normal %.3g deg; exact vs layered: IoU %.6f, depth p95 "
           "%.2g r, normal %.3g deg\n",
           ms.mask_iou, ms.depth_p95_r, ms.normal_mean_deg, me.mask_iou, me.depth_p95_r, me.normal_mean_deg);
    CHECK(mt.n_both > 1500, "only %zu pixels covered by both", mt.n_both);
    CHECK(mt.mask_iou >= 0.95, "IoU %g", mt.mask_iou);
    CHECK(fabs(mt.depth_bias_r) <= 0.25 && mt.depth_p95_r <= 0.5, "depth bias %g r, p95 %g r", mt.depth_bias_r,
          mt.depth_p95_r);
    CHECK(mt.interior_normal_mean_deg < 10, "interior normal %g deg", mt.interior_normal_mean_deg);
    CHECK(ms.mask_iou > 0.999 && ms.depth_p95_r < 0.01 && ms.normal_mean_deg < 0.1, "slice differs from layered");
    CHECK(me.mask_iou > 0.999 && me.depth_p95_r < 0.01 && me.normal_mean_deg < 0.1, "exact differs from layered");
    const char *want[] = {"volume", "faces", "march", "readback", NULL};
    const char *missing = fs_test_missing_stage(&st, want);
    CHECK(!missing, "stage %s not reported", missing);
    double thick = 0, thick_ref = 0;
    for (int i = 0; i < 128 * 128; i++) {
        thick += a.thickness[i];
        thick_ref += b.thickness[i];
    }
    printf("(b) thickness sum %.4g (reference %.4g)\n", thick, thick_ref);
    CHECK(thick > 0.8 * thick_ref && thick < 1.2 * thick_ref, "thickness %g vs reference %g", thick, thick_ref);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    fs_gbuffer_free(&c);
    fs_gbuffer_free(&e);
    fs_particles_free(&p);
}

/* (c) Transfer functions: the own image in both modes; the translucent one
 * shows what is behind the water, and the G-buffer does not change with the
 * mode. (d) The .vdb export reads back as the layered grid. */
static void transfer_and_export(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (load_dam(&p, &s, &f)) return;
    const fs_method *m = fs_method_find("volume_raycast");
    static fs_scene s2; /* the same scene in translucent mode */
    fs_scene_add_set(&s, "volume_raycast.grid_res=96");
    s2 = s;
    fs_scene_add_set(&s2, "volume_raycast.mode=translucent");
    fs_run *runs[2] = {NULL, NULL};
    fs_run_image im[2];
    memset(im, 0, sizeof im);
    int rc = FS_OK;
    for (int k = 0; k < 2 && !rc; k++) {
        rc = fs_run_open(&runs[k], m, k ? &s2 : &s, NULL, NULL);
        if (!rc) rc = fs_run_upload(runs[k], &p, NULL, NULL);
        if (!rc) rc = fs_run_render(runs[k], &s.camera, &im[k], NULL);
    }
    for (int k = 0; k < 2 && !rc; k++)
        if (!fs_gbuffer_aov(&im[k].g, FS_AOV_OWN) || !fs_gbuffer_aov(&im[k].g, FS_AOV_CAUSTICS))
            rc = fs_fail(FS_ERR_RUNTIME, "the declared AOVs own and caustics are missing");
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (rc) {
        for (int k = 0; k < 2; k++) {
            fs_run_close(runs[k]);
            fs_run_image_free(&im[k]);
        }
        fs_particles_free(&p);
        return;
    }
    const fs_gbuffer g[2] = {im[0].g, im[1].g};
    const float *own[2], *caustics[2];
    for (int k = 0; k < 2; k++) {
        own[k] = fs_gbuffer_aov(&g[k], FS_AOV_OWN);
        caustics[k] = fs_gbuffer_aov(&g[k], FS_AOV_CAUSTICS);
    }
    fs_run *opaque = runs[0];
    size_t water = 0, differ = 0, gdiff = 0, bad = 0;
    double lum[2] = {0, 0};
    for (int i = 0; i < 128 * 128; i++) {
        for (int k = 0; k < 2; k++) {
            const float *o = own[k] + 4 * i;
            bad += !(isfinite(o[0]) && isfinite(o[1]) && isfinite(o[2]) && o[3] == 1.0f && caustics[k][i] == 0.0f);
        }
        gdiff += g[0].coverage[i] != g[1].coverage[i] || (g[0].coverage[i] > 0 && g[0].depth[i] != g[1].depth[i]);
        if (!g[0].coverage[i]) {
            /* the top rows see the sky past the water: the same background in both modes
             * (elsewhere the translucent skin below iso may tint pixels next to the water) */
            if (i < 128 * 8)
                for (int c = 0; c < 3; c++) differ += fabsf(own[0][4 * i + c] - own[1][4 * i + c]) > 1e-5f;
            continue;
        }
        water++;
        for (int k = 0; k < 2; k++) lum[k] += own[k][4 * i] + own[k][4 * i + 1] + own[k][4 * i + 2];
    }
    size_t changed = 0;
    for (int i = 0; i < 128 * 128; i++)
        if (g[0].coverage[i])
            changed += fabsf(own[0][4 * i] - own[1][4 * i]) + fabsf(own[0][4 * i + 2] - own[1][4 * i + 2]) > 0.02f;
    printf("(c) %zu water px; own surface vs translucent: %zu water px differ, mean rgb sum %.3f vs %.3f\n", water,
           changed, lum[0] / (water ? water : 1), lum[1] / (water ? water : 1));
    CHECK(bad == 0, "%zu own pixels not finite / not opaque / with caustics", bad);
    CHECK(gdiff == 0, "the mode changed %zu G-buffer pixels", gdiff);
    CHECK(differ == 0, "the sky differs in %zu channels", differ);
    CHECK(water > 1500 && changed > water / 2, "translucent differs in only %zu of %zu water pixels", changed, water);

    const char *vdb = FS_TEST_OUT "/volume_raycast_export.vdb";
    unlink(vdb);
#if !FS_WITH_OPENVDB
    int vrc = fs_run_export(opaque, vdb, NULL);
    CHECK_REFUSED(vrc, fs_error_message(), vdb, "FS_WITH_OPENVDB");
#else
    CHECK(fs_run_export(opaque, vdb, NULL) == FS_OK, "vdb: %s", fs_error_message());
    fs_density_grid d, ex;
    fs_grid ng;
    fs_grid_build(&ng, &p, f.H);
    CHECK(fs_density_grid_read_vdb(&d, vdb, "density") == FS_OK, "read vdb back: %s", fs_error_message());
    CHECK(fs_density_grid_init(&ex, p.bmin, p.bmax, f.H, 96) == FS_OK &&
              fs_density_grid_exact(&ex, &p, &ng, &f) == FS_OK,
          "exact: %s", fs_error_message());
    /* the VDB holds the active (phi > 0) bounding box: compare by world position */
    double maxd = 0, maxv = 0;
    for (int k = 0; k < d.dim[2]; k++)
        for (int j = 0; j < d.dim[1]; j++)
            for (int i = 0; i < d.dim[0]; i++) {
                float x[3] = {d.origin[0] + i * d.spacing, d.origin[1] + j * d.spacing, d.origin[2] + k * d.spacing};
                float a = d.data[fs_density_grid_index(&d, i, j, k)], b = fs_density_grid_sample(&ex, x);
                maxd = fmax(maxd, fabs(a - b));
                maxv = fmax(maxv, b);
            }
    printf("(d) vdb %dx%dx%d, spacing %.4g vs %.4g: max |vdb - exact| %.3g (max phi %.3g)\n", d.dim[0], d.dim[1],
           d.dim[2], d.spacing, ex.spacing, maxd, maxv);
    CHECK(fabsf(d.spacing - ex.spacing) < 1e-6f * ex.spacing, "spacing %g vs %g", d.spacing, ex.spacing);
    CHECK(maxv > 0.5 && maxd < 1e-4, "vdb differs from the exact grid by %g", maxd);
    fs_density_grid_free(&d);
    fs_density_grid_free(&ex);
    fs_grid_free(&ng);
#endif
    CHECK(fs_run_export(opaque, FS_TEST_OUT "/volume_raycast_export.ply", NULL) == FS_ERR_INPUT,
          "a .ply export must be refused");
    for (int k = 0; k < 2; k++) {
        fs_run_close(runs[k]);
        fs_run_image_free(&im[k]);
    }
    fs_particles_free(&p);
}

int main(void)
{
    fs_methods_register_builtin();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    layered_grid();
    against_reference();
    transfer_and_export();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
