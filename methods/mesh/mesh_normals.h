/* splashsurf's vertex normals for the weighted recipe: the area-weighted mean
 * of the adjacent triangles' normals on the smoothed mesh, then iters passes
 * that set each normal to the normalised sum of its edge neighbours' normals
 * (splashsurf's --normals-smoothing-iters; the vertex's own normal is not in
 * the sum, as there). */
#ifndef FS_MESH_NORMALS_H
#define FS_MESH_NORMALS_H
#include "trimesh.h"

/* splashsurf's README recipe: --normals-smoothing-iters=10 */
#define FS_MESH_NORMAL_ITERS 10

/* Allocates and fills m->nrm. FS_ERR_RUNTIME (fs_fail) out of memory. */
int fs_mesh_normals_smoothed(fs_trimesh *m, int iters);

/* The field's outward unit normal at x into n; 0 where it cannot tell (the
 * gradient vanishes), 1 otherwise. */
typedef int (*fs_mesh_field_normal)(const void *ctx, const float *x, float n[3]);

/* Gives every vertex normal that is not unit (0 where the gradient vanished or
 * a smoothed sum cancelled) one: the area-weighted mean of its faces' normals,
 * else the field's (field may be NULL), else its largest face's, which every
 * vertex of a mesh without degenerate faces has (mesh_collapse.h). repaired:
 * how many (may be NULL). FS_ERR_RUNTIME (fs_fail) out of memory. */
int fs_mesh_normals_repair(fs_trimesh *m, fs_mesh_field_normal field, const void *ctx, size_t *repaired);

#endif
