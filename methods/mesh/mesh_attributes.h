/* Particle attributes onto the mesh's vertices, as splashsurf's
 * --interpolate_attribute does: at each vertex the Shepard (normalised) SPH
 * interpolation sum_i W(|v - x_i|) a_i / sum_i W(|v - x_i|) with the scene's
 * kernel, of the velocity and the colour where the frame has them. A vertex
 * with no particle within H gets 0. The exports write them (mesh_export.h). */
#ifndef FS_MESH_ATTRIBUTES_H
#define FS_MESH_ATTRIBUTES_H
#include "grid.h"
#include "kernels.h"
#include "particles.h"
#include "trimesh.h"

/* Fills m->vel (when p has velocities) and m->col (when p has colours); g is
 * p's grid (cell >= f->H). FS_ERR_RUNTIME (fs_fail) out of memory. */
int fs_mesh_attributes(fs_trimesh *m, const fs_particles *p, const fs_grid *g, const fs_field *f);

#endif
