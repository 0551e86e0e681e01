/* Particle statistics (particles.h): count, median nearest-neighbour distance
 * and median normalised density phi at the particle centres, so users can
 * check r and volume_scale against their data (docs/DESIGN.md, Units). */
#include "particle_stats.h"
#include "fs_error.h"
#include "grid.h"
#include "kernels.h"
#include <math.h>
#include <stdlib.h>

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Median of v (reordered); the mean of the two middle values for even n. */
static float median(float *v, size_t n)
{
    qsort(v, n, sizeof *v, cmp_float);
    return 0.5f * (v[(n - 1) / 2] + v[n / 2]);
}

typedef struct nn_state { uint32_t self; float best2; } nn_state;
static void nn_visit(void *user, uint32_t slot, float d2)
{
    nn_state *s = user;
    if (slot != s->self && d2 < s->best2) s->best2 = d2;
}

typedef struct phi_state { const fs_field *f; double sum; } phi_state;
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
    /* The cell is at least H (one ring of cells holds every density neighbour)
     * and large enough that a scene with far-flung spray stays within the cell cap. */
    fs_particles box = *p;
    fs_particles_bounds(&box);
    float ext = 0;
    for (int a = 0; a < 3; a++) ext = fmaxf(ext, box.bmax[a] - box.bmin[a]);
    float cell = fmaxf(f->H, ext / 400.0f);
    fs_grid g;
    int rc = fs_grid_build(&g, p, cell);
    if (rc) return rc;
    float *nn = malloc(p->n * sizeof *nn), *phi = malloc(p->n * sizeof *phi);
    if (!nn || !phi) {
        free(nn); free(phi); fs_grid_free(&g);
        return fs_fail(FS_ERR_RUNTIME, "particles: out of memory for statistics of %zu particles", p->n);
    }
    /* Nearest neighbour: search one cell first, then double the radius; a lone
     * particle (no neighbour within the whole box) gets INFINITY. */
    float diag = 2.0f * ext + 2.0f * cell;
    long n = (long)p->n;
#pragma omp parallel for schedule(dynamic, 256)
    for (long s = 0; s < n; s++) {
        const float *x = g.pos4 + 4 * s;
        nn_state st = {(uint32_t)s, INFINITY};
        for (float rad = cell; isinf(st.best2); rad *= 2.0f) {
            fs_grid_query(&g, x, rad, nn_visit, &st);
            if (rad > diag) break;
        }
        nn[s] = sqrtf(st.best2);
        phi_state ps = {f, 0.0};
        fs_grid_query(&g, x, f->H, phi_visit, &ps);
        phi[s] = (float)(ps.sum * f->volume);
    }
    out->n = p->n;
    out->nn_median = median(nn, p->n);
    out->density_median = median(phi, p->n);
    free(nn);
    free(phi);
    fs_grid_free(&g);
    return FS_OK;
}
