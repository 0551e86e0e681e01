/* Per-particle anisotropy of Yu & Turk 2013 as used by xu2022 (4.2): weighted
 * PCA of the neighbours within a radius R, eigenvalues clamped to
 * sigma_1 / kappa, isotropic at or below n_eps neighbours, a global scale, and
 * optional Laplacian smoothing of the kernel centres. The result for particle i
 * is a kernel centre c_i and a symmetric stretch matrix A_i: particle i's
 * sprite is the ellipsoid c_i + A_i (r u), |u| <= 1, and its anisotropic kernel
 * is W(|A_i^-1 (x - c_i)|, H) / det A_i (A_i = I gives the isotropic kernel).
 * shaders/common/anisotropy.comp.glsl computes the same from the GL grid. */
#ifndef FS_ANISOTROPY_H
#define FS_ANISOTROPY_H
#include "grid.h"
#include "kernels.h"
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Defaults shared by aniso_ssf and the anisotropic reference (methods/aniso_ssf/README.md). */
#define FS_ANISO_RADIUS_R 8.0   /* neighbourhood radius R, multiples of r (Yu & Turk's r_i = 2h, h = H = 4r) */
#define FS_ANISO_KAPPA 4.0      /* largest / smallest eigenvalue after clamping (xu2022: 4) */
#define FS_ANISO_N_EPS 20       /* at or below this many neighbours: isotropic (xu2022: 20) */
#define FS_ANISO_SCALE 1.0      /* stretch = scale * sigma_k / sigma_ref (see fs_aniso_sigma_ref) */
#define FS_ANISO_LAMBDA 0.0     /* Laplacian smoothing of centres (Yu & Turk eq. 6); xu2022 has none */
#define FS_ANISO_PER_PARTICLE 1 /* 1: each stretch scaled to determinant scale^3 (volume kept per particle) */

typedef struct fs_aniso_params {
    fs_kernel kernel; /* weight kernel of eq. 5 (the scene's kernel) */
    float radius;     /* R, scene units */
    float kappa;
    int n_eps;
    float scale;
    float lambda;
    int per_particle; /* 1: stretch = scale sigma_k / cbrt(sigma_1 sigma_2 sigma_3); 0: scale sigma_k / sigma_ref */
    float sigma_ref;  /* weighted variance per axis of the unjittered bulk lattice (scene units^2) */
} fs_aniso_params;

/* Weighted variance along one axis of a lattice of the given spacing around one
 * of its points, with weights W(d, radius): the bulk value that maps to stretch 1.
 * xu2022's global s (|s C| ~ 1 in the bulk) is scale / sigma_ref in our units. */
double fs_aniso_sigma_ref(fs_kernel k, float radius, float spacing);
/* Fills ap from the defaults above for particle radius r and the given kernel. */
void fs_aniso_defaults(fs_aniso_params *ap, fs_kernel k, float r);

/* Anisotropy of one point x over the grid's particles (x itself included when
 * it is a particle). centre[3], A[9] row-major symmetric; returns the neighbour
 * count (particles within R other than at distance 0). */
int fs_aniso_point(const fs_grid *g, const float x[3], const fs_aniso_params *ap, float centre[3], float A[9]);
/* Every particle, in the ORIGINAL order of p (g built from p): centre[3n], A[9n].
 * *max_axis (may be NULL) gets the largest stretch of any particle. */
int fs_aniso_compute(const fs_particles *p, const fs_grid *g, const fs_aniso_params *ap, float *centre, float *A,
                     float *max_axis);

#ifdef __cplusplus
}
#endif
#endif
