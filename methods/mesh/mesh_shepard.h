/* Shepard interpolation at a point over the neighbour grid: the kernel-weighted mean
 * sum_i W(|x - x_i|) v_i / sum_i W(|x - x_i|) of a per-particle value, with the
 * scene's kernel, over the 27 cells around x (the cell is at least H). The vertex
 * attributes (mesh_attributes.h) and splashsurf's smoothing weights (mesh_weights.h)
 * both interpolate this way. */
#ifndef FS_MESH_SHEPARD_H
#define FS_MESH_SHEPARD_H
#include "grid.h"
#include "kernels.h"
#include <stdint.h>

/* Component a of the value of the particle in sorted slot `slot`. */
typedef float (*fs_shepard_value)(const void *ctx, uint32_t slot, int a);

/* out[0..k), k <= 4: the mean of value(ctx, slot, a) at x, 0 where no particle is within H.
 * terms (may be NULL) gets the particles summed. */
void fs_mesh_shepard(const fs_grid *g, const fs_field *f, const float x[3], fs_shepard_value value, const void *ctx,
                     int k, double *out, uint64_t *terms);

#endif
