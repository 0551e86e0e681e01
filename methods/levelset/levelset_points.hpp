// The levelset method's point rasterisers (levelset_points.cpp): OpenVDB's
// points::rasterizeSpheres and points::rasterizeSmoothSpheres, which read a
// PointDataGrid built here from the positions. Kept apart from levelset_vdb.cpp
// because the PointDataGrid headers compile slowly. C++ only (the adapter's).
#ifndef FS_LEVELSET_POINTS_HPP
#define FS_LEVELSET_POINTS_HPP
#include "levelset_vdb.h"
#include <openvdb/openvdb.h>

// The level set (class level set, voxel b->voxel, half width b->half_width) of n
// particles by b->rasterizer (FS_LS_RASTER_SPHERES or _SMOOTH). Throws on failure.
openvdb::FloatGrid::Ptr fs_ls_points_rasterize(const float *x, const float *y, const float *z, size_t n,
                                               const fs_ls_build *b);

#endif
