/* Neighbour grid (grid.h) against brute force on random and real particle
 * sets, its refusals, and the particle statistics built on it. */
#include "fs_error.h"
#include "fs_test.h"
#include "grid.h"
#include "kernels.h"
#include "particle_io.h"
#include "particle_stats.h"
#include "timing.h"
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng = 88172645463325252ull;
static double frand(void) /* xorshift64, [0, 1) */
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (rng >> 11) * 0x1.0p-53;
}

typedef struct visit {
    const fs_grid *g;
    size_t count;
    uint64_t sum;
    int bad;
    const float *x;
    float r2;
} visit;
static void on_visit(void *user, uint32_t slot, float d2)
{
    visit *v = user;
    uint32_t orig;
    memcpy(&orig, &v->g->pos4[4 * (size_t)slot + 3], sizeof orig);
    if (orig != v->g->index[slot] || d2 > v->r2) v->bad++;
    v->count++;
    v->sum += (uint64_t)orig * 2654435761u + 1;
}

/* Cell coordinates of cell slot c. */
static void slot_cell(const fs_grid *g, size_t c, int cc[3])
{
    const int32_t *k = g->bkey + 3 * (c / FS_GRID_B3);
    int l = (int)(c % FS_GRID_B3);
    cc[0] = k[0] * FS_GRID_B + l % FS_GRID_B;
    cc[1] = k[1] * FS_GRID_B + l / FS_GRID_B % FS_GRID_B;
    cc[2] = k[2] * FS_GRID_B + l / (FS_GRID_B * FS_GRID_B);
}

static int cell_occupied(const fs_grid *g, int i, int j, int k)
{
    uint32_t s0, s1;
    fs_grid_cell_run(g, i, j, k, &s0, &s1);
    return s1 > s0;
}

/* Every particle sits in the slot of its cell, once, in original order. */
static int check_slots(const fs_grid *g, const fs_particles *p)
{
    char *seen = calloc(p->n ? p->n : 1, 1);
    int bad = 0;
    for (size_t c = 0; c < g->ncells; c++) {
        if (g->start[c] > g->start[c + 1]) bad++;
        int cc[3];
        slot_cell(g, c, cc);
        if (fs_grid_slot(g, cc[0], cc[1], cc[2]) != c) bad++;
        for (uint32_t s = g->start[c]; s < g->start[c + 1]; s++) {
            uint32_t o = g->index[s];
            if (o >= p->n || seen[o]++) {
                bad++;
                continue;
            }
            const float *q = g->pos4 + 4 * (size_t)s;
            if (q[0] != p->x[o] || q[1] != p->y[o] || q[2] != p->z[o]) bad++;
            for (int a = 0; a < 3; a++)
                if (fs_grid_coord(g, a, q[a]) != cc[a]) bad++;
            if (s > g->start[c] && g->index[s - 1] > o) bad++; /* original order kept inside a cell */
        }
    }
    free(seen);
    return bad;
}

/* Stored blocks are exactly those with a cell next to an occupied cell, and
 * the near bits say which cells have a particle in their 27 neighbours. */
static int check_blocks(const fs_grid *g, const fs_particles *p)
{
    int bad = 0;
    for (size_t i = 0; i < p->n; i++) {
        int c[3] = {fs_grid_coord(g, 0, p->x[i]), fs_grid_coord(g, 1, p->y[i]), fs_grid_coord(g, 2, p->z[i])};
        for (int d = 0; d < 27; d++)
            if (!fs_grid_near_occupied(g, c[0] + d % 3 - 1, c[1] + d / 3 % 3 - 1, c[2] + d / 9 - 1)) bad++;
    }
    for (size_t c = 0; c < g->ncells; c++) {
        int cc[3], near = 0;
        slot_cell(g, c, cc);
        for (int d = 0; d < 27; d++)
            near |= cell_occupied(g, cc[0] + d % 3 - 1, cc[1] + d / 3 % 3 - 1, cc[2] + d / 9 - 1);
        if (near != fs_grid_near_occupied(g, cc[0], cc[1], cc[2])) bad++;
    }
    for (size_t b = 0; b < g->nblocks; b++) { /* no block without a near cell */
        uint32_t w0 = g->near[2 * b], w1 = g->near[2 * b + 1];
        if (!w0 && !w1) bad++;
        for (int a = 0; a < 3; a++)
            if (g->bkey[3 * b + a] * FS_GRID_B < g->lo[a] || g->bkey[3 * b + a] * FS_GRID_B + 3 > g->hi[a]) bad++;
    }
    size_t size = g->table_mask + 1, used = 0;
    for (size_t h = 0; h < size; h++) used += g->table[h] != FS_GRID_NONE;
    if ((size & (size - 1)) || used != g->nblocks || 2 * used > size) bad++;
    return bad;
}

/* Clusters: every particle counted once, largest first, bulk box inside the box. */
static int check_clusters(const fs_grid *g, const fs_particles *p)
{
    int bad = 0;
    size_t sum = 0;
    for (int c = 0; c < g->nclusters; c++) {
        sum += g->clusters[c].n;
        if (c && g->clusters[c].n > g->clusters[c - 1].n) bad++;
    }
    if (sum != p->n) bad++;
    for (int a = 0; a < 3 && p->n; a++)
        if (g->bulk_lo[a] < p->bmin[a] || g->bulk_hi[a] > p->bmax[a] || g->bulk_lo[a] > g->bulk_hi[a]) bad++;
    return bad;
}

/* Structure of the grid, then every query against brute force. */
/* fs_grid_box_runs over 3x3x3 boxes around every stored cell holds exactly the
 * slots of the cells one by one, in order. */
static int check_box_runs(const fs_grid *g)
{
    int bad = 0;
    for (size_t c = 0; c < g->ncells; c += 7) {
        int cc[3], lo[3], hi[3];
        slot_cell(g, c, cc);
        for (int a = 0; a < 3; a++) {
            lo[a] = cc[a] - 1;
            hi[a] = cc[a] + 1;
        }
        uint32_t runs[FS_GRID_MAX_RUNS][2], s0, s1, got = 0, want = 0;
        int nr = fs_grid_box_runs(g, lo, hi, runs);
        for (int r = 0; r < nr; r++) {
            bad += runs[r][1] <= runs[r][0];
            got += runs[r][1] - runs[r][0];
        }
        for (int k = lo[2]; k <= hi[2]; k++)
            for (int j = lo[1]; j <= hi[1]; j++)
                for (int i = lo[0]; i <= hi[0]; i++) {
                    fs_grid_cell_run(g, i, j, k, &s0, &s1);
                    want += s1 - s0;
                    for (uint32_t s = s0; s < s1; s++) { /* each slot in exactly one run */
                        int in = 0;
                        for (int r = 0; r < nr; r++) in += s >= runs[r][0] && s < runs[r][1];
                        bad += in != 1;
                    }
                }
        bad += got != want;
    }
    return bad;
}

static void check_grid(const fs_particles *p, float cell, const float *radii, int nr, int nq, const char *what)
{
    fs_grid g;
    int rc = fs_grid_build(&g, p, cell);
    CHECK(rc == FS_OK, "%s: build: %s", what, fs_error_message());
    if (rc) return;
    CHECK(g.start[0] == 0 && g.start[g.ncells] == p->n, "%s: prefix sums", what);
    CHECK(g.ncells == g.nblocks * FS_GRID_B3, "%s: ncells", what);
    int bad = check_slots(&g, p), bad_blocks = check_blocks(&g, p), bad_clusters = check_clusters(&g, p);
    CHECK(bad == 0, "%s: %d structural errors", what, bad);
    CHECK(bad_blocks == 0, "%s: %d errors in the blocks, near bits or table", what, bad_blocks);
    CHECK(bad_clusters == 0, "%s: %d errors in the clusters", what, bad_clusters);
    int bad_runs = check_box_runs(&g);
    CHECK(bad_runs == 0, "%s: %d errors in the box runs", what, bad_runs);
    int mismatches = 0;
    size_t total = 0;
    for (int ri = 0; ri < nr; ri++)
        for (int q = 0; q < nq; q++) {
            float x[3];
            /* Half the queries at particles, half anywhere in the box grown by the radius. */
            if (q % 2) {
                size_t i = (size_t)(frand() * p->n);
                x[0] = p->x[i];
                x[1] = p->y[i];
                x[2] = p->z[i];
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
                if (dx * dx + dy * dy + dz * dz <= v.r2) {
                    count++;
                    sum += (uint64_t)i * 2654435761u + 1;
                }
            }
            if (count != v.count || sum != v.sum || v.bad) mismatches++;
            total += count;
        }
    printf("%s: %zu particles, %zu blocks, %d clusters, %d radii x %d queries, %zu neighbours found, %d mismatches\n",
           what, p->n, g.nblocks, g.nclusters, nr, nq, total, mismatches);
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
    if (fs_particles_alloc(&p, (size_t)m * m * m, 0)) {
        CHECK(0, "alloc");
        return;
    }
    for (int k = 0, i = 0; k < m; k++)
        for (int j = 0; j < m; j++)
            for (int l = 0; l < m; l++, i++) {
                p.x[i] = 2 * r * l;
                p.y[i] = 2 * r * j;
                p.z[i] = 2 * r * k;
            }
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
    if (random_set(&p, 1000)) {
        CHECK(0, "alloc");
        return;
    }
    fs_grid g;
    /* A tiny cell over a 2 m box: memory follows the particles (at most 8
     * blocks each), where the dense grid refused 10^13 cells. */
    int rc = fs_grid_build(&g, &p, 1e-4f);
    CHECK(rc == FS_OK && g.nblocks <= 8 * p.n, "tiny cell: %s, %zu blocks", fs_error_message(), g.nblocks);
    fs_grid_free(&g);
    /* A particle so far away that cell coordinates would overflow. */
    float keep = p.x[42];
    p.x[42] = 1e9f;
    rc = fs_grid_build(&g, &p, 0.05f);
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "particle 42 "), "overflowing stray refused: %s",
          fs_error_message());
    CHECK(g.start == NULL && g.pos4 == NULL && g.table == NULL, "nothing left allocated after a refusal");
    p.x[42] = keep;
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

/* A bulk with spray next to it and three strays thousands of metres away:
 * memory stays small, the strays make their own clusters outside the bulk, the
 * near spray stays in it, and queries around everything are still exact. */
static void strays(void)
{
    fs_particles p;
    if (random_set(&p, 5000)) {
        CHECK(0, "alloc");
        return;
    }
    fs_particles clean = p;
    float lo[3], hi[3];
    memcpy(lo, p.bmin, sizeof lo);
    memcpy(hi, p.bmax, sizeof hi);
    fs_particles q;
    if (fs_particles_alloc(&q, p.n + 5, 0)) {
        CHECK(0, "alloc");
        fs_particles_free(&p);
        return;
    }
    memcpy(q.x, p.x, p.n * sizeof *q.x);
    memcpy(q.y, p.y, p.n * sizeof *q.y);
    memcpy(q.z, p.z, p.n * sizeof *q.z);
    /* Two spray particles 0.6 m above the 2 m bulk (separate blocks, within its extent). */
    for (int s = 0; s < 2; s++) {
        q.x[p.n + s] = 0.5f + 0.1f * s;
        q.y[p.n + s] = hi[1] + 0.6f;
        q.z[p.n + s] = -2.0f;
    }
    const float far[3][3] = {{2000, 0, 0}, {-3000, 1.5f, -2}, {100, 4000, -4000}};
    for (int s = 0; s < 3; s++) {
        q.x[p.n + 2 + s] = far[s][0];
        q.y[p.n + 2 + s] = far[s][1];
        q.z[p.n + 2 + s] = far[s][2];
    }
    fs_particles_bounds(&q);
    fs_grid g, gc;
    int rc = fs_grid_build(&g, &q, 0.05f);
    CHECK(rc == FS_OK, "stray build: %s", fs_error_message());
    rc = fs_grid_build(&gc, &clean, 0.05f);
    CHECK(rc == FS_OK, "clean build: %s", fs_error_message());
    if (rc == FS_OK) {
        printf("strays: %zu blocks (%zu without), %d clusters, bulk y %g..%g\n", g.nblocks, gc.nblocks, g.nclusters,
               g.bulk_lo[1], g.bulk_hi[1]);
        CHECK(g.nblocks <= gc.nblocks + 5 * 8, "strays cost at most 8 blocks each: %zu vs %zu", g.nblocks, gc.nblocks);
        for (int s = 0; s < 3; s++) {
            int c[3] = {fs_grid_coord(&g, 0, far[s][0]), fs_grid_coord(&g, 1, far[s][1]),
                        fs_grid_coord(&g, 2, far[s][2])};
            int found = 0;
            for (int k = 0; k < g.nclusters; k++) {
                const fs_grid_cluster *cl = &g.clusters[k];
                found |= cl->n == 1 && cl->lo[0] <= c[0] && c[0] <= cl->hi[0] && cl->lo[1] <= c[1] &&
                    c[1] <= cl->hi[1] && cl->lo[2] <= c[2] && c[2] <= cl->hi[2];
            }
            CHECK(found, "stray %d is a cluster of its own", s);
        }
        for (int a = 0; a < 3; a++) {
            float want_hi = a == 1 ? hi[1] + 0.6f : hi[a];
            CHECK(g.bulk_lo[a] == lo[a] && g.bulk_hi[a] == want_hi, "bulk box axis %d: %g..%g, want %g..%g", a,
                  g.bulk_lo[a], g.bulk_hi[a], lo[a], want_hi);
            CHECK(gc.bulk_lo[a] == lo[a] && gc.bulk_hi[a] == hi[a], "clean bulk box = bounding box, axis %d", a);
        }
        fs_grid_free(&gc);
        fs_grid_free(&g);
        const float radii[] = {0.05f, 0.12f};
        check_grid(&q, 0.05f, radii, 2, 100, "bulk + strays");
        /* Queries at the strays themselves. */
        rc = fs_grid_build(&g, &q, 0.05f);
        for (int s = 0; s < 3 && rc == FS_OK; s++) {
            visit v = {&g, 0, 0, 0, far[s], 0.01f};
            fs_grid_query(&g, far[s], 0.1f, on_visit, &v);
            CHECK(v.count == 1 && !v.bad, "query at stray %d found %zu", s, v.count);
        }
        if (rc == FS_OK) fs_grid_free(&g);
    }
    fs_particles_free(&q);
    fs_particles_free(&p);
}

/* The sorted order and every array are the same on 1 and 2 threads. */
static void thread_independence(void)
{
    fs_particles p;
    if (random_set(&p, 300000)) {
        CHECK(0, "alloc");
        return;
    }
    fs_grid g[2];
    for (int t = 0; t < 2; t++) {
        omp_set_num_threads(t + 1);
        CHECK(fs_grid_build(&g[t], &p, 0.05f) == FS_OK, "build on %d threads", t + 1);
    }
    omp_set_num_threads(omp_get_num_procs());
    CHECK(g[0].nblocks == g[1].nblocks && !memcmp(g[0].bkey, g[1].bkey, 3 * g[0].nblocks * sizeof *g[0].bkey) &&
              !memcmp(g[0].start, g[1].start, (g[0].ncells + 1) * sizeof *g[0].start) &&
              !memcmp(g[0].near, g[1].near, (g[0].ncells / 32 + 1) * sizeof *g[0].near) &&
              !memcmp(g[0].index, g[1].index, p.n * sizeof *g[0].index),
          "grids built on 1 and 2 threads differ");
    fs_grid_free(&g[0]);
    fs_grid_free(&g[1]);
    fs_particles_free(&p);
}

/* The radius the spacing implies, on every bundled frame (all made at r = 0.025):
 * within 10% on the lattices (a block, and a dam break's first frame), within 20%
 * on developed flows (splashsurf's dam breaks after impact, fluidsurf's own
 * splash frame). */
static void radius_estimates(void)
{
    static const struct {
        const char *file;
        double tol;
    } frames[] = {
        {"splashsurf/cube_2366_particles.vtk", 0.10},
        {"splashsurf/double_dam_break_frame_01_4732_particles.vtk", 0.10},
        {"splashsurf/dam_break_frame_23_24389_particles.vtk", 0.20},
        {"splashsurf/double_dam_break_frame_26_4732_particles.vtk", 0.20},
        {"splashsurf/dam_break_frame_9_6859_particles.bgeo", 0.20},
        {"splash/dam_break_splash_100k.ply", 0.20},
    };
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", FS_TEST_DATA, frames[i].file);
        fs_particles p;
        float r = 0, r2 = 0;
        CHECK(fs_particles_read(&p, path, NULL) == FS_OK, "read %s: %s", path, fs_error_message());
        CHECK(fs_particles_estimate_radius(&p, &r) == FS_OK, "estimate %s: %s", path, fs_error_message());
        CHECK(fs_particles_estimate_radius(&p, &r2) == FS_OK && r2 == r, "estimate %s: not repeatable", path);
        printf("radius estimate %s: %.5f (%.3f of 0.025)\n", frames[i].file, r, r / 0.025);
        CHECK(fabs(r / 0.025 - 1) <= frames[i].tol, "%s: estimated r %.5f, more than %.0f%% off 0.025", frames[i].file,
              r, 100 * frames[i].tol);
        fs_particles_free(&p);
    }
    fs_particles one = {0};
    CHECK(fs_particles_alloc(&one, 1, 0) == FS_OK, "alloc");
    float r;
    CHECK(fs_particles_estimate_radius(&one, &r) == FS_ERR_INPUT, "one particle: no estimate");
    fs_particles_free(&one);
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
    radius_estimates();
    refusals();
    strays();
    thread_independence();

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
