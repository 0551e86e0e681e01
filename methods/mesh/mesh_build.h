/* The mesh method's surface, built on the CPU from one frame: the scene's own
 * field sampled on a sparse volume of cube size `cube` near the particles
 * (mesh_sample.h), meshed at iso by OpenVDB's volumeToMesh (mesh_vdb.h),
 * optionally smoothed (mesh_smooth.h), with vertex normals from the field's
 * analytic gradient (smooth=weighted: splashsurf's smoothed area-weighted
 * normals, mesh_normals.h). Used by the method (mesh.c) and by `fluidsurf mesh`. */
#ifndef FS_MESH_BUILD_H
#define FS_MESH_BUILD_H
#include "anisotropy.h"
#include "grid.h"
#include "kernels.h"
#include "particles.h"
#include "timing.h"
#include "trimesh.h"

typedef struct fs_mesh_opts {
    double cube;              /* voxel size, scene units */
    int smooth, smooth_iters; /* FS_MESH_SMOOTH_* of mesh_smooth.h */
    double weights_norm;      /* weighted: the count that gets weight 1 (mesh_weights.h; 0: FS_MESH_WEIGHTS_NORM) */
    int normal_iters;         /* weighted: smoothing passes of the area-weighted normals (mesh_normals.h) */
    int attributes;           /* 1: velocity and colour onto the vertices (mesh_attributes.h) */
    int aniso;                /* 1: the anisotropic field with ap */
    int zb;           /* 1: Zhu & Bridson's phi (zhu_bridson.h) with kernel radius zb_radius, meshed at its zero */
    double zb_radius; /* zhu_bridson: R, scene units (0: FS_ZB_RADIUS r) */
    fs_aniso_params ap;
    double mem_limit; /* bytes the sample volume may take; 0: the memory available now */
    int keep_all;     /* 1: keep every leaf's voxels, inside ones too (tests; mesh_vdb.h) */
} fs_mesh_opts;

/* Builds the mesh of frame p (g: its grid, cell >= H) into out, adding the
 * stages "field" (anisotropy, volume and sampling), "mesh", "smooth" (when on;
 * with the weights when weighted), "normals" and "attributes" (when asked) to st (may be NULL), with their work counts. FS_ERR_INPUT
 * when the volume would not fit mem_limit (naming the cube size that would),
 * FS_ERR_RUNTIME on other failures; out is then empty. */
int fs_mesh_build(const fs_particles *p, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o, fs_trimesh *out,
                  fs_stages *st);

#endif
