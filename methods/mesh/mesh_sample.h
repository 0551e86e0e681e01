/* The mesh method's field sampler: phi on every voxel of the sparse volume's
 * leaves, by splatting each particle's kernel onto the voxels inside its
 * support (an exact sum: the same kernels, H and V as the reference). */
#ifndef FS_MESH_SAMPLE_H
#define FS_MESH_SAMPLE_H
#include "aniso_kernels.h"
#include "grid.h"
#include "kernels.h"
#include "mesh_vdb.h"
#include "zhu_bridson.h"
#include <stdint.h>

typedef struct fs_mesh_work {
    uint64_t voxels; /* voxels sampled */
    uint64_t terms;  /* kernel terms added (voxel-particle pairs inside the support) */
} fs_mesh_work;

/* Fills v. Isotropic: ak NULL and g the particles' grid (cell >= H);
 * anisotropic: ak's kernels (g unused). FS_ERR_INPUT (fs_fail) over the volume's
 * memory limit (mesh_vdb.h), FS_ERR_RUNTIME out of memory. */
int fs_mesh_sample(fs_mesh_volume *v, double cube, const fs_field *f, const fs_grid *g, const fs_aniso_kernels *ak,
                   fs_mesh_work *w);

/* field=zhu_bridson: fills v with R - phi (zhu_bridson.h; 0 where no particle lies
 * within R), to be meshed at iso = R; g's cell >= R (scene units R and r). */
int fs_mesh_sample_zb(fs_mesh_volume *v, double cube, double R, double r, const fs_grid *g, fs_mesh_work *w);

#endif
