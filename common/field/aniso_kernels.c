/* The anisotropic kernels of a frame (aniso_kernels.h): centres and stretches
 * from anisotropy.c, A^-1 and 1/det A by an eigen decomposition, reordered to
 * the sorted slots of a grid of the centres. */
#include "aniso_kernels.h"
#include "eigen3.h"
#include "fs_error.h"
#include <stdlib.h>
#include <string.h>

void fs_aniso_kernels_free(fs_aniso_kernels *k)
{
    fs_grid_free(&k->grid);
    free(k->inv);
    free(k->wscale);
    memset(k, 0, sizeof *k);
}

/* Particle i's A^-1 (inv) and 1/det A (*ws) from its stretch A; its largest
 * axis and 1/(det A a_min) into *amax and *lip (max over particles). */
static int invert(const float *A, size_t i, float *inv, float *ws, float *amax, float *lip)
{
    double a[9], ev[3], V[9];
    for (int k = 0; k < 9; k++) a[k] = A[k];
    fs_eigen3_sym(a, ev, V);
    if (!(ev[0] > 0)) return fs_fail(FS_ERR_RUNTIME, "anisotropic field: particle %zu has a degenerate stretch", i);
    for (int r = 0; r < 3; r++)
        for (int q = 0; q < 3; q++) {
            double v = 0;
            for (int k = 0; k < 3; k++) v += V[3 * k + r] * V[3 * k + q] / ev[k];
            inv[3 * r + q] = (float)v;
        }
    *ws = (float)(1.0 / (ev[0] * ev[1] * ev[2]));
    if (ev[2] > *amax) *amax = (float)ev[2];
    if (*ws / ev[0] > *lip) *lip = (float)(*ws / ev[0]);
    return FS_OK;
}

/* Permutes the per-particle arrays (original order) into the grid's sorted order. */
static int to_sorted(fs_aniso_kernels *k, const float *inv, const float *ws, size_t n)
{
    k->inv = malloc((n ? n : 1) * 9 * sizeof *k->inv);
    k->wscale = malloc((n ? n : 1) * sizeof *k->wscale);
    if (!k->inv || !k->wscale) return fs_fail(FS_ERR_RUNTIME, "anisotropic field: out of memory");
    for (size_t sl = 0; sl < n; sl++) {
        uint32_t o = k->grid.index[sl];
        memcpy(k->inv + 9 * sl, inv + 9 * (size_t)o, 9 * sizeof *inv);
        k->wscale[sl] = ws[o];
    }
    return FS_OK;
}

int fs_aniso_kernels_build(fs_aniso_kernels *k, const fs_particles *p, const fs_grid *g, const fs_aniso_params *ap,
                           float H)
{
    memset(k, 0, sizeof *k);
    size_t n = p->n, n1 = n ? n : 1;
    float *A = malloc(n1 * 9 * sizeof *A), *cen = malloc(n1 * 3 * sizeof *cen);
    float *inv = malloc(n1 * 9 * sizeof *inv), *ws = malloc(n1 * sizeof *ws);
    fs_particles c;
    memset(&c, 0, sizeof c);
    int rc = A && cen && inv && ws ? fs_particles_alloc(&c, n, 0)
                                   : fs_fail(FS_ERR_RUNTIME, "anisotropic field: out of memory for %zu particles", n);
    if (!rc) rc = fs_aniso_compute(p, g, ap, cen, A, NULL);
    float amax = 1, lip = 0;
    for (size_t i = 0; !rc && i < n; i++) {
        c.x[i] = cen[3 * i];
        c.y[i] = cen[3 * i + 1];
        c.z[i] = cen[3 * i + 2];
        rc = invert(A + 9 * i, i, inv + 9 * i, ws + i, &amax, &lip);
    }
    free(A);
    free(cen);
    if (!rc) {
        fs_particles_bounds(&c);
        k->reach = H * amax * 1.0001f; /* a little margin for float rounding of the metric */
        k->lip = lip > 0 ? lip : 1;
        rc = fs_grid_build(&k->grid, &c, k->reach);
    }
    fs_particles_free(&c);
    if (!rc) rc = to_sorted(k, inv, ws, n);
    free(inv);
    free(ws);
    if (rc) fs_aniso_kernels_free(k);
    return rc;
}
