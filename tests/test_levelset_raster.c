/* levelset.rasterizer=particles|spheres|smooth against the analytic shape: a
 * ball of particles on the rest lattice (spacing s = 2r, centres within Rb = 6 s)
 * with spheres of R = 2r, seen from far away (nearly orthographic), against the
 * exact sphere of radius Ra = Rb + R, the outline of the whole union. Each
 * rasteriser's silhouette radius, the depth of the centre pixel, its thickness
 * (the diameter through the centre) and the depth and normal error against the
 * sphere are held to the bounds derived at sphere_bounds; spheres must give the
 * same union as particles, smooth a smoother one; an unknown rasteriser and a
 * search radius under the sphere radius are refused in one line. */
#include "fs_error.h"
#include "fs_test.h"
#include "metrics.h"
#include "test_render.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LAT 6 /* Rb in lattice spacings */

static void ball(fs_particles *p, float r, const float c[3])
{
    int n = 0;
    fs_particles_alloc(p, (size_t)(2 * LAT + 1) * (2 * LAT + 1) * (2 * LAT + 1), 0);
    for (int i = -LAT; i <= LAT; i++)
        for (int j = -LAT; j <= LAT; j++)
            for (int k = -LAT; k <= LAT; k++)
                if (i * i + j * j + k * k <= LAT * LAT) {
                    p->x[n] = c[0] + 2 * r * i, p->y[n] = c[1] + 2 * r * j, p->z[n] = c[2] + 2 * r * k;
                    n++;
                }
    p->n = (size_t)n;
    p->radius = r;
    fs_particles_bounds(p);
}

/* The exact sphere (centre c, radius Ra): depth, view-space normal, coverage, and
 * the chord as thickness. */
static void exact_sphere(const float c[3], double Ra, const fs_camera *cam, fs_gbuffer *g)
{
    float right[3], up[3], fwd[3];
    fs_camera_basis(cam, right, up, fwd);
    fs_gbuffer_clear(g);
    for (int py = 0; py < cam->height; py++)
        for (int px = 0; px < cam->width; px++) {
            float d[3];
            fs_camera_ray(cam, px + 0.5f, py + 0.5f, d);
            double o[3] = {cam->eye[0] - c[0], cam->eye[1] - c[1], cam->eye[2] - c[2]};
            double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
            double disc = b * b - (o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - Ra * Ra);
            if (disc < 0) continue;
            double t = -b - sqrt(disc);
            size_t id = (size_t)py * cam->width + px;
            float n[3];
            for (int a = 0; a < 3; a++) n[a] = (float)((cam->eye[a] + t * d[a] - c[a]) / Ra);
            fs_camera_to_view_dir(cam, n, g->normal + 3 * id);
            g->depth[id] = (float)(t * (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]));
            g->thickness[id] = (float)(2 * sqrt(disc));
            g->coverage[id] = 1;
        }
}

/* What each rasteriser must give, in units of r (h = r/2 the voxel, R = 2r, s = 2r).
 * - The union of the lattice spheres lies inside the sphere of Ra = Rb + R (every
 *   centre is within Rb). It holds the ball of Ra - sqrt 3 s (3.46 r): for |x| <= Rb +
 *   R - sqrt 3 s, the point y = x scaled to |y| = Rb - (sqrt 3 / 2) s has its nearest
 *   lattice point q within (sqrt 3 / 2) s (so |q| <= Rb, a centre), and |x - q| <=
 *   |x - y| + (sqrt 3 / 2) s <= R. A sampled level set of exact distances stays within
 *   (sqrt 3 / 2) h = 0.43 r of the union (trilinear interpolation of a 1-Lipschitz
 *   function; derived in test_levelset.c). So particles and spheres put the surface
 *   between Ra - 3.9 r and Ra + 0.43 r from the centre: the silhouette radius, the
 *   centre pixel's depth offset and half the centre thickness are held there.
 * - smooth (Zhu & Bridson): phi = |x - xbar| - R with xbar a convex combination of
 *   centres within the search radius, so phi <= 0 only within R of the centres' hull
 *   (the ball Rb): the surface is inside Ra too (+ 0.43 r for the sampling). It blends
 *   the spheres, filling the notches between them, so it was measured a little
 *   outside the union (silhouette 13.3 r against 13.2 r); no closed lower bound
 *   follows for a lattice, so the union's lower bound is used for it (not proven).
 * - Mean depth error against the sphere (both covered): the radial offsets above read
 *   along a ray as offset / cos(theta), which averages 2x over a disk, so up to 7.8 r
 *   would be allowed; held to <= 2 r (measured 1.3 r for the unions, 1.1 r for smooth,
 *   the depth of the bumps and notches between the outer spheres). IoU >= 0.85
 *   (((Ra - 3.9) / (Ra + 0.43))^2 would allow 0.49; measured 0.88 and 0.90).
 * - Normals: a union's normals are the spheres' own, up to 60 degrees off the ball's
 *   at the creases between neighbours; smooth's blend over the search radius, so its
 *   interior normal error against the sphere must be under 3/4 of the unions' (measured
 *   12 against 28 degrees).
 * - Thickness: the ball is symmetric under z -> -z, so the centre ray's exit lies as far
 *   behind the centre as its entry before it, each within 0.43 r of the shape's own:
 *   half the thickness is the front radius within 0.43 r. (This needs the inside of
 *   the level set signed as inside: smooth's deep inside is flood-filled for that.) */
typedef struct shape {
    double sil_r, front_r, thick_half_r; /* radii of the surface seen three ways, in r */
} shape;

static shape measure_shape(const fs_gbuffer *g, const fs_camera *cam, const float c[3], double px_world, float r)
{
    size_t n = (size_t)g->w * g->h, cov = 0;
    for (size_t i = 0; i < n; i++) cov += g->coverage[i] > 0;
    size_t mid = (size_t)(g->h / 2) * g->w + g->w / 2;
    double dist = 0; /* eye to centre along the view axis */
    for (int a = 0; a < 3; a++) dist += (double)(c[a] - cam->eye[a]) * (c[a] - cam->eye[a]);
    dist = sqrt(dist);
    shape s;
    s.sil_r = sqrt((double)cov / M_PI) * px_world / r;
    s.front_r = g->coverage[mid] ? (dist - g->depth[mid]) / r : 0;
    s.thick_half_r = 0.5 * g->thickness[mid] / r;
    return s;
}

static int within(double v, double lo, double hi) { return v >= lo && v <= hi; }

/* One rasteriser: its G-buffer (returned in g) against the exact sphere ex. */
static fs_metrics one(const char *name, const fs_particles *p, fs_field f, const fs_camera *cam, const float c[3],
                      double px_world, const fs_gbuffer *ex, fs_gbuffer *g)
{
    char set[64];
    snprintf(set, sizeof set, "rasterizer=%s", name);
    const char *sets[] = {"radius=2", "voxel=0.5", set, NULL};
    fs_metrics m;
    memset(&m, 0, sizeof m);
    int rc = fs_test_render("levelset", sets, p, f, cam, g, NULL);
    CHECK(rc == FS_OK, "%s: %s", name, fs_error_message());
    if (rc) return m;
    CHECK(fs_metrics_compute(g, NULL, ex, NULL, f.r, &m) == FS_OK, "%s: metrics: %s", name, fs_error_message());
    double Ra = (2.0 * LAT + 2) * 1; /* in r: Rb = 6 s = 12 r, R = 2 r */
    shape s = measure_shape(g, cam, c, px_world, f.r);
    double lo = Ra - 3.9, hi = Ra + 0.43;
    printf("%s: silhouette radius %.3f r, centre front %.3f r, half thickness %.3f r (want %.2f..%.2f; sphere %.0f r); "
           "IoU %.4f, depth bias %.3f r, p95 %.3f r, interior normal %.2f deg\n",
           name, s.sil_r, s.front_r, s.thick_half_r, lo, hi, Ra, m.mask_iou, m.depth_bias_r, m.depth_p95_r,
           m.interior_normal_mean_deg);
    CHECK(within(s.sil_r, lo, hi), "%s: silhouette radius %g r outside %g..%g", name, s.sil_r, lo, hi);
    CHECK(within(s.front_r, lo, hi), "%s: centre front %g r outside %g..%g", name, s.front_r, lo, hi);
    CHECK(within(s.thick_half_r, lo, hi), "%s: half centre thickness %g r outside %g..%g", name, s.thick_half_r, lo,
          hi);
    CHECK(fabs(s.thick_half_r - s.front_r) <= 0.43,
          "%s: half centre thickness %g r against the front's %g r (want within 0.43 r)", name, s.thick_half_r,
          s.front_r);
    CHECK(within(m.depth_bias_r, -0.43, 2.0), "%s: depth bias %g r outside -0.43..2", name, m.depth_bias_r);
    CHECK(m.mask_iou >= 0.85, "%s: IoU %g against the sphere (want >= 0.85)", name, m.mask_iou);
    return m;
}

static void rasterizers(void)
{
    float r = 0.025f, c[3] = {0.3f, 0.7f, -0.2f};
    fs_particles p;
    ball(&p, r, c);
    fs_field f = {r, 0.8f * 8 * r * r * r, FS_KERNEL_CUBIC, 4 * r, 0.6f};
    /* far and narrow: nearly orthographic, so the silhouette's area gives the radius */
    fs_camera cam = {.eye = {c[0], c[1], c[2] + 40.0f},
                     .target = {c[0], c[1], c[2]},
                     .up = {0, 1, 0},
                     .fovy_deg = 2.0f,
                     .width = 96,
                     .height = 96};
    fs_camera_fit_clip(&cam, p.bmin, p.bmax);
    double px_world = 2 * 40.0 * tan(1.0 * M_PI / 180) / cam.height;
    fs_gbuffer ex, gp, gs, gm;
    fs_gbuffer_alloc(&ex, cam.width, cam.height);
    fs_gbuffer_alloc(&gp, cam.width, cam.height);
    fs_gbuffer_alloc(&gs, cam.width, cam.height);
    fs_gbuffer_alloc(&gm, cam.width, cam.height);
    exact_sphere(c, (2.0 * LAT + 2) * r, &cam, &ex);
    fs_metrics mp = one("particles", &p, f, &cam, c, px_world, &ex, &gp);
    fs_metrics ms = one("spheres", &p, f, &cam, c, px_world, &ex, &gs);
    fs_metrics mm = one("smooth", &p, f, &cam, c, px_world, &ex, &gm);
    (void)ms;
    /* spheres and particles sample the same union, each within 0.43 r of it */
    fs_metrics d;
    CHECK(fs_metrics_compute(&gs, NULL, &gp, NULL, r, &d) == FS_OK, "spheres vs particles: %s", fs_error_message());
    printf("spheres vs particles: IoU %.4f, depth bias %.3f r, p95 %.3f r\n", d.mask_iou, d.depth_bias_r,
           d.depth_p95_r);
    CHECK(d.mask_iou >= 0.98 && fabs(d.depth_bias_r) <= 0.43 && d.depth_p95_r <= 0.86,
          "spheres vs particles: IoU %g, bias %g r, p95 %g r (the same union: want >= 0.98, <= 0.43, <= 0.86)",
          d.mask_iou, d.depth_bias_r, d.depth_p95_r);
    /* smooth blends the spheres: smoother than the union, and not the union */
    CHECK(mm.interior_normal_mean_deg < 0.75 * mp.interior_normal_mean_deg,
          "smooth: interior normal error %g deg, not below 3/4 of the union's %g", mm.interior_normal_mean_deg,
          mp.interior_normal_mean_deg);
    fs_gbuffer_free(&ex);
    fs_gbuffer_free(&gp);
    fs_gbuffer_free(&gs);
    fs_gbuffer_free(&gm);
    fs_particles_free(&p);
}

/* An unknown rasteriser, and smooth's search under the radius: bad input, one line. */
static void refusals(void)
{
    float r = 0.025f, c[3] = {0, 0, 0};
    fs_particles p;
    ball(&p, r, c);
    fs_field f = {r, 0.8f * 8 * r * r * r, FS_KERNEL_CUBIC, 4 * r, 0.6f};
    fs_camera cam = {.eye = {0, 0, 2}, .target = {0, 0, 0}, .up = {0, 1, 0}, .fovy_deg = 30, .width = 8, .height = 8};
    fs_camera_fit_clip(&cam, p.bmin, p.bmax);
    fs_gbuffer g;
    fs_gbuffer_alloc(&g, 8, 8);
    const char *bad[][3] = {{"rasterizer=blobs", NULL, NULL}, {"rasterizer=smooth", "search=1", NULL}};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        int rc = fs_test_render("levelset", bad[i], &p, f, &cam, &g, NULL);
        const char *msg = fs_error_message();
        CHECK(rc == FS_ERR_INPUT && !strchr(msg, '\n') && strstr(msg, i ? "search" : "rasterizer"), "%s: rc %d (%s)",
              bad[i][0], rc, msg);
        printf("%s%s%s: %s\n", bad[i][0], bad[i][1] ? " " : "", bad[i][1] ? bad[i][1] : "", msg);
    }
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

int main(void)
{
    rasterizers();
    refusals();
    TEST_DONE();
}
