/* Thin OpenVDB adapter of the mesh method (docs/DESIGN.md, "Layers": C++ only
 * behind extern "C"): the sparse sample volume (an openvdb::FloatGrid whose
 * leaves of 8^3 voxels are those within reach of a particle) and its meshing
 * by openvdb::tools::volumeToMesh. Built only with FS_WITH_OPENVDB=ON. */
#ifndef FS_MESH_VDB_H
#define FS_MESH_VDB_H
#include "trimesh.h"
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MESH_LEAF 8 /* voxels per leaf edge (OpenVDB's LeafNode<float, 3>) */
#define FS_MESH_LEAF3 (FS_MESH_LEAF * FS_MESH_LEAF * FS_MESH_LEAF)

typedef struct fs_mesh_volume fs_mesh_volume;

/* Leaves of voxel size `cube` (voxel (i,j,k) sits at (i,j,k) cube) that hold a
 * voxel within `reach` of one of the n points, every voxel active and 0 (the
 * field far from every particle; the sampler adds to it). When they would be more than max_leaves (0: no
 * bound), returns NULL with *need = their count and fs_fail not set; NULL with
 * fs_fail set on any other failure. */
fs_mesh_volume *fs_mesh_volume_create(const float *x, const float *y, const float *z, size_t n, double cube,
                                      double reach, size_t max_leaves, size_t *need);
/* The volume's leaf count. */
size_t fs_mesh_volume_leaves(const fs_mesh_volume *v);
/* Leaf i's 512 values (x slowest, z fastest: offset (x * 64 + y * 8 + z)) and
 * the voxel coordinates of its first voxel. */
float *fs_mesh_volume_leaf(fs_mesh_volume *v, size_t i, int origin[3]);
/* Bytes the volume holds (OpenVDB's memUsage). */
size_t fs_mesh_volume_bytes(const fs_mesh_volume *v);
/* The iso-surface value = iso as a mesh (volumeToMesh, adaptivity 0, quads
 * split in two), wound outward (towards lower values). FS_ERR_RUNTIME on failure. */
int fs_mesh_volume_mesh(const fs_mesh_volume *v, double iso, fs_trimesh *out);
void fs_mesh_volume_free(fs_mesh_volume *v);

#ifdef __cplusplus
}
#endif
#endif
