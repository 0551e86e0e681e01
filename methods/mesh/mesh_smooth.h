/* Mesh smoothing of the mesh method: uniform Laplacian (x += lambda (mean of
 * the edge neighbours - x)) or Taubin's lambda|mu (Taubin 1995, lambda 0.5,
 * mu -0.53: pass-band k 0.1), which smooths without shrinking. */
#ifndef FS_MESH_SMOOTH_H
#define FS_MESH_SMOOTH_H
#include "trimesh.h"

enum { FS_MESH_SMOOTH_OFF = 0, FS_MESH_SMOOTH_LAPLACIAN = 1, FS_MESH_SMOOTH_TAUBIN = 2 };
#define FS_MESH_LAMBDA 0.5
#define FS_MESH_MU (-0.53)

/* iters steps (a Taubin step is one lambda and one mu pass) on m's positions.
 * FS_ERR_RUNTIME (fs_fail) out of memory. */
int fs_mesh_smooth(fs_trimesh *m, int kind, int iters);

#endif
