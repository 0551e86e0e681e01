/* The feature weights of splashsurf's weighted Laplacian smoothing (Loeschner,
 * Boettcher, Jeske, Bender, "Weighted Laplacian Smoothing for Surface
 * Reconstruction of Particle-based Fluids", VMV 2023), as splashsurf computes
 * them: each particle's distance-weighted neighbour count n_i = sum over the
 * other particles within the support H of (1 - d^2 / H^2); its Shepard
 * interpolation at each vertex, n(v) = sum_i W(|v - x_i|) n_i / sum_i W(|v - x_i|)
 * with the scene's kernel; and w(v) = smoothstep(min(n(v) / norm, 1)), the
 * quintic 6x^5 - 15x^4 + 10x^3. Dense water (n >= norm) gets 1 (smoothed fully),
 * thin sheets and splashes, with few neighbours, get little. */
#ifndef FS_MESH_WEIGHTS_H
#define FS_MESH_WEIGHTS_H
#include "grid.h"
#include "kernels.h"
#include "trimesh.h"

/* splashsurf's --mesh-smoothing-weights-normalization default */
#define FS_MESH_WEIGHTS_NORM 13.0

/* w[v] for every vertex of m (w: m->nv floats), from the particles of g (cell
 * >= f->H). FS_ERR_RUNTIME (fs_fail) out of memory. terms (may be NULL) gets the
 * particle pairs and vertex-particle terms summed. */
int fs_mesh_weights(const fs_trimesh *m, const fs_grid *g, const fs_field *f, double norm, float *w, uint64_t *terms);

/* The quintic smoothstep of min(max(n / norm, 0), 1). */
float fs_mesh_weight_of_count(double n, double norm);

#endif
