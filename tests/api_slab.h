/* The particle slab of the C API tests, written once: ni x nj x nk sites on a lattice
 * of spacing 2r, shifted by dx along x, into x, y, z (their count returned). */
#ifndef FS_TEST_API_SLAB_H
#define FS_TEST_API_SLAB_H
#include <stddef.h>

static inline size_t api_slab(float *x, float *y, float *z, int ni, int nj, int nk, float r, float dx)
{
    size_t n = 0;
    for (int i = 0; i < ni; i++)
        for (int j = 0; j < nj; j++)
            for (int k = 0; k < nk; k++) x[n] = 2 * r * i + dx, y[n] = 2 * r * j, z[n] = 2 * r * k, n++;
    return n;
}
#endif
