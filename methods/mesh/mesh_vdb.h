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
#define FS_MESH_LEAF_BYTES (FS_MESH_LEAF3 * 4 + 256) /* a leaf with its voxels, and the tree above it */
#define FS_MESH_INDEX_BYTES 160                      /* every leaf's bookkeeping: mask, origin, minima, index entry */

typedef struct fs_mesh_volume fs_mesh_volume;

/* The sample volume: the leaves of voxel size `cube` (voxel (i,j,k) sits at
 * (i,j,k) cube) that hold a voxel within `reach` of one of the n points. It is
 * filled one slab at a time (the leaves of one x position of the leaf lattice,
 * in order), and only the leaves the iso-surface can pass through keep their
 * voxels: a leaf that is inside (every value > iso) and whose six face
 * neighbours' facing layers are inside too has no edge that crosses iso, so it
 * becomes one tile of OpenVDB's tree, valued at its minimum. The mesh is the
 * same; the voxels held are those kept plus two slabs. keep_all keeps every
 * leaf (for tests). mem_limit (bytes; 0: none) bounds what the volume holds:
 * when the leaves' bookkeeping alone would pass it, returns NULL with *need =
 * the leaf count and fs_fail not set (NULL with fs_fail set on any other
 * failure); fs_mesh_volume_slab refuses a slab that would pass it. */
fs_mesh_volume *fs_mesh_volume_create(const float *x, const float *y, const float *z, size_t n, double cube,
                                      double reach, double iso, int keep_all, double mem_limit, size_t *need);
/* The volume's leaf count and slab count. */
size_t fs_mesh_volume_leaves(const fs_mesh_volume *v);
size_t fs_mesh_volume_slabs(const fs_mesh_volume *v);
/* Slab s (filled in order, 0 first): its leaf count, their origins (the voxel
 * coordinates of each first voxel, 3 ints a leaf) and a buffer of count x 512
 * zeros to add the values into (leaf after leaf, x slowest, z fastest: offset
 * x * 64 + y * 8 + z). NULL with fs_fail set: FS_ERR_INPUT when the leaves kept
 * so far and this slab would pass mem_limit (naming the cube size that would
 * fit), FS_ERR_RUNTIME out of memory. */
float *fs_mesh_volume_slab(fs_mesh_volume *v, size_t s, size_t *count, const int **origins);
/* Slab s is filled: decides slab s - 1 (its leaves kept or made tiles) and
 * frees its buffer; after the last slab, decides that one too. FS_ERR_RUNTIME
 * (fs_fail) on failure. */
int fs_mesh_volume_slab_done(fs_mesh_volume *v, size_t s);
/* Leaves that kept their voxels. */
size_t fs_mesh_volume_kept(const fs_mesh_volume *v);
/* The iso-surface value = iso as a mesh (volumeToMesh, adaptivity 0, quads
 * split in two), wound outward (towards lower values). FS_ERR_RUNTIME on failure. */
int fs_mesh_volume_mesh(const fs_mesh_volume *v, double iso, fs_trimesh *out);
void fs_mesh_volume_free(fs_mesh_volume *v);

#ifdef __cplusplus
}
#endif
#endif
