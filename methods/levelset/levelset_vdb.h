/* Thin OpenVDB adapter of the levelset method (docs/DESIGN.md, "Layers": C++ only
 * behind extern "C"): particles -> narrow-band SDF by openvdb::tools::
 * ParticlesToLevelSet or by openvdb::points::rasterizeSpheres /
 * rasterizeSmoothSpheres (levelset_points.cpp), the optional LevelSetFilter recipe, per-thread ray tracers
 * (openvdb::tools::LevelSetRayIntersector) and the .vdb writer. Built only with
 * FS_WITH_OPENVDB=ON. */
#ifndef FS_LEVELSET_VDB_H
#define FS_LEVELSET_VDB_H
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef enum { FS_LS_SMOOTH_OFF = 0, FS_LS_SMOOTH_GAUSSIAN = 1, FS_LS_SMOOTH_MEANCURV = 2 } fs_ls_smoothing;
/* tools::ParticlesToLevelSet, points::rasterizeSpheres, points::rasterizeSmoothSpheres */
typedef enum { FS_LS_RASTER_PARTICLES = 0, FS_LS_RASTER_SPHERES = 1, FS_LS_RASTER_SMOOTH = 2 } fs_ls_rasterizer;

typedef struct fs_ls_build {
    double voxel;                            /* voxel size, scene units */
    double radius;                           /* sphere radius, scene units (>= 1.5 voxels) */
    double half_width;                       /* narrow-band half width, voxels */
    int dilate, smooth, smooth_iters, erode; /* the recipe: dilate/erode in voxels */
    int rasterizer;                          /* FS_LS_RASTER_* */
    double search; /* smooth: Zhu & Bridson's kernel (search) radius, scene units (>= radius) */
} fs_ls_build;

typedef struct fs_ls_grid fs_ls_grid;     /* the level set (openvdb::FloatGrid) */
typedef struct fs_ls_tracer fs_ls_tracer; /* one thread's ray intersector */

/* Builds the level set of n particles; NULL with fs_fail set on failure. */
fs_ls_grid *fs_ls_grid_build(const float *x, const float *y, const float *z, size_t n, const fs_ls_build *b);
uint64_t fs_ls_grid_active_voxels(const fs_ls_grid *g);
void fs_ls_grid_free(fs_ls_grid *g);
/* Writes the grid (named "surface", class level set) to path via temp + rename. */
int fs_ls_grid_write(const fs_ls_grid *g, const char *path);

/* NULL with fs_fail set on failure (an empty grid gives a tracer that never hits). */
fs_ls_tracer *fs_ls_tracer_create(const fs_ls_grid *g);
void fs_ls_tracer_free(fs_ls_tracer *t);

typedef struct fs_ls_hit {
    int hit;
    double t;         /* distance from eye to the first entry (dir is unit) */
    double n[3];      /* unit world normal (outward SDF gradient) at the entry */
    double thick;     /* sum of inside path lengths over every layer (0 when off) */
    uint64_t queries; /* intersector queries made for this ray */
} fs_ls_hit;
/* One ray from eye along unit dir. thickness: march on through the layers. */
void fs_ls_trace(fs_ls_tracer *t, const float eye[3], const float dir[3], int thickness, fs_ls_hit *h);

#ifdef __cplusplus
}
#endif
#endif
