/* levelset (OpenVDB's union-of-spheres level set, ray traced): against the exact
 * union of the same spheres (a CPU ray-sphere cast here) on the bundled dam break
 * and the synthetic box, with bounds from the voxel size (vs_union), and at half
 * the voxel on the box (it converges), the G-buffer conventions
 * (unit normals facing the camera, thickness > 0 and bounded), the thickness
 * switch, the .vdb export read back, and the refusals of bad parameters. */
#include "density_grid.h"
#include "fs_error.h"
#include "fs_test.h"
#include "method.h"
#include "builtin_methods.h"
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
                if (t > 0 && t < best) {
                    best = t;
                    bi = i;
                }
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
    if (want_thick)
        CHECK(zero_t <= covered / 1000, "%s: %d of %d covered pixels have thickness 0", what, zero_t, covered);
    return tmax;
}

static fs_metrics measure(const char *what, const fs_gbuffer *a, const fs_gbuffer *b, float r)
{
    fs_metrics m;
    memset(&m, 0, sizeof m);
    CHECK(fs_metrics_compute(a, NULL, b, NULL, r, &m) == FS_OK, "metrics: %s", fs_error_message());
    printf(
        "%s: IoU %.4f, depth bias %.3f r, rmse %.3f r, p95 %.3f r, normal mean %.2f deg (interior %.2f), p95 %.2f deg\n",
        what, m.mask_iou, m.depth_bias_r, m.depth_rmse_r, m.depth_p95_r, m.normal_mean_deg, m.interior_normal_mean_deg,
        m.normal_p95_deg);
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

/* What a sampled union of spheres must satisfy against the exact union of the same
 * spheres, from its voxel h and sphere radius R (the defaults: h = r/2, R = 2r).
 * ParticlesToLevelSet stores at each voxel the exact signed distance to the nearest
 * sphere, d = min_i |x - p_i| - R; LevelSetRayIntersector takes the zero of the
 * trilinear interpolant of those samples along the ray (a secant between voxel
 * crossings) and the interpolant's gradient as the normal (BoxStencil::gradient).
 * - Where the surface is. The trilinear weights of x are a probability over the cell's
 *   corners c with mean x and sum w |c - x|^2 = h^2 sum_axes t (1 - t) <= 3 h^2 / 4. d is
 *   1-Lipschitz, so everywhere |interp - d| <= sum w |c - x| <= (sqrt 3 / 2) h (0.43 r):
 *   the surface stays within that of the exact one. On one sphere's own part d is
 *   convex with Hessian <= I / R near the surface, so by Jensen 0 <= interp - d <=
 *   3 h^2 / (8 R) (0.05 r): the surface moves inward by at most that. Only at a crease,
 *   where two spheres meet and d = min of two is not convex, does it fill in outward,
 *   by up to (sqrt 3 / 2) h at the crease line and by nothing a voxel away.
 * - Coverage. The silhouettes run along the spheres' outlines, which move inward by at
 *   most 3 h^2 / (8 R); only the notches where two outlines meet fill in, by up to
 *   (sqrt 3 / 2) h. So a pixel changes coverage only within k = ceil((sqrt 3 / 2) h /
 *   pixel) pixels of the exact silhouette (asserted below), and there only where its
 *   centre lies between the two outlines: a small share of the rim, so IoU >= 0.98.
 * - Depth. Along a ray an offset delta reads delta / cos(theta) (theta between the ray
 *   and the normal). The inward 3 h^2 / (8 R) stays under h / 2 wherever cos(theta) >=
 *   3 h / (4 R) = 0.19, all but the outer 3.5% of a sphere's disk; the crease fill-in,
 *   (sqrt 3 / 2) h at the line tapering to 0 a voxel off, averages under h / 2 and
 *   pulls the other way: |depth bias| <= h / 2. The crease fill-in is seen on caps that
 *   face the eye within the crease's half angle (30 degrees, below), so it reads at most
 *   (sqrt 3 / 2) h / cos 30 = h: the 95th percentile of |error - bias| <= h (the top 5%
 *   are grazing pixels and pixels whose ray meets another sphere, which no voxel bounds).
 * - Normals. Neighbours at the fluid's rest spacing 2r (the box's lattice) meet in a
 *   crease whose two normals differ by 2 asin(2r / (2 R)) = 60 degrees. Within about a
 *   voxel of it the interpolant's gradient blends them, its error running from the
 *   half angle, 30 degrees, at the crease to about 0 a voxel off: 15 degrees on average.
 *   Off that band the gradient of the interpolated distance of one sphere errs by O(h/R)
 *   rad, a few degrees. So the mean over the interior stays <= 15 degrees.
 * - As h -> 0 the level set converges to the union: the bounds hold for h / 2 with h / 2
 *   in them, and the depth spread and the normal error shrink. */
typedef struct union_bounds {
    double iou, bias_r, p95_r, normal_deg;
} union_bounds;

static union_bounds bounds_for(double h_r)
{
    return (union_bounds){.iou = 0.98, .bias_r = h_r / 2, .p95_r = h_r, .normal_deg = 15};
}

/* levelset (sphere radius 2r, voxel h_r r) against the exact union of its spheres ex:
 * the bounds above and the rim; returns the metrics. */
static fs_metrics vs_union(const char *name, const fs_particles *p, fs_field f, const fs_camera *cam, double h_r,
                           const fs_gbuffer *ex, fs_gbuffer *ls)
{
    char voxel[64], what[160];
    snprintf(voxel, sizeof voxel, "voxel=%g", h_r);
    const char *sets[] = {"radius=2", voxel, NULL};
    fs_stages st = {0};
    CHECK(fs_test_render("levelset", sets, p, f, cam, ls, &st) == FS_OK, "%s: levelset: %s", name, fs_error_message());
    const char *want[] = {"upload", "trace", NULL}, *miss = fs_test_missing_stage(&st, want);
    CHECK(miss == NULL, "%s: no stage %s", name, miss);
    snprintf(what, sizeof what, "%s, voxel %g r, levelset vs the exact spheres of 2r", name, h_r);
    fs_metrics e = measure(what, ls, ex, f.r);
    union_bounds b = bounds_for(h_r);
    CHECK(e.mask_iou >= b.iou, "%s: IoU %g vs the exact spheres (want >= %g)", what, e.mask_iou, b.iou);
    CHECK(fabs(e.depth_bias_r) <= b.bias_r, "%s: depth bias %g r (want |bias| <= h/2 = %g r)", what, e.depth_bias_r,
          b.bias_r);
    CHECK(e.depth_p95_r <= b.p95_r, "%s: depth p95 %g r (want <= h = %g r)", what, e.depth_p95_r, b.p95_r);
    CHECK(e.interior_normal_mean_deg <= b.normal_deg, "%s: interior normal %g deg (want <= %g)", what,
          e.interior_normal_mean_deg, b.normal_deg);
    /* the rim: a pixel whose coverage differs lies within k pixels (chessboard) of a
     * pixel of the other exact coverage, k = the largest offset, (sqrt 3 / 2) h, over
     * the smallest pixel footprint (at the nearest depth), rounded up */
    double zmin = INFINITY, tan_half = tan(0.5 * cam->fovy_deg * M_PI / 180);
    size_t n = (size_t)cam->width * cam->height;
    for (size_t i = 0; i < n; i++)
        if (ex->coverage[i] && ex->depth[i] < zmin) zmin = ex->depth[i];
    double px_r = zmin * 2 * tan_half / cam->height / f.r, offset_r = sqrt(3.0) / 2 * h_r;
    int k = (int)ceil(offset_r / px_r), off_rim = 0, changed = 0;
    for (int y = 0; y < cam->height; y++)
        for (int x = 0; x < cam->width; x++) {
            size_t id = (size_t)y * cam->width + x;
            if (!ex->coverage[id] == !ls->coverage[id]) continue;
            changed++;
            int rim = 0;
            for (int v = y - k; v <= y + k; v++)
                for (int u = x - k; u <= x + k; u++)
                    if (u >= 0 && v >= 0 && u < cam->width && v < cam->height)
                        rim |= !ex->coverage[(size_t)v * cam->width + u] != !ex->coverage[id];
            off_rim += !rim;
        }
    printf(
        "%s: %d pixels change coverage, %d more than %d px off the exact silhouette (pixel >= %.3f r, offset <= %.3f r)\n",
        what, changed, off_rim, k, px_r, offset_r);
    CHECK(off_rim == 0, "%s: %d pixels change coverage more than %d px off the exact silhouette", what, off_rim, k);
    return e;
}

/* One frame: levelset against the exact union of its spheres (and at half the voxel,
 * when converge), the conventions, the thickness bound and switch. */
static void frame(const char *name, const fs_particles *p, fs_field f, const fs_camera *cam, int converge)
{
    fs_gbuffer ls, ex;
    fs_gbuffer_alloc(&ls, cam->width, cam->height);
    fs_gbuffer_alloc(&ex, cam->width, cam->height);
    exact_spheres(p, 2 * f.r, cam, &ex);
    fs_metrics e = vs_union(name, p, f, cam, 0.5, &ex, &ls);
    if (converge) {
        fs_gbuffer fine;
        fs_gbuffer_alloc(&fine, cam->width, cam->height);
        fs_metrics e2 = vs_union(name, p, f, cam, 0.25, &ex, &fine);
        CHECK(e2.depth_p95_r < e.depth_p95_r && e2.interior_normal_mean_deg < e.interior_normal_mean_deg,
              "%s: halving the voxel does not shrink the error: depth p95 %g -> %g r, normal %g -> %g deg", name,
              e.depth_p95_r, e2.depth_p95_r, e.interior_normal_mean_deg, e2.interior_normal_mean_deg);
        fs_gbuffer_free(&fine);
    }
    float tmax = conventions(name, &ls, cam, 1);
    double bound = diag(p, 2 * f.r);
    printf("%s: largest thickness %.4f (bound: the spheres' box diagonal %.4f)\n", name, tmax, bound);
    CHECK(tmax <= bound, "%s: thickness %g beyond the box diagonal %g", name, tmax, bound);
    /* thickness off: the same surface, thickness 0 */
    const char *off[] = {"thickness=off", NULL};
    fs_gbuffer no;
    fs_gbuffer_alloc(&no, cam->width, cam->height);
    CHECK(fs_test_render("levelset", off, p, f, cam, &no, NULL) == FS_OK, "%s: thickness off: %s", name,
          fs_error_message());
    conventions("thickness off", &no, cam, 0);
    size_t n = (size_t)cam->width * cam->height;
    CHECK(!memcmp(no.depth, ls.depth, n * sizeof(float)) && !memcmp(no.normal, ls.normal, 3 * n * sizeof(float)),
          "%s: thickness off changed the surface", name);
    fs_gbuffer_free(&no);
    fs_gbuffer_free(&ls);
    fs_gbuffer_free(&ex);
}

static void dam_break(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) {
        CHECK(0, "dam: %s", fs_error_message());
        return;
    }
    frame("dam break 6859, 128^2", &p, f, &s.camera, 0);
    fs_particles_free(&p);
}

static void box(void)
{
    static fs_scene s;
    fs_particles p;
    int rc = fs_scene_load(&s, FS_SOURCE_DIR "/experiments/scenes/box.json");
    CHECK(rc == FS_OK, "box.json: %s", fs_error_message());
    if (rc || fs_synthetic_generate(&s, 0, &p)) {
        CHECK(0, "box: %s", fs_error_message());
        return;
    }
    s.camera.width = s.camera.height = 96;
    fs_scene_frame_particles(&s, &p);
    frame("box, 96^2", &p, fs_scene_field(&s), &s.camera, 1);
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
    CHECK(fs_test_render("levelset", NULL, &p, fs_scene_field(&s), &c, &g, NULL) == FS_OK, "side: %s",
          fs_error_message());
    /* the ray passes at most sqrt(2) r from a lattice row (spacing 2r), so each end
     * sphere of 2r adds between sqrt(2) r and 2r to the centres' extent */
    float ext = p.bmax[0] - p.bmin[0], got = g.thickness[4 * 9 + 4];
    float lo = ext + 2 * 1.3f * s.radius, hi = ext + 2 * 2.05f * s.radius;
    printf("box side view: centre thickness %.4f, want %.4f..%.4f (centres' extent %.4f + 2 x 1.3..2.05 r)\n", got, lo,
           hi, ext);
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
    CHECK(!rc && fs_run_export(run, path, NULL) == FS_OK, "export: %s", fs_error_message());
    CHECK(fs_run_export(run, bad, NULL) == FS_ERR_INPUT && access(bad, F_OK) != 0, "a .ply export is refused, no file");
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
    const char *bad[][2] = {{"radius=0", NULL},       {"voxel=0", NULL},       {"voxel=-1", NULL},
                            {"half_width=0.5", NULL}, {"smooth=median", NULL}, {"radius=0.5", NULL}};
    fs_gbuffer g;
    fs_gbuffer_alloc(&g, 8, 8);
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        int rc = fs_test_render("levelset", bad[i], &p, f, &s.camera, &g, NULL);
        CHECK(rc == FS_ERR_INPUT && !strchr(fs_error_message(), '\n'), "%s: rc %d (%s)", bad[i][0], rc,
              fs_error_message());
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
