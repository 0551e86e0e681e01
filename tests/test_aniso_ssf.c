/* aniso_ssf on the OSMesa context: (a) the GLSL anisotropy equals the C one;
 * (b) ellipsoid sprite depth equals an exact CPU ray-ellipsoid intersection;
 * (c) every filter runs, changes the depth and keeps the coverage; (d) normals
 * from depth on a plane; (e) the anisotropic reference renders; (f) the
 * narrow-range filter keeps both sides of a depth discontinuity apart. */
#include "aniso_ssf/aniso_gl.h"
#include "eigen3.h"
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "method.h"
#include "builtin_methods.h"
#include "test_render.h"
#include "metrics.h"
#include "synthetic.h"
#include <stdlib.h>
#include <string.h>

static const float R_ = 0.025f;

static fs_field field(void) { return (fs_field){R_, 8 * R_ * R_ * R_, FS_KERNEL_CUBIC, 4 * R_, 0.6f}; }

/* A flat square patch of n x n particles in the plane z = 0 (spacing 2r). */
static void patch(fs_particles *p, int n)
{
    fs_particles_alloc(p, (size_t)n * n, 0);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            p->x[j * n + i] = (i - (n - 1) / 2.0f) * 2 * R_;
            p->y[j * n + i] = (j - (n - 1) / 2.0f) * 2 * R_;
        }
    fs_particles_bounds(p);
}

static void c_vs_glsl(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.synth.shape = FS_SYNTH_BOX;
    s.synth.size[0] = s.synth.size[1] = s.synth.size[2] = 10;
    s.synth.seed = 9;
    fs_particles p;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_OK, "box: %s", fs_error_message());
    fs_grid g;
    fs_grid_build(&g, &p, 4 * R_);
    fs_aniso_params ap;
    fs_aniso_defaults(&ap, FS_KERNEL_CUBIC, R_);
    ap.lambda = 0.5f;
    fs_gl_grid gg = {0};
    aniso_gl an;
    CHECK(aniso_gl_init(&an) == FS_OK, "init: %s", fs_error_message());
    CHECK(fs_gl_grid_upload(&gg, &g) == FS_OK && aniso_gl_run(&an, &gg, p.n, &ap) == FS_OK, "run: %s",
          fs_error_message());
    double emax = 0, cmax = 0;
    int nbad = 0;
    for (size_t sl = 0; sl < p.n; sl++) {
        float cg[3], Ag[9], cc[3], Ac[9];
        int ng;
        aniso_gl_read(&an, sl, cg, Ag, &ng);
        uint32_t i = g.index[sl];
        float x[3] = {p.x[i], p.y[i], p.z[i]};
        int nc = fs_aniso_point(&g, x, &ap, cc, Ac);
        nbad += nc != ng;
        for (int k = 0; k < 9; k++) emax = fmax(emax, fabs(Ag[k] - Ac[k]));
        for (int k = 0; k < 3; k++) cmax = fmax(cmax, fabs(cg[k] - cc[k]) / R_);
    }
    printf("(a) C vs GLSL on %zu particles: max |A| diff %.2e, max centre diff %.2e r, count mismatches %d\n", p.n,
           emax, cmax, nbad);
    CHECK(emax < 2e-3, "stretch matrices differ by %g", emax);
    CHECK(cmax < 1e-4, "centres differ by %g r", cmax);
    CHECK(nbad <= (int)p.n / 100, "%d neighbour counts differ", nbad);
    aniso_gl_free(&an);
    fs_gl_grid_free(&gg);
    fs_grid_free(&g);
    fs_particles_free(&p);
}

/* Nearest hit distance of the ray o + t d with the ellipsoid c + A (r u), |u| <= 1, or INFINITY. */
static double ray_ellipsoid(const float o[3], const float d[3], const float c[3], const float A[9])
{
    double a[9], ev[3], V[9], inv[9];
    for (int k = 0; k < 9; k++) a[k] = A[k];
    fs_eigen3_sym(a, ev, V);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            inv[3 * i + j] = 0;
            for (int k = 0; k < 3; k++) inv[3 * i + j] += V[3 * k + i] * V[3 * k + j] / (ev[k] * R_);
        }
    double q[3], pp[3];
    for (int i = 0; i < 3; i++) {
        q[i] = pp[i] = 0;
        for (int j = 0; j < 3; j++) {
            q[i] += inv[3 * i + j] * d[j];
            pp[i] += inv[3 * i + j] * (o[j] - c[j]);
        }
    }
    double qq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2], qp = q[0] * pp[0] + q[1] * pp[1] + q[2] * pp[2];
    double h = qp * qp - qq * (pp[0] * pp[0] + pp[1] * pp[1] + pp[2] * pp[2] - 1);
    return h < 0 ? INFINITY : (-qp - sqrt(h)) / qq;
}

static void sprite_depth(void)
{
    fs_particles p;
    patch(&p, 9);
    fs_camera cam = {{0.1f, -0.15f, 0.6f}, {0, 0, 0}, {0, 1, 0}, 40.0f, 96, 96, 0.05f, 5.0f};
    fs_gbuffer gb;
    fs_gbuffer_alloc(&gb, 96, 96);
    const char *sets[] = {"filter=none", "thickness=off", NULL};
    CHECK(fs_test_render("aniso_ssf", sets, &p, field(), &cam, &gb, NULL) == FS_OK, "render: %s", fs_error_message());
    fs_grid g;
    fs_grid_build(&g, &p, 4 * R_);
    fs_aniso_params ap;
    fs_aniso_defaults(&ap, FS_KERNEL_CUBIC, R_);
    float *c = malloc(p.n * 3 * sizeof *c), *A = malloc(p.n * 9 * sizeof *A);
    fs_aniso_compute(&p, &g, &ap, c, A, NULL);
    double s0 = 0;
    for (size_t i = 0; i < p.n; i++) s0 += A[9 * i + 8];
    float rt[3], up[3], fwd[3];
    fs_camera_basis(&cam, rt, up, fwd);
    int both = 0, only = 0;
    double emax = 0;
    for (int y = 0; y < 96; y++)
        for (int x = 0; x < 96; x++) {
            float d[3];
            fs_camera_ray(&cam, x + 0.5f, y + 0.5f, d);
            double t = INFINITY;
            for (size_t i = 0; i < p.n; i++) t = fmin(t, ray_ellipsoid(cam.eye, d, c + 3 * i, A + 9 * i));
            size_t id = (size_t)y * 96 + x;
            int cpu = isfinite(t), gpu = gb.coverage[id] > 0;
            if (cpu != gpu) {
                only++;
                continue;
            }
            if (!cpu) continue;
            both++;
            emax = fmax(emax, fabs(t * (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]) - gb.depth[id]) / R_);
        }
    printf("(b) ellipsoid sprites vs CPU ray-ellipsoid: %d px both, %d px one only, max depth diff %.2e r, "
           "mean z-stretch %.3f\n",
           both, only, emax, s0 / p.n);
    CHECK(s0 / p.n < 0.7, "the patch's particles are not flattened (mean z stretch %g)", s0 / p.n);
    CHECK(both > 1000, "only %d pixels", both);
    CHECK(only <= both / 100, "%d pixels covered by one side only", only);
    CHECK(emax < 0.01, "depth differs by %g r", emax);
    free(c);
    free(A);
    fs_grid_free(&g);
    fs_gbuffer_free(&gb);
    fs_particles_free(&p);
}

static void filters(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.synth.shape = FS_SYNTH_SLAB;
    s.synth.size[0] = s.synth.size[2] = 24;
    s.synth.seed = 4;
    fs_particles p;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_OK, "slab: %s", fs_error_message());
    fs_camera cam = {{0, 30 * R_, 40 * R_}, {0, 6 * R_, 0}, {0, 1, 0}, 40.0f, 128, 128, 0.05f, 10.0f};
    const char *names[] = {"none", "gaussian", "bilateral", "curvature", "narrow"};
    fs_gbuffer gb[5];
    for (int k = 0; k < 5; k++) {
        char set[64];
        snprintf(set, sizeof set, "filter=%s", names[k]);
        const char *sets[] = {set, NULL};
        fs_stages st = {0};
        fs_gbuffer_alloc(&gb[k], 128, 128);
        CHECK(fs_test_render("aniso_ssf", sets, &p, field(), &cam, &gb[k], &st) == FS_OK, "%s: %s", names[k],
              fs_error_message());
        const char *want[] = {"anisotropy", "splat", "filter", "normals", "thickness", "readback", NULL};
        const char *missing = fs_test_missing_stage(&st, want);
        CHECK(!missing, "%s: stage %s not reported", names[k], missing);
    }
    for (int k = 1; k < 5; k++) {
        int cov_diff = 0, bad = 0, n = 0;
        double change = 0;
        for (int i = 0; i < 128 * 128; i++) {
            cov_diff += gb[k].coverage[i] != gb[0].coverage[i];
            if (!gb[k].coverage[i]) continue;
            bad += !(isfinite(gb[k].depth[i]) && gb[k].depth[i] > 0);
            if (gb[0].coverage[i]) {
                change += fabs(gb[k].depth[i] - gb[0].depth[i]);
                n++;
            }
        }
        change = n ? change / n / R_ : 0;
        printf("(c) %s: mean |depth change| %.3f r, coverage changed at %d px, bad depths %d\n", names[k], change,
               cov_diff, bad);
        CHECK(change > 0.01, "%s does not change the depth (%g r)", names[k], change);
        CHECK(cov_diff == 0, "%s changes the coverage at %d px (holes)", names[k], cov_diff);
        CHECK(bad == 0, "%s leaves %d non-finite or non-positive depths", names[k], bad);
    }
    /* Narrow-range on a continuous sloped surface, away from the silhouettes: it
     * must not move the depth towards the camera (dropping the far samples did, by
     * 1.6 r) and, like the Gaussian, only fill the dips between the sprites
     * (narrow smooths a little more: its extra 2D pass). */
    unsigned char *in = malloc(128 * 128);
    fs_interior_mask(&gb[0], &gb[0], 12, in);
    double dg = 0, dn = 0;
    int m = 0;
    for (int i = 0; i < 128 * 128; i++) {
        if (!in[i]) continue;
        dg += gb[1].depth[i] - gb[0].depth[i];
        dn += gb[4].depth[i] - gb[0].depth[i];
        m++;
    }
    dg /= m * R_;
    dn /= m * R_;
    printf("(c) sloped slab, %d px >= 12 px from a silhouette: mean depth change gaussian %+.3f r, narrow %+.3f r\n", m,
           dg, dn);
    CHECK(m > 1000, "only %d pixels away from the silhouettes", m);
    CHECK(dn - dg > -0.3 && dn - dg < 0.4, "narrow-range moves a sloped surface by %+.3f r against the Gaussian",
          dn - dg);
    free(in);
    for (int k = 0; k < 5; k++) fs_gbuffer_free(&gb[k]);
    fs_particles_free(&p);
}

/* Mean signed depth change (in r, positive = away from the camera) over the
 * pixels of one depth class (near: z < split) with a pixel of the other class
 * within 4 px. */
static double edge_change(const fs_gbuffer *a, const fs_gbuffer *b, float split, int near, int *count)
{
    double sum = 0;
    int n = 0;
    for (int y = 4; y < 124; y++)
        for (int x = 4; x < 124; x++) {
            int i = y * 128 + x;
            if (!a->coverage[i] || (a->depth[i] < split) != near) continue;
            int other = 0;
            for (int dy = -4; dy <= 4 && !other; dy++)
                for (int dx = -4; dx <= 4; dx++) {
                    int j = i + dy * 128 + dx;
                    if (a->coverage[j] && (a->depth[j] < split) != near) {
                        other = 1;
                        break;
                    }
                }
            if (!other) continue;
            sum += b->depth[i] - a->depth[i];
            n++;
        }
    *count = n;
    return n ? sum / n / R_ : 0;
}

/* (f) The narrow-range filter at a depth discontinuity: a strip of particles
 * 20 r in front of a plane. The far plane beside the strip's silhouette is not
 * pulled forward (the near samples are left out) and the strip's rim moves
 * back by at most mu = r plus the smoothing of the sphere bumps (about 0.5 r,
 * the far samples are clamped to z + mu); the Gaussian, with no range, smears
 * one surface into the other, which shows the scene tests something. */
static void narrow_discontinuity(void)
{
    fs_particles far, p;
    patch(&far, 30);
    fs_particles_alloc(&p, far.n + 8 * 30, 0);
    memcpy(p.x, far.x, far.n * sizeof *p.x);
    memcpy(p.y, far.y, far.n * sizeof *p.y);
    for (int j = 0; j < 30; j++)
        for (int i = 0; i < 8; i++) {
            size_t k = far.n + (size_t)j * 8 + i;
            p.x[k] = (i - 5) * 2 * R_;
            p.y[k] = (j - 14.5f) * 2 * R_;
            p.z[k] = 20 * R_;
        }
    fs_particles_bounds(&p);
    fs_camera cam = {{0, 0, 3.0f}, {0, 0, 0}, {0, 1, 0}, 40.0f, 128, 128, 0.05f, 10.0f};
    const char *names[] = {"none", "gaussian", "narrow"};
    fs_gbuffer gb[3];
    for (int k = 0; k < 3; k++) {
        char set[64];
        snprintf(set, sizeof set, "filter=%s", names[k]);
        const char *sets[] = {set, "anisotropy=off", NULL};
        fs_gbuffer_alloc(&gb[k], 128, 128);
        CHECK(fs_test_render("aniso_ssf", sets, &p, field(), &cam, &gb[k], NULL) == FS_OK, "%s: %s", names[k],
              fs_error_message());
    }
    float split = 3.0f - 10 * R_;
    int nf, nn;
    double g_far = edge_change(&gb[0], &gb[1], split, 0, &nf), g_near = edge_change(&gb[0], &gb[1], split, 1, &nn);
    double n_far = edge_change(&gb[0], &gb[2], split, 0, &nf), n_near = edge_change(&gb[0], &gb[2], split, 1, &nn);
    printf("(f) depth step of 20 r: mean depth change beside the step, far side (%d px) gaussian %+.2f r, narrow "
           "%+.2f r; near side (%d px) gaussian %+.2f r, narrow %+.2f r\n",
           nf, g_far, n_far, nn, g_near, n_near);
    CHECK(nf > 100 && nn > 100, "too few pixels beside the step (%d far, %d near)", nf, nn);
    CHECK(g_far < -2.0 && g_near > 2.0,
          "the Gaussian does not smear the step (%+.2f r, %+.2f r): the scene tests nothing", g_far, g_near);
    CHECK(n_far > -0.25, "narrow-range pulls the far surface towards the near one by %.2f r", -n_far);
    CHECK(n_near > -0.25 && n_near < 1.5, "narrow-range moves the near rim by %+.2f r (mu = r)", n_near);
    for (int k = 0; k < 3; k++) fs_gbuffer_free(&gb[k]);
    fs_particles_free(&p);
    fs_particles_free(&far);
}

static void plane_normals(void)
{
    fs_particles p;
    patch(&p, 17);
    fs_camera cam = {{0.1f, -0.2f, 0.8f}, {0, 0, 0}, {0, 1, 0}, 40.0f, 128, 128, 0.05f, 5.0f};
    fs_gbuffer gb;
    fs_gbuffer_alloc(&gb, 128, 128);
    const char *sets[] = {"filter=none", "kappa=50", NULL};
    CHECK(fs_test_render("aniso_ssf", sets, &p, field(), &cam, &gb, NULL) == FS_OK, "render: %s", fs_error_message());
    float nz[3] = {0, 0, 1}, nv[3];
    fs_camera_to_view_dir(&cam, nz, nv);
    unsigned char *in = malloc(128 * 128);
    fs_interior_mask(&gb, &gb, 3, in);
    double sum = 0;
    int n = 0;
    for (int i = 0; i < 128 * 128; i++) {
        if (!in[i]) continue;
        const float *m = gb.normal + 3 * i;
        sum += acos(fmin(1.0, fabs(m[0] * nv[0] + m[1] * nv[1] + m[2] * nv[2]))) * 180 / FS_PI;
        n++;
    }
    printf("(d) normals from depth on a plane of flat ellipsoids: mean %.3f deg over %d interior px\n", sum / n, n);
    CHECK(n > 2000, "only %d interior pixels", n);
    CHECK(sum / n < 1.5, "mean normal error %g deg on a plane", sum / n);
    free(in);
    fs_gbuffer_free(&gb);
    fs_particles_free(&p);
}

static void aniso_reference(void)
{
    fs_scene s;
    fs_scene_defaults(&s);
    s.synth.shape = FS_SYNTH_BOX;
    s.synth.size[0] = s.synth.size[1] = s.synth.size[2] = 10;
    s.synth.seed = 2;
    fs_particles p;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_OK, "box: %s", fs_error_message());
    fs_camera cam = {{0.5f, 0.6f, 0.7f}, {0, 5 * R_, 0}, {0, 1, 0}, 40.0f, 64, 64, 0.05f, 10.0f};
    fs_gbuffer iso, ani;
    fs_gbuffer_alloc(&iso, 64, 64);
    fs_gbuffer_alloc(&ani, 64, 64);
    const char *sets[] = {"field=anisotropic", NULL};
    CHECK(fs_test_render("reference", NULL, &p, field(), &cam, &iso, NULL) == FS_OK, "iso: %s", fs_error_message());
    CHECK(fs_test_render("reference", sets, &p, field(), &cam, &ani, NULL) == FS_OK, "aniso: %s", fs_error_message());
    fs_metrics mt;
    fs_metrics_compute(&ani, NULL, &iso, NULL, R_, &mt);
    printf("(e) anisotropic vs isotropic reference: IoU %.4f, depth bias %.3f r, normal mean %.2f deg, %zu px\n",
           mt.mask_iou, mt.depth_bias_r, mt.normal_mean_deg, mt.n_both);
    CHECK(mt.n_both > 500, "anisotropic reference covers %zu px", mt.n_both);
    CHECK(mt.mask_iou > 0.85, "IoU %g against the isotropic surface", mt.mask_iou);
    CHECK(fabs(mt.depth_bias_r) > 0.02 || mt.normal_mean_deg > 0.5, "the anisotropic field changes nothing");
    fs_gbuffer_free(&iso);
    fs_gbuffer_free(&ani);
    fs_particles_free(&p);
}

int main(void)
{
    fs_methods_register_builtin();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    c_vs_glsl();
    sprite_depth();
    filters();
    narrow_discontinuity();
    plane_normals();
    aniso_reference();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
