/* Density grids: phi (docs/DESIGN.md) sampled at the points of a regular grid, built
 * three ways and shared by surfels and volume_raycast:
 *   fs_density_grid_exact        exact CPU sum through the neighbour grid (verification)
 *   fs_slice_splat_*             iwasaki2006 section 4: particles clustered by height,
 *                                four grid planes per RGBA32F pass, disks as point sprites
 *   fs_layered_splat_*           inacio2010 IV-A: one pass, each particle one point, a
 *                                geometry shader routing its disks to the layers of an
 *                                R32F 3D texture (gl_Layer); the grid stays on the GL side
 * Layout: grid point (i,j,k) is at origin + spacing*(i,j,k); data index
 * (k*dim[1] + j)*dim[0] + i (x fastest), the same as fs_grid's cells. */
#ifndef FS_DENSITY_GRID_H
#define FS_DENSITY_GRID_H
#include "grid.h"
#include "kernels.h"
#include "particles.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_density_grid {
    float origin[3]; /* world position of grid point (0,0,0) */
    float spacing;   /* distance between neighbouring grid points (cubic cells) */
    int dim[3];      /* grid points per axis */
    float *data;     /* dim[0]*dim[1]*dim[2] values of phi */
} fs_density_grid;

/* Largest grid accepted (points), so a far-flung spray cannot exhaust memory. */
#define FS_DENSITY_GRID_MAX_POINTS ((size_t)1 << 28)

/* Sizes and allocates (zeroed) a grid over [bmin - pad, bmax + pad] with `res`
 * points along the longest axis; FS_ERR_INPUT if too large, FS_ERR_RUNTIME on OOM. */
int fs_density_grid_init(fs_density_grid *g, const float bmin[3], const float bmax[3], float pad, int res);
void fs_density_grid_free(fs_density_grid *g);
static inline size_t fs_density_grid_index(const fs_density_grid *g, int i, int j, int k)
{
    return ((size_t)k * g->dim[1] + j) * g->dim[0] + i;
}
static inline size_t fs_density_grid_points(const fs_density_grid *g)
{
    return (size_t)g->dim[0] * g->dim[1] * g->dim[2];
}
/* Trilinear sample of phi at world position x (0 outside the grid). */
float fs_density_grid_sample(const fs_density_grid *g, const float x[3]);

/* Exact CPU grid: phi at every grid point through the neighbour grid ng (built
 * with cell >= f->H); OpenMP over planes. Written independently of the splat code. */
int fs_density_grid_exact(fs_density_grid *g, const fs_particles *p, const fs_grid *ng, const fs_field *f);

/* The particles a fixed-resolution grid over the bulk box keeps: those inside
 * [lo - pad, hi + pad] (docs/DESIGN.md, "Neighbour grid"; pass the grid's bulk box
 * and pad H). When none is outside, *out = *p (it shares p's arrays: do not free
 * it) and *dropped = 0; else *out is a copy of the positions inside, with its
 * bounds (free it with fs_particles_free), and *dropped says how many were left. */
int fs_density_grid_keep(const fs_particles *p, const float lo[3], const float hi[3], float pad, fs_particles *out,
                         size_t *dropped);

/* Relative L2 difference ||a - b|| / ||b|| over all points (grids of equal shape). */
double fs_density_grid_rel_l2(const fs_density_grid *a, const fs_density_grid *b);

/* Writes g as an OpenVDB FloatGrid named `name` (voxel size = spacing, index
 * (0,0,0) at origin, background 0, points with phi > 0 active) through a
 * temporary file renamed into place. "path: what" errors. */
int fs_density_grid_write_vdb(const fs_density_grid *g, const char *path, const char *name);
/* Reads the FloatGrid `name` back into a dense grid (bounding box of its active
 * voxels); for round-trip tests and tools. */
int fs_density_grid_read_vdb(fs_density_grid *g, const char *path, const char *name);

#ifdef __cplusplus
}
#endif
#endif
