/* Neighbour grid (grid.h) against brute force on random and real particle
 * sets, its refusals, and the particle statistics built on it. */
#include "fs_error.h"
#include "fs_test.h"
#include "grid.h"
#include "kernels.h"
#include "particle_io.h"
#include "particle_stats.h"
#include "timing.h"
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 88172645463325252ull;
static double frand(void) /* xorshift64, [0, 1) */
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (rng >> 11) * 0x1.0p-53;
}

typedef struct visit { const fs_grid *g; size_t count; uint64_t sum; int bad; const float *x; float r2; } visit;
static void on_visit(void *user, uint32_t slot, float d2)
{
    visit *v = user;
    uint32_t orig;
    memcpy(&orig, &v->g->pos4[4 * (size_t)slot + 3], sizeof orig);
    if (orig != v->g->index[slot] || d2 > v->r2) v->bad++;
    v->count++;
    v->sum += (uint64_t)orig * 2654435761u + 1;
}

/* Structure of the grid, then every query against brute force. */
static void check_grid(const fs_particles *p, float cell, const float *radii, int nr, int nq, const char *what)
{
    fs_grid g;
    int rc = fs_grid_build(&g, p, cell);
    CHECK(rc == FS_OK, "%s: build: %s", what, fs_error_message());
    if (rc) return;
    CHECK(g.start[0] == 0 && g.start[g.ncells] == p->n, "%s: prefix sums", what);
    char *seen = calloc(p->n, 1);
    int bad = 0;
    for (size_t c = 0; c < g.ncells; c++) {
        if (g.start[c] > g.start[c + 1]) bad++;
        int i = (int)(c % g.dim[0]), j = (int)(c / g.dim[0] % g.dim[1]), k = (int)(c / g.dim[0] / g.dim[1]);
        for (uint32_t s = g.start[c]; s < g.start[c + 1]; s++) {
            uint32_t o = g.index[s];
            if (o >= p->n || seen[o]++) { bad++; continue; }
            const float *q = g.pos4 + 4 * (size_t)s;
            if (q[0] != p->x[o] || q[1] != p->y[o] || q[2] != p->z[o]) bad++;
            if (fs_grid_coord(&g, 0, q[0]) != i || fs_grid_coord(&g, 1, q[1]) != j || fs_grid_coord(&g, 2, q[2]) != k) bad++;
            if (s > g.start[c] && g.index[s - 1] > o) bad++; /* original order kept inside a cell */
        }
    }
    CHECK(bad == 0, "%s: %d structural errors", what, bad);
    free(seen);
    int mismatches = 0;
    size_t total = 0;
    for (int ri = 0; ri < nr; ri++)
        for (int q = 0; q < nq; q++) {
            float x[3];
            /* Half the queries at particles, half anywhere in the box grown by the radius. */
            if (q % 2) {
                size_t i = (size_t)(frand() * p->n);
                x[0] = p->x[i]; x[1] = p->y[i]; x[2] = p->z[i];
            } else {
                for (int a = 0; a < 3; a++)
                    x[a] = (float)(p->bmin[a] - 2 * radii[ri] + frand() * (p->bmax[a] - p->bmin[a] + 4 * radii[ri]));
            }
            visit v = {&g, 0, 0, 0, x, radii[ri] * radii[ri]};
            fs_grid_query(&g, x, radii[ri], on_visit, &v);
            size_t count = 0;
            uint64_t sum = 0;
            for (size_t i = 0; i < p->n; i++) {
                float dx = p->x[i] - x[0], dy = p->y[i] - x[1], dz = p->z[i] - x[2];
                if (dx * dx + dy * dy + dz * dz <= v.r2) { count++; sum += (uint64_t)i * 2654435761u + 1; }
            }
            if (count != v.count || sum != v.sum || v.bad) mismatches++;
            total += count;
        }
    printf("%s: %zu particles, %dx%dx%d cells, %d radii x %d queries, %zu neighbours found, %d mismatches\n", what,
           p->n, g.dim[0], g.dim[1], g.dim[2], nr, nq, total, mismatches);
    CHECK(mismatches == 0, "%s: %d queries differ from brute force", what, mismatches);
    CHECK(total > 0, "%s: queries found nothing", what);
    fs_grid_free(&g);
}

static int random_set(fs_particles *p, size_t n)
{
    if (fs_particles_alloc(p, n, 0)) return 1;
    for (size_t i = 0; i < n; i++) {
        /* A dense cluster plus sparse spray, so cells hold very different counts. */
        double s = i % 4 ? 0.3 : 2.0;
        p->x[i] = (float)(s * frand() - 0.4);
        p->y[i] = (float)(s * frand() + 1.0);
        p->z[i] = (float)(s * frand() - 3.0);
    }
    fs_particles_bounds(p);
    return 0;
}

static void real_file(const char *name, float nn_expect)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/splashsurf/%s", FS_TEST_DATA, name);
    fs_particles p;
    int rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "read %s: %s", path, fs_error_message());
    if (rc) return;
    fs_particles_bounds(&p);
    const float r = 0.025f, radii[] = {0.6f * 4 * r, 4 * r, 2.5f * 4 * r};
    check_grid(&p, 4 * r, radii, 3, 200, name);
    check_grid(&p, 1.3f * 4 * r, radii, 2, 100, name);
    if (nn_expect > 0) {
        fs_field f = {r, 8 * r * r * r, FS_KERNEL_CUBIC, 4 * r, 0.6f};
        fs_particle_stats st;
        rc = fs_particles_stats(&p, &f, &st);
        CHECK(rc == FS_OK, "stats %s: %s", name, fs_error_message());
        printf("%s: stats n %zu, NN median %.5f, density median %.4f (volume_scale 1)\n", name, st.n, st.nn_median,
               st.density_median);
        CHECK(st.n == p.n, "stats count");
        CHECK_NEAR(st.nn_median, nn_expect, 1e-4, "NN median");
        /* A 13x14x13 block on an exact 2r lattice: with H = 4r only the outermost
         * layer misses neighbours, so the median is the interior value ~1. */
        CHECK_NEAR(st.density_median, 1.0, 0.02, "cube density median");
    }
    fs_particles_free(&p);
}

/* Interior density of an exact lattice of spacing 2r with H = 4r and
 * volume_scale 1: the cubic spline sums to 1 (to float precision) there. */
static void lattice_density(void)
{
    const float r = 0.025f;
    const int m = 21;
    fs_particles p;
    if (fs_particles_alloc(&p, (size_t)m * m * m, 0)) { CHECK(0, "alloc"); return; }
    for (int k = 0, i = 0; k < m; k++)
        for (int j = 0; j < m; j++)
            for (int l = 0; l < m; l++, i++) { p.x[i] = 2 * r * l; p.y[i] = 2 * r * j; p.z[i] = 2 * r * k; }
    fs_field f = {r, 8 * r * r * r, FS_KERNEL_CUBIC, 4 * r, 0.6f};
    fs_particle_stats st;
    int rc = fs_particles_stats(&p, &f, &st);
    CHECK(rc == FS_OK, "lattice stats: %s", fs_error_message());
    printf("lattice %d^3: NN median %.6f, density median %.5f\n", m, st.nn_median, st.density_median);
    CHECK_NEAR(st.nn_median, 2 * r, 1e-6, "lattice NN");
    /* More than half the 21^3 points are 2+ spacings from the boundary, so the
     * median is the interior value. */
    CHECK_NEAR(st.density_median, 1.0, 0.02, "lattice interior density");
    f.volume *= 0.8f;
    rc = fs_particles_stats(&p, &f, &st);
    CHECK(rc == FS_OK && fabsf(st.density_median - 0.8f) < 0.02f, "density scales with V: %g", st.density_median);
    fs_particles_free(&p);
}

static void refusals(void)
{
    fs_particles p;
    if (random_set(&p, 1000)) { CHECK(0, "alloc"); return; }
    fs_grid g;
    int rc = fs_grid_build(&g, &p, 1e-4f);
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "too many, raise the cell size"), "tiny cell refused: %s",
          fs_error_message());
    CHECK(g.start == NULL && g.pos4 == NULL, "nothing left allocated after a refusal");
    rc = fs_grid_build(&g, &p, 0);
    CHECK(rc == FS_ERR_INPUT, "zero cell refused");
    p.y[17] = NAN;
    rc = fs_grid_build(&g, &p, 0.1f);
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "17"), "NaN position refused: %s", fs_error_message());
    fs_field f = {0.025f, 0, FS_KERNEL_CUBIC, 0.1f, 0.6f};
    fs_particle_stats st;
    CHECK(fs_particles_stats(&p, &f, &st) == FS_ERR_INPUT, "stats refuse V = 0");
    fs_particles_free(&p);
    /* A query far outside the grid visits nothing. */
    random_set(&p, 100);
    fs_grid_build(&g, &p, 0.2f);
    float far[3] = {100, 100, 100};
    visit v = {&g, 0, 0, 0, far, 1};
    fs_grid_query(&g, far, 1.0f, on_visit, &v);
    CHECK(v.count == 0, "far query found %zu", v.count);
    fs_grid_free(&g);
    fs_particles_free(&p);
}

int main(void)
{
    fs_particles p;
    if (random_set(&p, 20000)) return 1;
    const float radii[] = {0.02f, 0.05f, 0.12f, 0.31f};
    check_grid(&p, 0.05f, radii, 4, 150, "random 20k, cell 0.05");
    fs_particles_free(&p);
    if (random_set(&p, 3)) return 1; /* a handful of particles */
    check_grid(&p, 0.05f, radii, 4, 20, "random 3");
    fs_particles_free(&p);

    real_file("cube_2366_particles.vtk", 0.05f);
    real_file("dam_break_frame_23_24389_particles.vtk", 0);
    lattice_density();
    refusals();

    /* Build time for one million particles (reported, not asserted). */
    if (random_set(&p, 1000000) == 0) {
        fs_grid g;
        double best = 1e9;
        for (int rep = 0; rep < 3; rep++) {
            double t0 = fs_now_ms();
            int rc = fs_grid_build(&g, &p, 0.05f);
            double ms = fs_now_ms() - t0;
            CHECK(rc == FS_OK, "1M build");
            if (ms < best) best = ms;
            fs_grid_free(&g);
        }
        printf("grid build, 1M particles: %.1f ms (best of 3)\n", best);
        fs_particles_free(&p);
    }
    TEST_DONE();
}
