/* levelset (OpenVDB's union-of-spheres level set, ray traced): against the exact
 * union of the same spheres (a CPU ray-sphere cast here), against the reference
 * on the bundled dam break and the synthetic box, the G-buffer conventions
 * (unit normals facing the camera, thickness > 0 and bounded), the thickness
 * switch, the .vdb export read back, and the refusals of bad parameters. */
#include "density_grid.h"
#include "fs_error.h"
#include "fs_test.h"
#include "method.h"
#include "metrics.h"
#include "run.h"
#include "scene.h"
#include "synthetic.h"
#include "test_render.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The exact union of spheres of radius R at the particles: nearest entry depth,
 * outward normal (view space, facing the camera), coverage. */
static void exact_spheres(const fs_particles *p, float R, const fs_camera *cam, fs_gbuffer *g)
{
    float right[3], up[3], fwd[3];
    fs_camera_basis(cam, right, up, fwd);
    fs_gbuffer_clear(g);
#pragma omp parallel for schedule(dynamic, 1)
    for (int py = 0; py < cam->height; py++)
        for (int px = 0; px < cam->width; px++) {
            float d[3];
            fs_camera_ray(cam, px + 0.5f, py + 0.5f, d);
            double best = INFINITY;
            size_t bi = 0;
            for (size_t i = 0; i < p->n; i++) {
                double o[3] = {cam->eye[0] - p->x[i], cam->eye[1] - p->y[i], cam->eye[2] - p->z[i]};
                double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
                double c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - (double)R * R, disc = b * b - c;
                if (disc < 0) continue;
                double t = -b - sqrt(disc);
                if (t > 0 && t < best) { best = t; bi = i; }
            }
            if (!isfinite(best)) continue;
            size_t id = (size_t)py * cam->width + px;
            float n[3] = {(float)((cam->eye[0] + best * d[0] - p->x[bi]) / R),
                          (float)((cam->eye[1] + best * d[1] - p->y[bi]) / R),
                          (float)((cam->eye[2] + best * d[2] - p->z[bi]) / R)};
            fs_camera_to_view_dir(cam, n, g->normal + 3 * id);
            g->depth[id] = (float)best * (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]);
            g->coverage[id] = 1;
        }
}

/* Conventions every G-buffer keeps; returns the largest thickness. */
static float conventions(const char *what, const fs_gbuffer *g, const fs_camera *cam, int want_thick)
{
    int bad_n = 0, bad_face = 0, bad_t = 0, bad_d = 0, zero_t = 0, covered = 0;
    float tmax = 0;
    for (int py = 0; py < g->h; py++)
        for (int px = 0; px < g->w; px++) {
            size_t id = (size_t)py * g->w + px;
            const float *n = g->normal + 3 * id;
            if (!g->coverage[id]) {
                bad_d += !isinf(g->depth[id]) || g->thickness[id] != 0;
                continue;
            }
            float dw[3], dv[3];
            fs_camera_ray(cam, px + 0.5f, py + 0.5f, dw);
            fs_camera_to_view_dir(cam, dw, dv);
            bad_n += fabsf(sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) > 1e-4f;
            bad_face += n[0] * dv[0] + n[1] * dv[1] + n[2] * dv[2] > 1e-6f;
            bad_d += !(g->depth[id] > 0) || !isfinite(g->depth[id]);
            bad_t += want_thick ? !(g->thickness[id] >= 0) : g->thickness[id] != 0;
            zero_t += g->thickness[id] == 0;
            covered++;
            if (g->thickness[id] > tmax) tmax = g->thickness[id];
        }
    CHECK(!bad_n && !bad_face && !bad_d && !bad_t,
          "%s: %d normals not unit, %d not facing the camera, %d bad depths, %d bad thickness", what, bad_n, bad_face,
          bad_d, bad_t);
    /* a grazing hit whose exit lies within the intersector's step has none: 0.1% */
    if (want_thick) CHECK(zero_t <= covered / 1000, "%s: %d of %d covered pixels have thickness 0", what, zero_t, covered);
    return tmax;
}

static fs_metrics measure(const char *what, const fs_gbuffer *a, const fs_gbuffer *b, float r)
{
    fs_metrics m;
    memset(&m, 0, sizeof m);
    CHECK(fs_metrics_compute(a, NULL, b, NULL, r, &m) == FS_OK, "metrics: %s", fs_error_message());
    printf("%s: IoU %.4f, depth bias %.3f r, rmse %.3f r, p95 %.3f r, normal mean %.2f deg (interior %.2f), p95 %.2f deg\n",
           what, m.mask_iou, m.depth_bias_r, m.depth_rmse_r, m.depth_p95_r, m.normal_mean_deg,
           m.interior_normal_mean_deg, m.normal_p95_deg);
    return m;
}

static double diag(const fs_particles *p, float grow)
{
    double s = 0;
    for (int a = 0; a < 3; a++) {
        double e = p->bmax[a] - p->bmin[a] + 2 * grow;
        s += e * e;
    }
    return sqrt(s);
}

/* One frame: levelset against the exact spheres and the reference. */
static void frame(const char *name, const fs_particles *p, fs_field f, const fs_camera *cam, double iou_ref,
                  double bias_lo, double bias_hi)
{
    fs_gbuffer ls, ex, ref;
    fs_gbuffer_alloc(&ls, cam->width, cam->height);
    fs_gbuffer_alloc(&ex, cam->width, cam->height);
    fs_gbuffer_alloc(&ref, cam->width, cam->height);
    fs_stages st = {0};
    CHECK(fs_test_render("levelset", NULL, p, f, cam, &ls, &st) == FS_OK, "%s: levelset: %s", name, fs_error_message());
    const char *want[] = {"upload", "trace", NULL}, *miss = fs_test_missing_stage(&st, want);
    CHECK(miss == NULL, "%s: no stage %s", name, miss);
    CHECK(fs_test_render("reference", NULL, p, f, cam, &ref, NULL) == FS_OK, "%s: reference: %s", name, fs_error_message());
    exact_spheres(p, 2 * f.r, cam, &ex);
    char what[128];
    snprintf(what, sizeof what, "%s, levelset vs exact spheres of 2r", name);
    fs_metrics e = measure(what, &ls, &ex, f.r);
    /* the level set is the union sampled at voxel r/2: the silhouette moves by a
     * fraction of a voxel, the depth by less; the normals round the creases */
    CHECK(e.mask_iou >= 0.98, "%s: IoU %g vs the exact spheres", name, e.mask_iou);
    CHECK(fabs(e.depth_bias_r) <= 0.2 && e.depth_rmse_r <= 0.5, "%s: depth bias %g r, rmse %g r vs the exact spheres",
          name, e.depth_bias_r, e.depth_rmse_r);
    CHECK(e.interior_normal_mean_deg <= 15, "%s: interior normal %g deg vs the exact spheres", name,
          e.interior_normal_mean_deg);
    snprintf(what, sizeof what, "%s, levelset vs reference", name);
    fs_metrics m = measure(what, &ls, &ref, f.r);
    /* spheres of 2r stand about r outside the iso-surface (closer to the eye) */
    CHECK(m.mask_iou >= iou_ref, "%s: IoU %g vs reference (want >= %g)", name, m.mask_iou, iou_ref);
    CHECK(m.depth_bias_r >= bias_lo && m.depth_bias_r <= bias_hi, "%s: depth bias %g r vs reference (want %g..%g)", name,
          m.depth_bias_r, bias_lo, bias_hi);
    CHECK(m.interior_normal_mean_deg <= 35, "%s: interior normal %g deg vs reference", name, m.interior_normal_mean_deg);
    float tmax = conventions(name, &ls, cam, 1);
    double bound = diag(p, 2 * f.r);
    printf("%s: largest thickness %.4f (bound: the spheres' box diagonal %.4f)\n", name, tmax, bound);
    CHECK(tmax <= bound, "%s: thickness %g beyond the box diagonal %g", name, tmax, bound);
    /* thickness off: the same surface, thickness 0 */
    const char *off[] = {"thickness=off", NULL};
    fs_gbuffer no;
    fs_gbuffer_alloc(&no, cam->width, cam->height);
    CHECK(fs_test_render("levelset", off, p, f, cam, &no, NULL) == FS_OK, "%s: thickness off: %s", name, fs_error_message());
    conventions("thickness off", &no, cam, 0);
    size_t n = (size_t)cam->width * cam->height;
    CHECK(!memcmp(no.depth, ls.depth, n * sizeof(float)) && !memcmp(no.normal, ls.normal, 3 * n * sizeof(float)),
          "%s: thickness off changed the surface", name);
    fs_gbuffer_free(&no);
    fs_gbuffer_free(&ls);
    fs_gbuffer_free(&ex);
    fs_gbuffer_free(&ref);
}

static void dam_break(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) { CHECK(0, "dam: %s", fs_error_message()); return; }
    frame("dam break 6859, 128^2", &p, f, &s.camera, 0.75, -4.0, -0.3);
    fs_particles_free(&p);
}

static void box(void)
{
    static fs_scene s;
    fs_particles p;
    int rc = fs_scene_load(&s, FS_SOURCE_DIR "/experiments/scenes/box.json");
    CHECK(rc == FS_OK, "box.json: %s", fs_error_message());
    if (rc || fs_synthetic_generate(&s, 0, &p)) { CHECK(0, "box: %s", fs_error_message()); return; }
    s.camera.width = s.camera.height = 96;
    fs_scene_frame_particles(&s, &p);
    frame("box, 96^2", &p, fs_scene_field(&s), &s.camera, 0.8, -4.0, -0.3);
    /* a ray straight through the box's middle sees about its width in x */
    fs_camera c = s.camera;
    float mid[3];
    for (int a = 0; a < 3; a++) mid[a] = 0.5f * (p.bmin[a] + p.bmax[a]);
    memcpy(c.target, mid, sizeof mid);
    memcpy(c.eye, mid, sizeof mid);
    c.eye[0] = p.bmax[0] + 1.0f;
    c.up[0] = 0, c.up[1] = 1, c.up[2] = 0;
    c.width = c.height = 9;
    fs_camera_fit_clip(&c, p.bmin, p.bmax);
    fs_gbuffer g;
    fs_gbuffer_alloc(&g, 9, 9);
    CHECK(fs_test_render("levelset", NULL, &p, fs_scene_field(&s), &c, &g, NULL) == FS_OK, "side: %s", fs_error_message());
    /* the ray passes at most sqrt(2) r from a lattice row (spacing 2r), so each end
     * sphere of 2r adds between sqrt(2) r and 2r to the centres' extent */
    float ext = p.bmax[0] - p.bmin[0], got = g.thickness[4 * 9 + 4];
    float lo = ext + 2 * 1.3f * s.radius, hi = ext + 2 * 2.05f * s.radius;
    printf("box side view: centre thickness %.4f, want %.4f..%.4f (centres' extent %.4f + 2 x 1.3..2.05 r)\n", got, lo, hi, ext);
    CHECK(got >= lo && got <= hi, "box: centre thickness %g, want %g..%g", got, lo, hi);
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

/* The export: a .vdb that OpenVDB reads back (as a float grid); other kinds refused. */
static void export_vdb(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) return;
    fs_methods_register_builtin();
    fs_run *run = NULL;
    int rc = fs_run_open(&run, fs_method_find("levelset"), &s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &p, NULL, NULL);
    CHECK(rc == FS_OK, "open/upload: %s", fs_error_message());
    char path[256], bad[256];
    snprintf(path, sizeof path, "%s/test_levelset_%d.vdb", P_tmpdir, (int)getpid());
    snprintf(bad, sizeof bad, "%s/test_levelset_%d.ply", P_tmpdir, (int)getpid());
    CHECK(!rc && fs_run_export(run, path) == FS_OK, "export: %s", fs_error_message());
    CHECK(fs_run_export(run, bad) == FS_ERR_INPUT && access(bad, F_OK) != 0, "a .ply export is refused, no file");
    fs_density_grid g;
    CHECK(fs_density_grid_read_vdb(&g, path, "surface") == FS_OK, "read back: %s", fs_error_message());
    if (g.data) {
        CHECK(fabsf(g.spacing - 0.5f * f.r) < 1e-6f, "voxel %g, want r/2", g.spacing);
        size_t n = (size_t)g.dim[0] * g.dim[1] * g.dim[2], neg = 0;
        for (size_t i = 0; i < n; i++) neg += g.data[i] < 0;
        CHECK(neg > 0, "no voxel inside the level set");
        printf("export: %dx%dx%d voxels, spacing %g, %zu inside\n", g.dim[0], g.dim[1], g.dim[2], g.spacing, neg);
        fs_density_grid_free(&g);
    }
    unlink(path);
    fs_run_close(run);
    fs_particles_free(&p);
}

/* Bad parameters: refused by the table (the range) or by create (radius under 1.5 voxels). */
static void refusals(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) return;
    const char *bad[][2] = {{"radius=0", NULL}, {"voxel=0", NULL}, {"voxel=-1", NULL}, {"half_width=0.5", NULL},
                            {"smooth=median", NULL}, {"radius=0.5", NULL}};
    fs_gbuffer g;
    fs_gbuffer_alloc(&g, 8, 8);
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        int rc = fs_test_render("levelset", bad[i], &p, f, &s.camera, &g, NULL);
        CHECK(rc == FS_ERR_INPUT && !strchr(fs_error_message(), '\n'), "%s: rc %d (%s)", bad[i][0], rc, fs_error_message());
        printf("%s: %s\n", bad[i][0], fs_error_message());
    }
    /* the recipe runs: dilate, smooth, erode */
    const char *recipe[] = {"dilate=1", "smooth=meancurvature", "smooth_iters=2", "erode=1", NULL};
    s.camera.width = s.camera.height = 64;
    CHECK(fs_test_render("levelset", recipe, &p, f, &s.camera, &g, NULL) == FS_OK, "recipe: %s", fs_error_message());
    conventions("recipe", &g, &s.camera, 1);
    const char *gauss[] = {"smooth=gaussian", "smooth_iters=3", NULL};
    CHECK(fs_test_render("levelset", gauss, &p, f, &s.camera, &g, NULL) == FS_OK, "gaussian: %s", fs_error_message());
    conventions("gaussian", &g, &s.camera, 1);
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

int main(void)
{
    dam_break();
    box();
    export_vdb();
    refusals();
    TEST_DONE();
}
