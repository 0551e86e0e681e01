/* The anisotropic kernels of a frame, ready to sum (Yu & Turk 2013, as
 * common/field/anisotropy.h computes them): particle j's kernel is
 * W(|A_j^-1 (x - c_j)|, H) / det A_j. Built once per frame by every user of the
 * anisotropic field (the reference's ray caster, the mesh method's sampler),
 * so both sum the same kernels. */
#ifndef FS_ANISO_KERNELS_H
#define FS_ANISO_KERNELS_H
#include "anisotropy.h"
#include "grid.h"
#include "kernels.h"
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_aniso_kernels {
    fs_grid grid;  /* grid of the kernel centres c_j, cell >= reach */
    float *inv;    /* A_j^-1 per sorted slot of grid (9 floats, row-major, symmetric) */
    float *wscale; /* 1 / det A_j per sorted slot */
    float reach;   /* largest distance at which a kernel is nonzero: H times the largest axis */
    float lip;     /* max_j 1 / (det A_j a_min,j): |grad| of a kernel is at most max|W'| lip */
} fs_aniso_kernels;

/* From frame p and its grid g (cell >= ap->radius is not needed: the grid only
 * finds the WPCA neighbours). FS_ERR_RUNTIME (fs_fail) on a degenerate stretch
 * or out of memory; k is then empty. */
int fs_aniso_kernels_build(fs_aniso_kernels *k, const fs_particles *p, const fs_grid *g, const fs_aniso_params *ap,
                           float H);
void fs_aniso_kernels_free(fs_aniso_kernels *k);

#ifdef __cplusplus
}
#endif
#endif
