// Thin OpenVDB adapter for density grids (density_grid.h): a dense fs_density_grid
// to and from a sparse FloatGrid. Index (i,j,k) maps to world origin +
// spacing*(i,j,k); background 0; only points with phi > 0 are active.
// Kept free of PointDataGrid headers, which compile slowly.
#include "density_grid.h"
#include "fs_error.h"
#include "output_file.h"

#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace
{

void write_grid(const fs_density_grid *g, const char *tmp, const char *name)
{
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    auto xform = openvdb::math::Transform::createLinearTransform(g->spacing);
    xform->postTranslate(openvdb::Vec3d(g->origin[0], g->origin[1], g->origin[2]));
    grid->setTransform(xform);
    grid->setName(name);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    auto acc = grid->getAccessor();
    for (int k = 0; k < g->dim[2]; k++)
        for (int j = 0; j < g->dim[1]; j++) {
            const float *row = g->data + fs_density_grid_index(g, 0, j, k);
            for (int i = 0; i < g->dim[0]; i++)
                if (row[i] > 0.0f) acc.setValue(openvdb::Coord(i, j, k), row[i]);
        }
    openvdb::io::File file(tmp);
    file.write({grid});
    file.close();
}

int read_grid(fs_density_grid *g, const char *path, const char *name)
{
    openvdb::io::File file(path);
    file.open(false);
    if (!file.hasGrid(name)) {
        file.close();
        return fs_fail(FS_ERR_INPUT, "%s: no grid named '%s'", path, name);
    }
    openvdb::GridBase::Ptr base = file.readGrid(name);
    file.close();
    openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
    if (!grid)
        return fs_fail(FS_ERR_INPUT, "%s: grid '%s' is a %s, not a float grid", path, name, base->type().c_str());
    const openvdb::math::Transform &xf = grid->transform();
    openvdb::Vec3d vs = xf.voxelSize();
    if (!xf.isLinear() || std::fabs(vs[0] - vs[1]) > 1e-6 * vs[0] || std::fabs(vs[0] - vs[2]) > 1e-6 * vs[0])
        return fs_fail(FS_ERR_INPUT, "%s: grid '%s' does not have cubic voxels", path, name);
    openvdb::CoordBBox bb = grid->evalActiveVoxelBoundingBox();
    if (bb.empty()) return fs_fail(FS_ERR_INPUT, "%s: grid '%s' has no active voxels", path, name);
    openvdb::Coord d = bb.dim();
    double total = (double)d.x() * d.y() * d.z();
    if (total > (double)FS_DENSITY_GRID_MAX_POINTS)
        return fs_fail(FS_ERR_INPUT, "%s: grid '%s' spans %dx%dx%d voxels: too many", path, name, d.x(), d.y(), d.z());
    float *data = static_cast<float *>(std::calloc((size_t)total, sizeof(float)));
    if (!data) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for %dx%dx%d voxels", path, d.x(), d.y(), d.z());
    std::memset(g, 0, sizeof *g);
    g->data = data;
    g->dim[0] = d.x();
    g->dim[1] = d.y();
    g->dim[2] = d.z();
    g->spacing = (float)vs[0];
    openvdb::Vec3d o = xf.indexToWorld(bb.min());
    for (int a = 0; a < 3; a++) g->origin[a] = (float)o[a];
    auto acc = grid->getConstAccessor();
    for (int k = 0; k < g->dim[2]; k++)
        for (int j = 0; j < g->dim[1]; j++)
            for (int i = 0; i < g->dim[0]; i++)
                g->data[fs_density_grid_index(g, i, j, k)] = acc.getValue(bb.min().offsetBy(i, j, k));
    return FS_OK;
}

} // namespace

extern "C" int fs_density_grid_write_vdb(const fs_density_grid *g, const char *path, const char *name)
{
    if (!g->data) return fs_fail(FS_ERR_INPUT, "%s: density grid not initialised", path);
    if (!name || !*name) return fs_fail(FS_ERR_INPUT, "%s: empty grid name", path);
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    try {
        openvdb::initialize();
        write_grid(g, tmp, name);
    } catch (const std::exception &e) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot write VDB density grid: %s", path, e.what());
    }
    return fs_output_end(path, tmp, 1);
}

extern "C" int fs_density_grid_read_vdb(fs_density_grid *g, const char *path, const char *name)
{
    std::memset(g, 0, sizeof *g);
    try {
        openvdb::initialize();
        int rc = read_grid(g, path, name);
        if (rc) fs_density_grid_free(g);
        return rc;
    } catch (const std::exception &e) {
        fs_density_grid_free(g);
        return fs_fail(FS_ERR_INPUT, "%s: cannot read VDB density grid: %s", path, e.what());
    }
}
