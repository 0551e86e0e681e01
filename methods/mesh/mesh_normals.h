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

#endif
