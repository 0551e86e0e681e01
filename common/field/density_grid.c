/* Density grids (density_grid.h): allocation, trilinear sampling, the exact CPU
 * grid through the neighbour grid, and the relative L2 difference. The exact
 * grid is written without reference to the splatting code, so the two check
 * each other. */
#include "density_grid.h"
#include "counters.h"
#include "fs_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int fs_density_grid_init(fs_density_grid *g, const float bmin[3], const float bmax[3], float pad, int res)
{
    memset(g, 0, sizeof *g);
    if (res < 2) return fs_fail(FS_ERR_INPUT, "density grid: resolution %d must be at least 2", res);
    if (!(pad >= 0) || !isfinite(pad)) return fs_fail(FS_ERR_INPUT, "density grid: padding %g must be >= 0", pad);
    double lo[3], ext[3], emax = 0;
    for (int a = 0; a < 3; a++) {
        if (!isfinite(bmin[a]) || !isfinite(bmax[a]) || bmax[a] < bmin[a])
            return fs_fail(FS_ERR_INPUT, "density grid: bad bounding box on axis %d: [%g, %g]", a, bmin[a], bmax[a]);
        lo[a] = (double)bmin[a] - pad;
        ext[a] = ((double)bmax[a] + pad) - lo[a];
        if (ext[a] > emax) emax = ext[a];
    }
    if (!(emax > 0)) return fs_fail(FS_ERR_INPUT, "density grid: the box is a single point (give a padding)");
    double h = emax / (res - 1), total = 1;
    int dim[3];
    for (int a = 0; a < 3; a++) {
        /* enough points to reach bmax + pad (a relative slack absorbs rounding) */
        double n = ceil(ext[a] / h - 1e-6) + 1;
        if (n < 2) n = 2;
        if (n > (double)FS_DENSITY_GRID_MAX_POINTS)
            return fs_fail(FS_ERR_INPUT, "density grid: %g points along axis %d is too many", n, a);
        dim[a] = (int)n;
        total *= n;
    }
    if (total > (double)FS_DENSITY_GRID_MAX_POINTS)
        return fs_fail(FS_ERR_INPUT, "density grid: %dx%dx%d points exceed the limit of %zu (resolution %d)", dim[0],
                       dim[1], dim[2], (size_t)FS_DENSITY_GRID_MAX_POINTS, res);
    g->data = calloc((size_t)total, sizeof(float));
    if (!g->data)
        return fs_fail(FS_ERR_RUNTIME, "density grid: out of memory for %dx%dx%d points", dim[0], dim[1], dim[2]);
    for (int a = 0; a < 3; a++) {
        g->origin[a] = (float)lo[a];
        g->dim[a] = dim[a];
    }
    g->spacing = (float)h;
    return FS_OK;
}

void fs_density_grid_free(fs_density_grid *g)
{
    free(g->data);
    memset(g, 0, sizeof *g);
}

float fs_density_grid_sample(const fs_density_grid *g, const float x[3])
{
    if (!g->data) return 0.0f;
    int i0[3];
    float t[3];
    for (int a = 0; a < 3; a++) {
        float u = (x[a] - g->origin[a]) / g->spacing;
        if (!(u >= 0.0f) || u > (float)(g->dim[a] - 1)) return 0.0f; /* outside (or NaN) */
        int i = (int)u;
        if (i > g->dim[a] - 2) i = g->dim[a] - 2;
        i0[a] = i;
        t[a] = u - (float)i;
    }
    float v = 0.0f;
    for (int c = 0; c < 8; c++) {
        int di = c & 1, dj = (c >> 1) & 1, dk = c >> 2;
        float w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
        v += w * g->data[fs_density_grid_index(g, i0[0] + di, i0[1] + dj, i0[2] + dk)];
    }
    return v;
}

int fs_density_grid_exact(fs_density_grid *g, const fs_particles *p, const fs_grid *ng, const fs_field *f)
{
    if (!g->data) return fs_fail(FS_ERR_INPUT, "density grid: not initialised");
    if (!(f->H > 0) || !(f->volume > 0) || !isfinite(f->H) || !isfinite(f->volume))
        return fs_fail(FS_ERR_INPUT, "density grid: support H %g and volume V %g must be positive", f->H, f->volume);
    if (ng->n != p->n)
        return fs_fail(FS_ERR_INPUT, "density grid: the neighbour grid holds %zu particles, the set %zu", ng->n, p->n);
    size_t npts = fs_density_grid_points(g);
    if (ng->n == 0) {
        memset(g->data, 0, npts * sizeof(float));
        return FS_OK;
    }
    const float H = f->H, H2 = H * H, V = f->volume;
    const fs_kernel kern = f->kernel;
    uint64_t evals = 0, visits = 0; /* work counters: a sum per voxel summed, the particles it looked at */
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : evals, visits)
    for (int k = 0; k < g->dim[2]; k++) {
        float z = g->origin[2] + g->spacing * k;
        int klo = fs_grid_coord(ng, 2, z - H), khi = fs_grid_coord(ng, 2, z + H);
        for (int j = 0; j < g->dim[1]; j++) {
            float y = g->origin[1] + g->spacing * j;
            int jlo = fs_grid_coord(ng, 1, y - H), jhi = fs_grid_coord(ng, 1, y + H);
            float *row = g->data + fs_density_grid_index(g, 0, j, k);
            /* the support ball misses every stored cell: the whole row is zero */
            if (khi < ng->lo[2] || klo > ng->hi[2] || jhi < ng->lo[1] || jlo > ng->hi[1]) {
                memset(row, 0, (size_t)g->dim[0] * sizeof(float));
                continue;
            }
            for (int i = 0; i < g->dim[0]; i++) {
                float x = g->origin[0] + g->spacing * i;
                int ilo = fs_grid_coord(ng, 0, x - H), ihi = fs_grid_coord(ng, 0, x + H);
                double sum = 0.0;
                for (int kc = klo; kc <= khi; kc++)
                    for (int jc = jlo; jc <= jhi; jc++) {
                        uint32_t s0, s1;
                        for (int ic = ilo, e; ic <= ihi; ic = e + 1) { /* one run of sorted slots per block */
                            e = fs_grid_row_run(ng, ic, ihi, jc, kc, &s0, &s1);
                            visits += s1 - s0;
                            for (uint32_t s = s0; s < s1; s++) {
                                const float *q = ng->pos4 + 4 * (size_t)s;
                                float dx = q[0] - x, dy = q[1] - y, dz = q[2] - z;
                                float d2 = dx * dx + dy * dy + dz * dz;
                                if (d2 < H2) sum += fs_kernel_w(kern, sqrtf(d2), H);
                            }
                        }
                    }
                row[i] = (float)(V * sum);
                evals++;
            }
        }
    }
    fs_count_add(FS_CNT_FIELD_EVALS, evals);
    fs_count_add(FS_CNT_NEIGHBOURS, visits);
    fs_count_add(FS_CNT_TEXELS, npts); /* every voxel is stored, zero rows too */
    return FS_OK;
}

static int inside(const fs_particles *p, size_t i, const float lo[3], const float hi[3])
{
    return p->x[i] >= lo[0] && p->x[i] <= hi[0] && p->y[i] >= lo[1] && p->y[i] <= hi[1] && p->z[i] >= lo[2] &&
        p->z[i] <= hi[2];
}

int fs_density_grid_keep(const fs_particles *p, const float lo[3], const float hi[3], float pad, fs_particles *out,
                         size_t *dropped)
{
    float l[3], h[3];
    for (int a = 0; a < 3; a++) {
        l[a] = lo[a] - pad;
        h[a] = hi[a] + pad;
    }
    size_t keep = 0;
    for (size_t i = 0; i < p->n; i++) keep += inside(p, i, l, h);
    *dropped = p->n - keep;
    if (!*dropped) {
        *out = *p;
        return FS_OK;
    }
    if (fs_particles_alloc(out, keep, 0))
        return fs_fail(FS_ERR_RUNTIME, "density grid: out of memory for %zu particles", keep);
    for (size_t i = 0, k = 0; i < p->n; i++)
        if (inside(p, i, l, h)) {
            out->x[k] = p->x[i];
            out->y[k] = p->y[i];
            out->z[k] = p->z[i];
            k++;
        }
    out->radius = p->radius;
    fs_particles_bounds(out);
    return FS_OK;
}

double fs_density_grid_rel_l2(const fs_density_grid *a, const fs_density_grid *b)
{
    for (int k = 0; k < 3; k++)
        if (a->dim[k] != b->dim[k]) return NAN;
    if (!a->data || !b->data) return NAN;
    size_t n = fs_density_grid_points(a);
    double num = 0, den = 0;
    for (size_t i = 0; i < n; i++) {
        double d = (double)a->data[i] - b->data[i];
        num += d * d;
        den += (double)b->data[i] * b->data[i];
    }
    if (den == 0) return num == 0 ? 0.0 : INFINITY;
    return sqrt(num / den);
}
