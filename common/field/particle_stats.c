/* Particle statistics (particle_stats.h): median nearest-neighbour distance and
 * median normalised density phi at particle centres, so users can check r and
 * volume_scale against their data (docs/DESIGN.md, Units), and the radius
 * estimate for files that give none. Both look at a fixed-size sample of the
 * particles, drawn with a fixed seed: O(N) for the grid, then a constant cost,
 * and the same answer on every run. */
#include "particle_stats.h"
#include "fs_error.h"
#include "grid.h"
#include "kernels.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { KNN = 32 }; /* neighbours of the density estimate */

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* The q-quantile of v (reordered). */
static float quantile(float *v, size_t n, double q)
{
    qsort(v, n, sizeof *v, cmp_float);
    double at = q * (double)(n - 1);
    size_t i = (size_t)at;
    return i + 1 < n ? (float)(v[i] + (at - (double)i) * (v[i + 1] - v[i])) : v[n - 1];
}

/* m grid slots drawn without replacement with a fixed seed (all of them when
 * n <= m): a partial Fisher-Yates shuffle on a splitmix64 stream. */
static uint32_t *sample_slots(size_t n, size_t *m)
{
    if (*m > n) *m = n;
    uint32_t *all = malloc((n ? n : 1) * sizeof *all);
    if (!all) return NULL;
    for (size_t i = 0; i < n; i++) all[i] = (uint32_t)i;
    uint64_t s = 0x9e3779b97f4a7c15ull;
    for (size_t i = 0; i < *m && *m < n; i++) {
        uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        size_t j = i + (size_t)((z ^ (z >> 31)) % (n - i));
        uint32_t t = all[i];
        all[i] = all[j], all[j] = t;
    }
    return all;
}

/* A grid whose cells hold a few particles: the cell is the mean spacing the
 * bounding box implies (cap: 400 cells an axis, for far spray), and at least
 * min_cell. */
static int stats_grid(const fs_particles *p, float min_cell, fs_grid *g, float *ext)
{
    fs_particles box = *p;
    fs_particles_bounds(&box);
    double vol = 1;
    *ext = 0;
    for (int a = 0; a < 3; a++) {
        float e = box.bmax[a] - box.bmin[a];
        *ext = fmaxf(*ext, e);
        vol *= fmax(e, 1e-30);
    }
    float spacing = (float)cbrt(vol / (double)p->n);
    float cell = fmaxf(fmaxf(min_cell, spacing), *ext / 400.0f);
    if (!(cell > 0)) cell = 1; /* every particle at one point */
    return fs_grid_build(g, p, cell);
}

/* The K smallest squared distances to other particles, kept sorted. */
typedef struct knn_state {
    uint32_t self;
    int k;
    float d2[KNN];
} knn_state;
static void knn_visit(void *user, uint32_t slot, float d2)
{
    knn_state *s = user;
    if (slot == s->self || (s->k == KNN && d2 >= s->d2[KNN - 1])) return;
    int i = s->k < KNN ? s->k++ : KNN - 1;
    for (; i > 0 && s->d2[i - 1] > d2; i--) s->d2[i] = s->d2[i - 1];
    s->d2[i] = d2;
}

/* Grows the search from rad until k neighbours (or the whole box) are in. */
static void knn(const fs_grid *g, uint32_t slot, float rad, float diag, int want, knn_state *st)
{
    for (;; rad *= 2.0f) {
        st->self = slot, st->k = 0;
        fs_grid_query(g, g->pos4 + 4 * (size_t)slot, rad, knn_visit, st);
        /* the k found within rad are the true nearest only if the k-th lies within rad */
        if ((st->k >= want && st->d2[want - 1] <= rad * rad) || rad > diag) return;
    }
}

int fs_particles_estimate_radius(const fs_particles *p, float *r)
{
    *r = 0;
    if (p->n < 2 || !p->x) return fs_fail(FS_ERR_INPUT, "particles: a radius needs at least 2 particles to estimate");
    fs_grid g;
    float ext;
    int rc = stats_grid(p, 0, &g, &ext);
    if (rc) return rc;
    size_t m = FS_STATS_SAMPLE;
    uint32_t *pick = sample_slots(p->n, &m);
    float *vol = malloc(m * sizeof *vol);
    if (!pick || !vol) {
        free(pick), free(vol), fs_grid_free(&g);
        return fs_fail(FS_ERR_RUNTIME, "particles: out of memory for the radius estimate");
    }
    int want = p->n - 1 < KNN ? (int)(p->n - 1) : KNN;
    float diag = 2.0f * ext + 2.0f * g.cell;
    long nm = (long)m;
#pragma omp parallel for schedule(dynamic, 16)
    for (long s = 0; s < nm; s++) {
        knn_state st;
        knn(&g, pick[s], g.cell, diag, want, &st);
        double d = sqrt((double)st.d2[st.k - 1]);
        vol[s] = (float)(4.0 / 3.0 * M_PI * d * d * d / st.k); /* the volume each neighbour takes */
    }
    /* A particle near a free surface sees empty space in its ball and reads too
     * large a volume; in a splashing frame most particles may be near one. The
     * 10th percentile is the bulk's unless nine in ten are; at 32 neighbours the
     * bulk's own spread is a few percent, so it reads little low. */
    float v = quantile(vol, m, 0.10);
    *r = 0.5f * cbrtf(v);
    free(pick), free(vol), fs_grid_free(&g);
    if (!(*r > 0) || !isfinite(*r))
        return fs_fail(FS_ERR_INPUT, "particles: no spacing to estimate a radius from (all particles at one point?)");
    return FS_OK;
}

typedef struct phi_state {
    const fs_field *f;
    double sum;
} phi_state;
static void phi_visit(void *user, uint32_t slot, float d2)
{
    (void)slot;
    phi_state *s = user;
    s->sum += fs_kernel_w(s->f->kernel, sqrtf(d2), s->f->H);
}

int fs_particles_stats(const fs_particles *p, const fs_field *f, fs_particle_stats *out)
{
    if (p->n == 0 || !p->x) return fs_fail(FS_ERR_INPUT, "particles: no particles");
    if (!(f->H > 0) || !(f->volume > 0) || !isfinite(f->H) || !isfinite(f->volume))
        return fs_fail(FS_ERR_INPUT, "particles: support H %g and volume V %g must be positive", f->H, f->volume);
    fs_grid g;
    float ext;
    int rc = stats_grid(p, 0.25f * f->H, &g, &ext);
    if (rc) return rc;
    size_t m = FS_STATS_SAMPLE;
    uint32_t *pick = sample_slots(p->n, &m);
    float *nn = malloc(m * sizeof *nn), *phi = malloc(m * sizeof *phi);
    if (!pick || !nn || !phi) {
        free(pick), free(nn), free(phi), fs_grid_free(&g);
        return fs_fail(FS_ERR_RUNTIME, "particles: out of memory for statistics of %zu particles", p->n);
    }
    /* a lone particle (no neighbour within the whole box) gets INFINITY */
    float diag = 2.0f * ext + 2.0f * g.cell;
    long nm = (long)m;
#pragma omp parallel for schedule(dynamic, 16)
    for (long s = 0; s < nm; s++) {
        knn_state st;
        knn(&g, pick[s], g.cell, diag, 1, &st);
        nn[s] = st.k ? sqrtf(st.d2[0]) : INFINITY;
        phi_state ps = {f, 0.0};
        fs_grid_query(&g, g.pos4 + 4 * (size_t)pick[s], f->H, phi_visit, &ps);
        phi[s] = (float)(ps.sum * f->volume);
    }
    out->n = p->n;
    out->sampled = m;
    out->nn_median = quantile(nn, m, 0.5);
    out->density_median = quantile(phi, m, 0.5);
    free(pick), free(nn), free(phi), fs_grid_free(&g);
    return FS_OK;
}
