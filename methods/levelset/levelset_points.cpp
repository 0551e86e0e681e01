// OpenVDB's point rasterisers for the levelset method (levelset_points.hpp):
// the positions become a PointDataGrid, which points::rasterizeSpheres (a
// sphere of radius b->radius stamped per point, as ParticlesToLevelSet) or
// points::rasterizeSmoothSpheres (Zhu & Bridson 2005: at each voxel the
// distance to the kernel-weighted mean of the points within b->search, less
// the weighted mean radius) turn into a narrow-band level set.
#include "levelset_points.hpp"

#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/points/PointRasterizeSDF.h>
#include <openvdb/tools/PointIndexGrid.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <vector>

namespace
{

// The PointDataGrid's voxel: one sphere radius (about one point a voxel at the
// rest spacing 2r of spheres of 2r); it only buckets the points, the level set
// gets its own transform.
openvdb::points::PointDataGrid::Ptr point_grid(const float *x, const float *y, const float *z, size_t n, double cell)
{
    std::vector<openvdb::Vec3R> pos(n);
    for (size_t i = 0; i < n; i++) pos[i] = openvdb::Vec3R(x[i], y[i], z[i]);
    openvdb::points::PointAttributeVector<openvdb::Vec3R> list(pos);
    openvdb::math::Transform::Ptr xf = openvdb::math::Transform::createLinearTransform(cell);
    auto index = openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(list, *xf);
    // NullCodec: positions kept as floats (voxel-relative), no quantisation
    return openvdb::points::createPointDataGrid<openvdb::points::NullCodec, openvdb::points::PointDataGrid>(*index,
                                                                                                            list, *xf);
}

} // namespace

openvdb::FloatGrid::Ptr fs_ls_points_rasterize(const float *x, const float *y, const float *z, size_t n,
                                               const fs_ls_build *b)
{
    auto points = point_grid(x, y, z, n, b->radius);
    // the same index-to-world map as openvdb::createLevelSet's (voxel centres at i * voxel)
    openvdb::math::Transform::Ptr xf = openvdb::math::Transform::createLinearTransform(b->voxel);
    openvdb::FloatGrid::Ptr grid;
    if (b->rasterizer == FS_LS_RASTER_SMOOTH) {
        grid = openvdb::points::rasterizeSmoothSpheres<openvdb::points::PointDataGrid, openvdb::FloatGrid>(
            *points, b->radius, b->search, b->half_width, xf);
        // The smooth rasteriser clamps the deep inside to -background and turns it
        // off, and its pruneInactive then makes those leaves +background tiles (outside):
        // the signs of the inactive values are set again from the band's, as a level
        // set needs them (a ray marching on from inside must not see a false exit).
        openvdb::tools::signedFloodFill(grid->tree());
    } else {
        grid = openvdb::points::rasterizeSpheres<openvdb::points::PointDataGrid, openvdb::FloatGrid>(*points, b->radius,
                                                                                                     b->half_width, xf);
    }
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    return grid;
}
