/* SPH simulator (sph.h): CPU and GPU paths agree over a few steps; a pool at
 * rest keeps rho0 and its depth; a short dam break keeps every particle in the
 * box without the safety clamp; adaptive steps stay within the CFL/viscosity
 * bound and fixed steps that break it are counted; spouts emit coloured
 * particles; bad parameters are refused. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "particles.h"
#include "sph.h"
#include "timing.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static fs_sph *make(const char *scene, size_t n, fs_sph_params *p, int gpu)
{
    fs_sph *s = NULL;
    int rc = fs_sph_create(&s, scene, n, p, gpu);
    CHECK(rc == FS_OK, "create %s (%s): %s", scene, gpu ? "gpu" : "cpu", fs_error_message());
    return s;
}

/* Same scene, same fixed steps on both paths: positions within float noise. */
static void cpu_vs_gpu(const char *scene, size_t n, int steps, const char *renderer)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *a = make(scene, n, &p, 0), *b = make(scene, n, &p, 1);
    if (!a || !b) {
        fs_sph_destroy(a);
        fs_sph_destroy(b);
        return;
    }
    float dt = fs_sph_dt_bound(a);
    double ta = 0, tb = 0;
    for (int i = 0; i < steps; i++) {
        double t0 = fs_now_ms();
        CHECK(fs_sph_step(a, dt) == FS_OK, "cpu step: %s", fs_error_message());
        double t1 = fs_now_ms();
        CHECK(fs_sph_step(b, dt) == FS_OK, "gpu step: %s", fs_error_message());
        ta += t1 - t0;
        tb += fs_now_ms() - t1;
    }
    fs_particles pa, pb;
    CHECK(fs_sph_get(a, &pa) == FS_OK && fs_sph_get(b, &pb) == FS_OK, "get");
    CHECK(pa.n == pb.n && pa.n == fs_sph_count(a), "counts %zu %zu", pa.n, pb.n);
    double dx = 0, dv = 0, moved = 0, vmax = 0;
    fs_sph *init = make(scene, n, &p, 0);
    fs_particles p0;
    fs_sph_get(init, &p0);
    for (size_t i = 0; i < pa.n && i < pb.n && i < p0.n; i++) {
        dx = fmax(dx, fmax(fabs(pa.x[i] - pb.x[i]), fmax(fabs(pa.y[i] - pb.y[i]), fabs(pa.z[i] - pb.z[i]))));
        dv = fmax(dv, fmax(fabs(pa.vx[i] - pb.vx[i]), fmax(fabs(pa.vy[i] - pb.vy[i]), fabs(pa.vz[i] - pb.vz[i]))));
        moved = fmax(moved, fabs(pa.y[i] - p0.y[i]));
    }
    for (size_t i = 0; i < pa.n; i++) vmax = fmax(vmax, fmax(fabs(pa.vx[i]), fmax(fabs(pa.vy[i]), fabs(pa.vz[i]))));
    printf("%s cpu vs gpu (%s), %zu particles, %d steps of %.2e s: max |dx| %.3g m (moved up to %.3g m), "
           "max |dv| %.3g m/s (of %.3g); %.1f ms/step cpu, %.1f ms/step gpu path\n",
           scene, renderer, pa.n, steps, dt, dx, moved, dv, vmax, ta / steps, tb / steps);
    CHECK(moved > 1e-4, "%s: the particles moved (%g)", scene, moved);
    CHECK(dx < 1e-5, "%s: positions differ by %g m", scene, dx);
    CHECK(dv < 1e-4 * vmax + 1e-5, "%s: velocities differ by %g m/s", scene, dv);
    if (pa.phase && pb.phase) CHECK(!memcmp(pa.phase, pb.phase, pa.n * sizeof *pa.phase), "phases");
    fs_particles_free(&pa);
    fs_particles_free(&pb);
    fs_particles_free(&p0);
    fs_sph_destroy(init);
    fs_sph_destroy(a);
    fs_sph_destroy(b);
}

/* A pool at rest: after the initial settling the density stays near rho0 and
 * the depth matches the volume. */
static void pool_at_rest(void)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *s = make("pool", 1000, &p, 0);
    if (!s) return;
    for (int f = 0; f < 18; f++) CHECK(fs_sph_advance(s, 1.0 / 60) == FS_OK, "advance: %s", fs_error_message());
    fs_sph_measure m;
    CHECK(fs_sph_measure_state(s, &m) == FS_OK, "measure");
    const fs_sph_stats *st = fs_sph_get_stats(s);
    printf("pool at rest, %zu particles, t = %.2f s: density error %.4f (|interior| %.4f), depth %.4f vs %.4f, "
           "kinetic %.2g, clamps %ld\n",
           fs_sph_count(s), st->t, m.density_err, m.density_abs_err, m.depth, m.depth_expected, m.kinetic, st->clamps);
    CHECK(m.density_err < 0.02 && m.density_abs_err < 0.02, "density error %g / %g", m.density_err, m.density_abs_err);
    CHECK(fabs(m.depth / m.depth_expected - 1) < 0.05, "depth %g vs %g", m.depth, m.depth_expected);
    CHECK(m.outside == 0 && st->clamps == 0, "outside %zu clamps %ld", m.outside, st->clamps);
    fs_sph_destroy(s);
}

/* A short dam break: nothing outside, no clamp used, every step within the bound. */
static void dam_break_short(void)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *s = make("dam_break", 1000, &p, 0);
    if (!s) return;
    float lo[3], hi[3];
    fs_sph_box(s, lo, hi);
    float bound0 = fs_sph_dt_bound(s); /* the largest: nothing moves yet */
    fs_sph_measure m0, m;
    CHECK(fs_sph_measure_state(s, &m0) == FS_OK, "measure");
    for (int f = 0; f < 24; f++) CHECK(fs_sph_advance(s, 1.0 / 60) == FS_OK, "advance: %s", fs_error_message());
    const fs_sph_stats *st = fs_sph_get_stats(s);
    fs_sph_measure_state(s, &m);
    /* The depth is the mean surface height over the floor: the water's volume
     * over the floor area while the column stands and while it collapses. */
    printf("dam break depth: %.4f at t = 0, %.4f at 0.4 s, volume / floor area %.4f\n", m0.depth, m.depth,
           m.depth_expected);
    CHECK(fabs(m0.depth / m0.depth_expected - 1) < 0.01, "depth at t = 0: %g vs %g", m0.depth, m0.depth_expected);
    CHECK(fabs(m.depth / m.depth_expected - 1) < 0.02, "depth at 0.4 s: %g vs %g", m.depth, m.depth_expected);
    printf("dam break, %zu particles, box %.2f x %.2f x %.2f, t = %.2f s: %ld steps, dt %.2e..%.2e, smallest bound "
           "%.2e, v_max %.2f m/s, clamps %ld, outside %zu, violations %ld\n",
           fs_sph_count(s), hi[0], hi[1], hi[2], st->t, st->steps, st->dt_min, st->dt_max, st->bound_min, st->v_max,
           st->clamps, m.outside, st->violations);
    CHECK(fabs(st->t - 0.4) < 1e-4, "time %g", st->t);
    CHECK(m.outside == 0, "%zu particles outside", m.outside);
    CHECK(st->clamps == 0, "%ld safety clamps", st->clamps);
    CHECK(st->violations == 0 && st->dt_max <= bound0, "%ld steps beyond the bound, dt_max %g > %g", st->violations,
          st->dt_max, bound0);
    CHECK(st->v_max > 1.0f, "the water moved (v_max %g)", st->v_max);
    fs_sph_destroy(s);
}

/* Fixed steps: a step beyond the bound is counted; one within is not. */
static void fixed_steps(void)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    p.fixed_dt = 0.01f;
    fs_sph *s = make("dam_break", 500, &p, 0);
    if (!s) return;
    int rc = fs_sph_advance(s, 0.01);
    const fs_sph_stats *st = fs_sph_get_stats(s);
    CHECK(st->steps == 1 && st->violations == 1, "0.01 s step: %ld steps, %ld violations (rc %d)", st->steps,
          st->violations, rc);
    fs_sph_destroy(s);
    p.fixed_dt = 1e-4f;
    s = make("dam_break", 500, &p, 0);
    if (!s) return;
    CHECK(fs_sph_advance(s, 0.001) == FS_OK, "advance");
    st = fs_sph_get_stats(s);
    CHECK(st->steps == 10 && st->violations == 0, "1e-4 s steps: %ld steps, %ld violations", st->steps, st->violations);
    fs_sph_destroy(s);
}

static void spouts(void)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *s = make("spouts", 2000, &p, 0);
    if (!s) return;
    size_t n0 = fs_sph_count(s);
    for (int f = 0; f < 6; f++) CHECK(fs_sph_advance(s, 1.0 / 60) == FS_OK, "advance: %s", fs_error_message());
    fs_particles q;
    CHECK(fs_sph_get(s, &q) == FS_OK, "get");
    int seen[8] = {0};
    for (size_t i = 0; q.phase && i < q.n; i++) seen[q.phase[i] & 7]++;
    printf("spouts: %zu -> %zu particles, per colour id %d %d %d %d %d\n", n0, q.n, seen[0], seen[1], seen[2], seen[3],
           seen[4]);
    CHECK(q.n > n0 && q.color && q.phase, "emitted with colours");
    CHECK(seen[1] && seen[1] == seen[2] && seen[2] == seen[3] && seen[3] == seen[4], "four spouts alike");
    fs_particles_free(&q);
    fs_sph_destroy(s);
}

static void bad_input(void)
{
    fs_sph_params p;
    fs_sph *s = NULL;
    fs_sph_params_default(&p);
    CHECK(fs_sph_create(&s, "nope", 0, &p, 0) == FS_ERR_INPUT && strstr(fs_error_message(), "nope"), "unknown scene");
    p.r = -1;
    CHECK(fs_sph_create(&s, "dam_break", 0, &p, 0) == FS_ERR_INPUT, "negative radius");
    fs_sph_params_default(&p);
    p.cfl = 2;
    CHECK(fs_sph_create(&s, "dam_break", 0, &p, 0) == FS_ERR_INPUT, "cfl");
    fs_sph_params_default(&p);
    CHECK(fs_sph_create(&s, "dam_break", 10, &p, 0) == FS_ERR_INPUT, "too few particles");
    CHECK(s == NULL, "nothing made");
}

/* The container moved 2 cm (fs_sph_move_box) over 6 frames: the GPU grid follows the box, the paths still agree. */
static void moved_box(void)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *a = make("pool", 500, &p, 0), *b = make("pool", 500, &p, 1);
    if (!a || !b) {
        fs_sph_destroy(a);
        fs_sph_destroy(b);
        return;
    }
    const float d[3] = {0.02f / 6, 0, 0};
    for (int f = 0; f < 6; f++) {
        CHECK(fs_sph_move_box(a, d, 1.0 / 60) == FS_OK, "move cpu: %s", fs_error_message());
        CHECK(fs_sph_move_box(b, d, 1.0 / 60) == FS_OK, "move gpu: %s", fs_error_message());
    }
    fs_particles pa, pb;
    CHECK(fs_sph_get(a, &pa) == FS_OK && fs_sph_get(b, &pb) == FS_OK, "get");
    double dx = 0;
    for (size_t i = 0; i < pa.n && i < pb.n; i++)
        dx = fmax(dx, fmax(fabs(pa.x[i] - pb.x[i]), fmax(fabs(pa.y[i] - pb.y[i]), fabs(pa.z[i] - pb.z[i]))));
    float lo[3], hi[3];
    fs_sph_box(a, lo, hi);
    printf("moved box (x + %.3f m): cpu vs gpu max |dx| %.3g m, clamps %ld / %ld\n", lo[0], dx,
           fs_sph_get_stats(a)->clamps, fs_sph_get_stats(b)->clamps);
    CHECK(fabsf(lo[0] - 0.02f) < 1e-5f, "box moved to %g", lo[0]);
    CHECK(dx < 1e-4, "moved box: positions differ by %g m", dx);
    fs_particles_free(&pa);
    fs_particles_free(&pb);
    fs_sph_destroy(a);
    fs_sph_destroy(b);
}

int main(void)
{
    bad_input();
    fixed_steps();
    pool_at_rest();
    dam_break_short();
    spouts();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    cpu_vs_gpu("dam_break", 1000, 20, ctx.renderer);
    cpu_vs_gpu("spouts", 1500, 40, ctx.renderer);
    moved_box();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
