/* The reference with field=zhu_bridson (methods/reference/README.md,
 * "field=zhu_bridson") against the formula's zero found on its own (a double
 * sum of Zhu & Bridson's phi over every particle, marched at 0.01 r and
 * bisected, on every other pixel), on the rest lattice (spacing 2r, r = 0.025, R = 4r), seen from
 * straight above at 33x33:
 *  - a slab 16 x 16 x 6: every pixel's first hit within 1e-3 r of the formula's zero
 *    along the same ray (0.860-0.885 r above the top layer, not the ideal face's
 *    1 r), the centre pixel's thickness 10 r + 2 x 0.8850 r, its normal straight up;
 *  - a lattice ball (sites with |p| <= sqrt(108) r: a 3 x 3 patch on top): the same
 *    hits, the same coverage, and every hit within r of the outermost centres
 *    (|x| <= max |p| + r: the proven bound, since xbar lies in the particles' hull);
 *  - accel=on and off give the same image (the field has one march);
 *  - zb_radius=6 (R > H: its own grid): the slab's hits follow the formula with R = 6r.
 * Breaking the weights (k = (1 - s^2)^2) moves the slab's centre hit to 0.723 r and the
 * ball's hits by up to 0.59 r: 4 checks fail. */
#include "fs_error.h"
#include "fs_test.h"
#include "zb_lattice.h"
#include "kernels.h"
#include "test_render.h"
#include <math.h>
#include <stdlib.h>

#define R_ ZB_R
static double KR = 4 * R_; /* the kernel radius the independent sum uses */

/* The first zero along o + t d for t in [t0, t1] (0.01 r steps, then bisection); -1 when none. */
static double indep_hit(const fs_particles *p, const float o[3], const float d[3], double t0, double t1)
{
    double h = 0.01 * R_, prev = t0;
    for (double t = t0 + h; t <= t1; prev = t, t += h) {
        double x[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
        if (zb_indep_phi(p, x, KR) >= 0) continue;
        double lo = prev, hi = t;
        for (int i = 0; i < 40; i++) {
            double mid = 0.5 * (lo + hi), y[3] = {o[0] + mid * d[0], o[1] + mid * d[1], o[2] + mid * d[2]};
            if (zb_indep_phi(p, y, KR) < 0) hi = mid;
            else lo = mid;
        }
        return 0.5 * (lo + hi);
    }
    return -1;
}

static fs_field field(void)
{
    return (fs_field){(float)R_, (float)(8 * R_ * R_ * R_), FS_KERNEL_CUBIC, (float)(4 * R_), 0.6f};
}

static fs_camera above(float height)
{
    return (fs_camera){{0, 0, height}, {0, 0, 0}, {0, 1, 0}, 20.0f, 33, 33, 0.01f, 10.0f};
}

static int render(const fs_particles *p, const fs_camera *cam, const char *accel, fs_gbuffer *g)
{
    const char *sets[] = {"field=zhu_bridson", accel, KR > 4.5 * R_ ? "zb_radius=6" : NULL, NULL};
    int rc = fs_test_render("reference", sets, p, field(), cam, g, NULL);
    CHECK(rc == FS_OK, "reference field=zhu_bridson: %s", fs_error_message());
    return rc;
}

/* Every pixel's hit against the formula's zero along its ray (t in [ta, tb]);
 * returns the largest difference in r; *cov_diff counts pixels covered by one only. */
static double compare_hits(const fs_particles *p, const fs_camera *cam, const fs_gbuffer *g, double ta, double tb,
                           int *cov_diff, double *max_radius)
{
    float rt[3], up[3], fwd[3];
    fs_camera_basis(cam, rt, up, fwd);
    double worst = 0;
    *cov_diff = 0;
    *max_radius = 0;
    for (int py = 0; py < cam->height; py += 2)
        for (int px = 0; px < cam->width; px += 2) {
            float d[3];
            fs_camera_ray(cam, px + 0.5f, py + 0.5f, d);
            size_t id = (size_t)py * cam->width + px;
            double t = indep_hit(p, cam->eye, d, ta, tb), dot = d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2];
            int hit = g->coverage[id] > 0;
            if (hit != (t >= 0)) {
                if (getenv("FS_ZB_DEBUG"))
                    fprintf(stderr, "pixel %d %d: reference %s, formula %s (t %g r, depth %g r)\n", px, py,
                            hit ? "hit" : "miss", t >= 0 ? "hit" : "miss", t / R_, g->depth[id] / R_);
                (*cov_diff)++;
                continue;
            }
            if (!hit) continue;
            double tr = g->depth[id] / dot, x[3];
            worst = fmax(worst, fabs(tr - t) / R_);
            for (int a = 0; a < 3; a++) x[a] = cam->eye[a] + tr * d[a];
            *max_radius = fmax(*max_radius, sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
        }
    return worst;
}

static void slab(void)
{
    fs_particles p;
    zb_lattice(&p, zb_slab_site);
    fs_camera cam = above((float)(50 * R_));
    fs_gbuffer g = {0};
    if (render(&p, &cam, "accel=on", &g)) return;
    int cov;
    double rmax, worst = compare_hits(&p, &cam, &g, 48.5 * R_, 52 * R_, &cov, &rmax);
    size_t c = 16 * 33 + 16;
    double z = cam.eye[2] - g.depth[c];
    printf("slab: centre hit %.4f r above the top layer, thickness %.4f r; every pixel within %.2e r of the formula\n",
           z / R_, g.thickness[c] / R_, worst);
    CHECK(cov == 0, "slab: %d pixels differ in coverage", cov);
    CHECK(worst < 1e-3, "slab: hits %.4f r off the formula's zero", worst);
    CHECK(fabs(z / R_ - 0.8850) < 1e-3, "slab: centre hit %.4f r above the top layer, 0.8850 expected", z / R_);
    CHECK(fabs(g.thickness[c] / R_ - 11.770) < 2e-3, "slab: thickness %.4f r, 11.770 expected", g.thickness[c] / R_);
    CHECK(g.normal[3 * c + 2] > cosf(0.05f * (float)M_PI / 180),
          "slab: centre normal (%g %g %g) not towards the camera", g.normal[3 * c], g.normal[3 * c + 1],
          g.normal[3 * c + 2]);
    fs_gbuffer off = {0};
    if (!render(&p, &cam, "accel=off", &off)) {
        int same = 1;
        for (size_t i = 0; i < (size_t)33 * 33; i++)
            same &= off.depth[i] == g.depth[i] && off.coverage[i] == g.coverage[i];
        CHECK(same, "slab: accel=off differs from accel=on (zhu_bridson has one march)");
    }
    fs_gbuffer_free(&off);
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

static void ball(void)
{
    fs_particles p;
    zb_lattice(&p, zb_ball_site);
    double pmax = 0;
    for (size_t i = 0; i < p.n; i++) pmax = fmax(pmax, sqrt(p.x[i] * p.x[i] + p.y[i] * p.y[i] + p.z[i] * p.z[i]));
    fs_camera cam = above((float)(90 * R_));
    fs_gbuffer g = {0};
    if (render(&p, &cam, "accel=on", &g)) return;
    int cov;
    double rmax, worst = compare_hits(&p, &cam, &g, 78.5 * R_, 91 * R_, &cov, &rmax);
    size_t c = 16 * 33 + 16;
    double z = cam.eye[2] - g.depth[c];
    printf("ball (%zu particles, outermost centre %.3f r): top hit %.4f r above the top site, farthest hit %.4f r "
           "from the centre; every pixel within %.2e r of the formula, %d coverage differences\n",
           p.n, pmax / R_, z / R_ - 10, rmax / R_, worst, cov);
    CHECK(cov == 0, "ball: %d pixels differ in coverage", cov);
    CHECK(worst < 1e-3, "ball: hits %.4f r off the formula's zero", worst);
    CHECK(rmax <= pmax + R_ * 1.0001, "ball: a hit %.4f r from the centre, beyond the outermost centre + r (%.4f r)",
          rmax / R_, pmax / R_ + 1);
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

/* zb_radius=6 (R above the scene's H = 4r: the reference builds its own grid):
 * the slab's hits follow the formula with R = 6r, whose zero lies elsewhere. */
static void radius6(void)
{
    fs_particles p;
    zb_lattice(&p, zb_slab_site);
    fs_camera cam = above((float)(50 * R_));
    fs_gbuffer g = {0};
    KR = 6 * R_;
    if (!render(&p, &cam, "accel=on", &g)) {
        int cov;
        double rmax, worst = compare_hits(&p, &cam, &g, 48.5 * R_, 52 * R_, &cov, &rmax);
        double z = (cam.eye[2] - g.depth[16 * 33 + 16]) / R_;
        printf("slab, zb_radius=6: centre hit %.4f r above the top layer; every pixel within %.2e r of the formula\n",
               z, worst);
        CHECK(cov == 0 && worst < 1e-3, "zb_radius=6: %d coverage differences, hits %.4f r off", cov, worst);
        CHECK(fabs(z - 0.8850) > 0.01, "zb_radius=6: centre hit %.4f r, as with R = 4r", z);
    }
    KR = 4 * R_;
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

int main(void)
{
    slab();
    ball();
    radius6();
    TEST_DONE();
}
