/* Uniform neighbour grid by counting sort (grid.h). Cell ids are computed in
 * parallel; the histogram and scatter stay serial so particles keep their
 * original order inside a cell, which makes every sum over a cell (and so every
 * image) reproducible whatever the thread count. */
#include "grid.h"
#include "fs_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void fs_grid_free(fs_grid *g)
{
    free(g->start);
    free(g->index);
    free(g->pos4);
    memset(g, 0, sizeof *g);
}

/* Bounding box of the positions; fails on a NaN/Inf position (it would make
 * floorf() undefined when cast to int). */
/* Below this many particles a parallel loop costs more (thread wake-up) than it saves. */
#define FS_GRID_PARALLEL_MIN 100000

static int positions_box(const fs_particles *p, float lo[3], float hi[3])
{
    float x0 = INFINITY, y0 = INFINITY, z0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, z1 = -INFINITY;
    long bad = -1;
    long n = (long)p->n;
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) reduction(min : x0, y0, z0) reduction(max : x1, y1, z1, bad)
    for (long i = 0; i < n; i++) {
        float x = p->x[i], y = p->y[i], z = p->z[i];
        if (!isfinite(x) || !isfinite(y) || !isfinite(z)) { if (i > bad) bad = i; continue; }
        x0 = fminf(x0, x); y0 = fminf(y0, y); z0 = fminf(z0, z);
        x1 = fmaxf(x1, x); y1 = fmaxf(y1, y); z1 = fmaxf(z1, z);
    }
    if (bad >= 0) return fs_fail(FS_ERR_INPUT, "particles: particle %ld has a non-finite position", bad);
    lo[0] = x0; lo[1] = y0; lo[2] = z0;
    hi[0] = x1; hi[1] = y1; hi[2] = z1;
    return FS_OK;
}

int fs_grid_build(fs_grid *g, const fs_particles *p, float cell)
{
    memset(g, 0, sizeof *g);
    if (!(cell > 0) || !isfinite(cell))
        return fs_fail(FS_ERR_INPUT, "grid: cell size %g must be a positive number", cell);
    if (p->n >= UINT32_MAX)
        return fs_fail(FS_ERR_INPUT, "grid: %zu particles: too many (at most %u)", p->n, UINT32_MAX - 1);
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    if (p->n) {
        int rc = positions_box(p, lo, hi);
        if (rc) return rc;
    }
    /* One empty cell of margin on every side: the field is zero on the grid's
     * boundary, so ray marchers enter and leave in empty space. */
    double cells = 1;
    for (int a = 0; a < 3; a++) {
        g->origin[a] = lo[a] - cell;
        double d = floor(((double)hi[a] - g->origin[a]) / cell) + 2;
        if (d > (double)FS_GRID_MAX_CELLS) d = (double)FS_GRID_MAX_CELLS + 1;
        g->dim[a] = (int)d;
        cells *= d;
    }
    if (cells > (double)FS_GRID_MAX_CELLS)
        return fs_fail(FS_ERR_INPUT, "grid: cell size %g gives %.0f cells: too many, raise the cell size",
                       cell, cells);
    g->cell = cell;
    g->ncells = (size_t)cells;
    g->n = p->n;
    size_t n = p->n;
    uint32_t *cid = malloc((n ? n : 1) * sizeof *cid);
    g->start = calloc(g->ncells + 1, sizeof *g->start);
    g->index = malloc((n ? n : 1) * sizeof *g->index);
    g->pos4 = malloc((n ? n : 1) * 4 * sizeof *g->pos4);
    if (!cid || !g->start || !g->index || !g->pos4) {
        free(cid);
        fs_grid_free(g);
        return fs_fail(FS_ERR_RUNTIME, "grid: out of memory for %zu particles", n);
    }
    long nl = (long)n;
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) schedule(static)
    for (long i = 0; i < nl; i++) {
        int ci = fs_grid_clampi(fs_grid_coord(g, 0, p->x[i]), g->dim[0] - 1);
        int cj = fs_grid_clampi(fs_grid_coord(g, 1, p->y[i]), g->dim[1] - 1);
        int ck = fs_grid_clampi(fs_grid_coord(g, 2, p->z[i]), g->dim[2] - 1);
        cid[i] = (uint32_t)fs_grid_cell_id(g, ci, cj, ck);
    }
    /* Histogram into start[c + 1], prefix sum, then scatter with start[c] as
     * the running cursor (shifted back afterwards). */
    for (size_t i = 0; i < n; i++) g->start[cid[i] + 1]++;
    for (size_t c = 0; c < g->ncells; c++) g->start[c + 1] += g->start[c];
    for (size_t i = 0; i < n; i++) g->index[g->start[cid[i]]++] = (uint32_t)i;
    memmove(g->start + 1, g->start, g->ncells * sizeof *g->start);
    g->start[0] = 0;
    free(cid);
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) schedule(static)
    for (long s = 0; s < nl; s++) {
        uint32_t i = g->index[s];
        float *q = g->pos4 + 4 * s;
        q[0] = p->x[i];
        q[1] = p->y[i];
        q[2] = p->z[i];
        memcpy(&q[3], &i, sizeof i);
    }
    return FS_OK;
}

void fs_grid_query(const fs_grid *g, const float x[3], float radius, fs_grid_visit fn, void *user)
{
    if (!g->n || !(radius >= 0)) return;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = fs_grid_coord(g, a, x[a] - radius);
        hi[a] = fs_grid_coord(g, a, x[a] + radius);
        if (hi[a] < 0 || lo[a] > g->dim[a] - 1) return; /* the ball misses the grid */
        lo[a] = fs_grid_clampi(lo[a], g->dim[a] - 1);
        hi[a] = fs_grid_clampi(hi[a], g->dim[a] - 1);
    }
    float r2 = radius * radius;
    for (int k = lo[2]; k <= hi[2]; k++)
        for (int j = lo[1]; j <= hi[1]; j++) {
            size_t row = fs_grid_cell_id(g, 0, j, k);
            uint32_t s0 = g->start[row + lo[0]], s1 = g->start[row + hi[0] + 1];
            for (uint32_t s = s0; s < s1; s++) { /* a row of cells is one run of slots */
                const float *q = g->pos4 + 4 * (size_t)s;
                float dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
                float d2 = dx * dx + dy * dy + dz * dz;
                if (d2 <= r2) fn(user, s, d2);
            }
        }
}

int fs_grid_fit(const fs_grid *given, const fs_particles *p, float cell, fs_grid *own, int *has_own,
                const fs_grid **out)
{
    if (*has_own) { fs_grid_free(own); *has_own = 0; }
    *out = given;
    if (given && given->cell >= cell && given->n == p->n) return FS_OK;
    int rc = fs_grid_build(own, p, cell);
    if (rc) return rc;
    *has_own = 1;
    *out = own;
    return FS_OK;
}
