/* Density grids (density_grid.h): (a) the exact grid against a brute-force sum
 * over all particles; (b) iwasaki2006's slice splatting against the exact grid
 * on the real dam break (cubic and Wyvill kernels, other up axes, 1 vs 16
 * clusters); (c) VDB write + read round trip (tests/density_grid.cmake then
 * runs vdb_print on the file); (d) bad input. Trilinear sampling first. */
#include "density_splat.h"
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "particle_io.h"
#include "timing.h"
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const float R_ = 0.025f;

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static double frand(void) /* xorshift64, [0, 1) */
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (rng >> 11) * 0x1.0p-53;
}

static fs_field field(fs_kernel k) { return (fs_field){R_, 0.8f * 8 * R_ * R_ * R_, k, 4 * R_, 0.6f}; }

static int read_set(fs_particles *p, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/splashsurf/%s", FS_TEST_DATA, name);
    int rc = fs_particles_read(p, path, NULL);
    CHECK(rc == FS_OK, "read %s: %s", path, fs_error_message());
    if (!rc) fs_particles_bounds(p);
    return rc;
}

/* Trilinear sampling reproduces a linear function exactly and is 0 outside. */
static void sampling(void)
{
    const float lo[3] = {-1, 0, 2}, hi[3] = {1, 0.5f, 3};
    fs_density_grid g;
    CHECK(fs_density_grid_init(&g, lo, hi, 0.1f, 21) == FS_OK, "init: %s", fs_error_message());
    CHECK(g.dim[0] == 21 && g.dim[1] == 8 && g.dim[2] == 12, "dims %d %d %d", g.dim[0], g.dim[1], g.dim[2]);
    for (int a = 0; a < 3; a++) {
        CHECK(g.origin[a] <= lo[a] - 0.1f + 1e-6f, "origin %d", a);
        CHECK(g.origin[a] + g.spacing * (g.dim[a] - 1) >= hi[a] + 0.1f - 1e-5f, "far end %d", a);
    }
    for (int k = 0; k < g.dim[2]; k++)
        for (int j = 0; j < g.dim[1]; j++)
            for (int i = 0; i < g.dim[0]; i++) {
                float x = g.origin[0] + g.spacing * i, y = g.origin[1] + g.spacing * j, z = g.origin[2] + g.spacing * k;
                g.data[fs_density_grid_index(&g, i, j, k)] = 1 + 2 * x - 3 * y + 0.5f * z;
            }
    double emax = 0;
    for (int q = 0; q < 500; q++) {
        float x[3];
        for (int a = 0; a < 3; a++) x[a] = g.origin[a] + (float)frand() * g.spacing * (g.dim[a] - 1);
        emax = fmax(emax, fabs(fs_density_grid_sample(&g, x) - (1 + 2 * x[0] - 3 * x[1] + 0.5 * x[2])));
    }
    CHECK(emax < 1e-4, "trilinear error %g on a linear function", emax);
    const float out1[3] = {g.origin[0] - 0.01f, 0.2f, 2.5f}, out2[3] = {0, 0.2f, 99};
    CHECK(fs_density_grid_sample(&g, out1) == 0 && fs_density_grid_sample(&g, out2) == 0, "outside is 0");
    fs_density_grid_free(&g);
}

/* (a) Exact grid through the neighbour grid vs a sum over all particles. */
static void exact_vs_brute(const fs_particles *p, float cell_mult, const char *what)
{
    fs_field f = field(FS_KERNEL_CUBIC);
    fs_grid ng;
    int rc = fs_grid_build(&ng, p, cell_mult * f.H);
    CHECK(rc == FS_OK, "%s: grid: %s", what, fs_error_message());
    if (rc) return;
    fs_density_grid g;
    CHECK(fs_density_grid_init(&g, p->bmin, p->bmax, f.H, 40) == FS_OK, "%s: init: %s", what, fs_error_message());
    CHECK(fs_density_grid_exact(&g, p, &ng, &f) == FS_OK, "%s: exact: %s", what, fs_error_message());
    double emax = 0, vmax = 0;
    int nonzero = 0;
    for (int q = 0; q < 400; q++) {
        int i = (int)(frand() * g.dim[0]), j = (int)(frand() * g.dim[1]), k = (int)(frand() * g.dim[2]);
        double x = g.origin[0] + g.spacing * i, y = g.origin[1] + g.spacing * j, z = g.origin[2] + g.spacing * k;
        double sum = 0;
        for (size_t s = 0; s < p->n; s++) {
            double dx = p->x[s] - x, dy = p->y[s] - y, dz = p->z[s] - z;
            sum += fs_kernel_w(f.kernel, (float)sqrt(dx * dx + dy * dy + dz * dz), f.H);
        }
        sum *= f.volume;
        float v = g.data[fs_density_grid_index(&g, i, j, k)];
        nonzero += sum > 0;
        vmax = fmax(vmax, sum);
        emax = fmax(emax, fabs(v - sum));
    }
    printf("(a) %s, cell %.2f H: exact vs brute force at 400 points (%d non-zero, max %.3f): max |diff| %.2e\n", what,
           cell_mult, nonzero, vmax, emax);
    CHECK(nonzero > 40, "%s: only %d of the sampled points are non-zero", what, nonzero);
    CHECK(emax < 2e-6, "%s: exact grid differs from brute force by %g", what, emax);
    fs_density_grid_free(&g);
    fs_grid_free(&ng);
}

/* A dense lump plus sparse spray far from it (cells of very different counts). */
static void spray_set(fs_particles *p)
{
    fs_particles_alloc(p, 3000, 0);
    for (size_t i = 0; i < p->n; i++) {
        double s = i % 5 ? 0.4 : 1.5;
        p->x[i] = (float)(s * frand() - 0.2);
        p->y[i] = (float)(s * frand() + 0.5);
        p->z[i] = (float)(s * frand() - 1.0);
    }
    fs_particles_bounds(p);
}

/* (b) slice splatting vs the exact grid on the 24k dam break. */
static void splat_vs_exact(fs_slice_splat *ss, const fs_particles *p, fs_kernel kern, int up, int res,
                           fs_density_grid *splat_out)
{
    fs_field f = field(kern);
    fs_grid ng;
    fs_grid_build(&ng, p, f.H);
    fs_density_grid ex, sp;
    CHECK(fs_density_grid_init(&ex, p->bmin, p->bmax, f.H, res) == FS_OK, "init: %s", fs_error_message());
    CHECK(fs_density_grid_init(&sp, p->bmin, p->bmax, f.H, res) == FS_OK, "init: %s", fs_error_message());
    double t0 = fs_now_ms();
    CHECK(fs_density_grid_exact(&ex, p, &ng, &f) == FS_OK, "exact: %s", fs_error_message());
    double t1 = fs_now_ms();
    int rc = fs_slice_splat_run(ss, &sp, p, &f, up, 16);
    CHECK(rc == FS_OK, "splat: %s", fs_error_message());
    double t2 = fs_now_ms();
    double l2 = fs_density_grid_rel_l2(&sp, &ex), emax = 0, vmax = 0;
    for (size_t i = 0; i < fs_density_grid_points(&ex); i++) {
        emax = fmax(emax, fabs(sp.data[i] - ex.data[i]));
        vmax = fmax(vmax, ex.data[i]);
    }
    printf(
        "(b) %s up %d, %dx%dx%d: rel L2 %.2e, max |diff| %.2e (max phi %.3f), %zu disks; exact %.0f ms, splat %.0f ms\n",
        fs_kernel_name(kern), up, ex.dim[0], ex.dim[1], ex.dim[2], l2, emax, vmax, fs_slice_splat_disks(ss), t1 - t0,
        t2 - t1);
    CHECK(vmax > 1.0, "exact grid max %g: not the dam break interior", vmax);
    CHECK(l2 < 1e-3, "%s up %d: slice splat vs exact rel L2 %g (bar 1e-3)", fs_kernel_name(kern), up, l2);
    CHECK(emax < 1e-3, "%s up %d: max |diff| %g", fs_kernel_name(kern), up, emax);
    fs_density_grid_free(&ex);
    fs_grid_free(&ng);
    if (splat_out) *splat_out = sp;
    else fs_density_grid_free(&sp);
}

static void clusters_agree(fs_slice_splat *ss, const fs_particles *p)
{
    fs_field f = field(FS_KERNEL_CUBIC);
    fs_density_grid a, b;
    fs_density_grid_init(&a, p->bmin, p->bmax, f.H, 48);
    fs_density_grid_init(&b, p->bmin, p->bmax, f.H, 48);
    CHECK(fs_slice_splat_run(ss, &a, p, &f, 1, 1) == FS_OK, "1 cluster: %s", fs_error_message());
    size_t d1 = fs_slice_splat_disks(ss);
    CHECK(fs_slice_splat_run(ss, &b, p, &f, 1, 16) == FS_OK, "16 clusters: %s", fs_error_message());
    size_t d16 = fs_slice_splat_disks(ss);
    double emax = 0;
    for (size_t i = 0; i < fs_density_grid_points(&a); i++) emax = fmax(emax, fabs(a.data[i] - b.data[i]));
    size_t passes = (size_t)(a.dim[1] + 3) / 4;
    printf("(b) 1 vs 16 clusters: max |diff| %.2e, disks %zu vs %zu (all particles in all %zu passes: %zu)\n", emax, d1,
           d16, passes, p->n * passes);
    CHECK(emax < 1e-5, "1 and 16 clusters differ by %g", emax);
    CHECK(d1 == p->n * passes, "1 cluster drew %zu disks, expected %zu", d1, p->n * passes);
    CHECK(d16 < d1 / 2, "16 clusters drew %zu disks, 1 cluster %zu: the clustering culls little", d16, d1);
    fs_density_grid_free(&a);
    fs_density_grid_free(&b);
}

#if FS_WITH_OPENVDB
/* (c) VDB round trip; the file stays in FS_TEST_OUT for the vdb_print test. */
static void vdb_roundtrip(const fs_density_grid *g)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/density_grid.vdb", FS_TEST_OUT);
    CHECK(fs_density_grid_write_vdb(g, path, "density") == FS_OK, "write: %s", fs_error_message());
    fs_density_grid r;
    int rc = fs_density_grid_read_vdb(&r, path, "density");
    CHECK(rc == FS_OK, "read: %s", fs_error_message());
    if (rc) return;
    CHECK(fabsf(r.spacing - g->spacing) <= 1e-6f * g->spacing, "spacing %g vs %g", r.spacing, g->spacing);
    int off[3], bad = 0, placed = 1;
    for (int a = 0; a < 3; a++) {
        float t = (r.origin[a] - g->origin[a]) / g->spacing;
        off[a] = (int)lroundf(t);
        int ok = fabsf(t - off[a]) < 1e-3f && off[a] >= 0 && off[a] + r.dim[a] <= g->dim[a];
        CHECK(ok, "origin axis %d: %g", a, t);
        placed &= ok;
    }
    if (!placed) {
        fs_density_grid_free(&r);
        return;
    }
    size_t active = 0;
    for (int k = 0; k < g->dim[2]; k++)
        for (int j = 0; j < g->dim[1]; j++)
            for (int i = 0; i < g->dim[0]; i++) {
                float v = g->data[fs_density_grid_index(g, i, j, k)];
                int ri = i - off[0], rj = j - off[1], rk = k - off[2];
                int in = ri >= 0 && rj >= 0 && rk >= 0 && ri < r.dim[0] && rj < r.dim[1] && rk < r.dim[2];
                float w = in ? r.data[fs_density_grid_index(&r, ri, rj, rk)] : 0.0f;
                active += v > 0;
                if (w != (v > 0 ? v : 0.0f)) bad++;
            }
    printf("(c) VDB round trip: %zu active of %zu points, read box %dx%dx%d, %d mismatches\n", active,
           fs_density_grid_points(g), r.dim[0], r.dim[1], r.dim[2], bad);
    CHECK(bad == 0, "%d values differ after the round trip", bad);
    fs_density_grid_free(&r);
    CHECK(fs_density_grid_read_vdb(&r, path, "nope") == FS_ERR_INPUT && strstr(fs_error_message(), "nope"),
          "missing grid name: %s", fs_error_message());
    CHECK(r.data == NULL, "failed read leaves an empty grid");
    fs_density_grid_free(&r);
}
#endif

/* (d) refusals. */
static void bad_input(const fs_density_grid *g)
{
    const char *path = "/nonexistent-fluidsurf-dir/grid.vdb";
    int rc = fs_density_grid_write_vdb(g, path, "density");
    CHECK(rc != FS_OK && strstr(fs_error_message(), path), "write into a missing folder: rc %d, '%s'", rc,
          fs_error_message());
#if !FS_WITH_OPENVDB
    CHECK_REFUSED(rc, fs_error_message(), path, "FS_WITH_OPENVDB");
#endif
    struct stat st;
    CHECK(stat(path, &st) != 0, "something was left at %s", path);
    /* a folder that exists: a failing write leaves no temporary file behind */
    char dir[1024], target[1100];
    snprintf(dir, sizeof dir, "%s/density_bad", FS_TEST_OUT);
    mkdir(dir, 0755);
    snprintf(target, sizeof target, "%s/x.vdb", dir);
    CHECK(fs_density_grid_write_vdb(g, target, "") == FS_ERR_INPUT, "empty grid name accepted");
    CHECK(rmdir(dir) == 0, "%s is not empty after failed writes", dir);

    fs_density_grid h;
    const float lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    CHECK(fs_density_grid_init(&h, lo, hi, 0, 1000000) == FS_ERR_INPUT && h.data == NULL, "absurd resolution: %s",
          fs_error_message());
    printf("(d) absurd resolution: %s\n", fs_error_message());
    CHECK(fs_density_grid_init(&h, lo, hi, 0, 1) == FS_ERR_INPUT, "resolution 1 accepted");
    const float nan3[3] = {0, NAN, 0};
    CHECK(fs_density_grid_init(&h, nan3, hi, 0, 10) == FS_ERR_INPUT, "NaN box accepted");
    CHECK(fs_density_grid_init(&h, lo, lo, 0, 10) == FS_ERR_INPUT, "point box without padding accepted");
    CHECK(fs_density_grid_read_vdb(&h, "/nonexistent-fluidsurf-dir/in.vdb", "density") == FS_ERR_INPUT &&
              strstr(fs_error_message(), "/nonexistent-fluidsurf-dir/in.vdb"),
          "reading a missing file: %s", fs_error_message());
}

int main(void)
{
    sampling();
    fs_particles cube, spray, dam;
    if (FS_WITH_VTK && read_set(&cube, "cube_2366_particles.vtk") == FS_OK) {
        exact_vs_brute(&cube, 1.0f, "cube");
        fs_particles_free(&cube);
    }
    spray_set(&spray);
    exact_vs_brute(&spray, 1.0f, "spray");
    exact_vs_brute(&spray, 0.45f, "spray"); /* cells smaller than H: more cells per query */
    fs_particles_free(&spray);

    /* The lean build reads no VTK: it takes the dam break's BGEO frame instead. */
    if (read_set(&dam,
                 FS_WITH_VTK ? "dam_break_frame_23_24389_particles.vtk" : "dam_break_frame_9_6859_particles.bgeo"))
        TEST_DONE();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) {
        fs_particles_free(&dam);
        TEST_DONE();
    }
    fs_slice_splat *ss = fs_slice_splat_create();
    CHECK(ss != NULL, "create: %s", fs_error_message());
    if (ss) {
        fs_density_grid cubic;
        splat_vs_exact(ss, &dam, FS_KERNEL_CUBIC, 1, 64, &cubic);
        splat_vs_exact(ss, &dam, FS_KERNEL_WYVILL, 1, 64, NULL);
        splat_vs_exact(ss, &dam, FS_KERNEL_CUBIC, 2, 64, NULL);
        splat_vs_exact(ss, &dam, FS_KERNEL_CUBIC, 0, 48, NULL);
        clusters_agree(ss, &dam);
        fs_density_grid bad;
        fs_density_grid_init(&bad, dam.bmin, dam.bmax, 0.1f, 16);
        fs_field f = field(FS_KERNEL_CUBIC);
        CHECK(fs_slice_splat_run(ss, &bad, &dam, &f, 3, 16) == FS_ERR_INPUT, "up axis 3 accepted");
        CHECK(fs_slice_splat_run(ss, &bad, &dam, &f, 1, 0) == FS_ERR_INPUT, "0 clusters accepted");
        fs_density_grid_free(&bad);
#if FS_WITH_OPENVDB
        vdb_roundtrip(&cubic);
#else
        char vdb[1024];
        snprintf(vdb, sizeof vdb, "%s/density_grid_lean.vdb", FS_TEST_OUT);
        int vrc = fs_density_grid_write_vdb(&cubic, vdb, "density");
        CHECK_REFUSED(vrc, fs_error_message(), vdb, "FS_WITH_OPENVDB");
        fs_density_grid back;
        vrc = fs_density_grid_read_vdb(&back, vdb, "density");
        CHECK(vrc == FS_ERR_INPUT && back.data == NULL, "VDB read without OpenVDB: rc %d", vrc);
#endif
        bad_input(&cubic);
        fs_density_grid_free(&cubic);
    }
    fs_slice_splat_destroy(ss);
    fs_gl_context_destroy(&ctx);
    fs_particles_free(&dam);
    TEST_DONE();
}
