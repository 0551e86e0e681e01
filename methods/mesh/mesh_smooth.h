/* Mesh smoothing of the mesh method: uniform Laplacian (x += lambda (mean of
 * the edge neighbours - x)), Taubin's lambda|mu (Taubin 1995, lambda 0.5,
 * mu -0.53: pass-band k 0.1), which smooths without shrinking, or splashsurf's
 * weighted Laplacian (Loeschner et al. 2023: x += w_v (mean - x), step 1 times a
 * per-vertex weight w_v in [0, 1] from the particle density, mesh_weights.h). */
#ifndef FS_MESH_SMOOTH_H
#define FS_MESH_SMOOTH_H
#include "trimesh.h"

typedef enum {
    FS_MESH_SMOOTH_OFF = 0,
    FS_MESH_SMOOTH_LAPLACIAN = 1,
    FS_MESH_SMOOTH_TAUBIN = 2,
    FS_MESH_SMOOTH_WEIGHTED = 3
} fs_mesh_smoothing;
#define FS_MESH_LAMBDA 0.5
#define FS_MESH_MU (-0.53)
/* weighted: splashsurf's step (beta = 1; postprocessing.rs passes R::one()) */
#define FS_MESH_WEIGHTED_BETA 1.0

/* iters steps (a Taubin step is one lambda and one mu pass) on m's positions;
 * w: the per-vertex weights for FS_MESH_SMOOTH_WEIGHTED (else unused, may be
 * NULL). FS_ERR_RUNTIME (fs_fail) out of memory. */
int fs_mesh_smooth(fs_trimesh *m, int kind, int iters, const float *w);

#endif
