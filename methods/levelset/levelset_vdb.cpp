// Thin OpenVDB adapter of the levelset method (levelset_vdb.h). Only level-set
// tools here (no PointDataGrid headers, which compile slowly: the point
// rasterisers are in levelset_points.cpp).
#include "levelset_vdb.h"
#include "fs_error.h"
#include "levelset_points.hpp"
#include "output_file.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/RayIntersector.h>

#include <cmath>
#include <exception>
#include <new>

struct fs_ls_grid {
    openvdb::FloatGrid::Ptr grid;
    uint64_t active;
};

using Intersector = openvdb::tools::LevelSetRayIntersector<openvdb::FloatGrid>;
struct fs_ls_tracer {
    Intersector *isect; // NULL: the grid has no active voxels
    double voxel;
};

namespace
{

// The particle-list adaptor ParticlesToLevelSet reads (as vdb_tool -points2ls).
struct ParticleList {
    using PosType = openvdb::Vec3R;
    const float *x, *y, *z;
    size_t n;
    double radius;
    size_t size() const { return n; }
    void getPos(size_t i, openvdb::Vec3R &p) const { p = openvdb::Vec3R(x[i], y[i], z[i]); }
    void getPosRad(size_t i, openvdb::Vec3R &p, openvdb::Real &r) const
    {
        getPos(i, p);
        r = radius;
    }
};

// tools::ParticlesToLevelSet (as vdb_tool -points2ls): the default rasteriser.
openvdb::FloatGrid::Ptr particles_to_level_set(const float *x, const float *y, const float *z, size_t n,
                                               const fs_ls_build *b)
{
    openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(b->voxel, b->half_width);
    ParticleList pl{x, y, z, n, b->radius};
    openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
    raster.rasterizeSpheres(pl, b->radius);
    raster.finalize(true);
    return grid;
}

openvdb::FloatGrid::Ptr build(const float *x, const float *y, const float *z, size_t n, const fs_ls_build *b)
{
    openvdb::FloatGrid::Ptr grid = b->rasterizer == FS_LS_RASTER_PARTICLES ? particles_to_level_set(x, y, z, n, b)
                                                                           : fs_ls_points_rasterize(x, y, z, n, b);
    grid->setName("surface");
    if (b->dilate > 0 || b->smooth != FS_LS_SMOOTH_OFF || b->erode > 0) {
        openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
        if (b->dilate > 0) filter.offset(-b->dilate * b->voxel); // a negative offset grows the surface
        for (int i = 0; b->smooth != FS_LS_SMOOTH_OFF && i < b->smooth_iters; i++) {
            if (b->smooth == FS_LS_SMOOTH_GAUSSIAN) filter.gaussian(1);
            else filter.meanCurvature();
        }
        if (b->erode > 0) filter.offset(b->erode * b->voxel);
    }
    return grid;
}

} // namespace

extern "C" fs_ls_grid *fs_ls_grid_build(const float *x, const float *y, const float *z, size_t n, const fs_ls_build *b)
{
    fs_ls_grid *g = new (std::nothrow) fs_ls_grid;
    if (!g) {
        fs_fail(FS_ERR_RUNTIME, "levelset: out of memory");
        return nullptr;
    }
    try {
        openvdb::initialize();
        g->grid = build(x, y, z, n, b);
        g->active = g->grid->activeVoxelCount();
    } catch (const std::exception &e) {
        delete g;
        fs_fail(FS_ERR_RUNTIME, "levelset: OpenVDB level set: %s", e.what());
        return nullptr;
    }
    return g;
}

extern "C" uint64_t fs_ls_grid_active_voxels(const fs_ls_grid *g) { return g ? g->active : 0; }

extern "C" void fs_ls_grid_free(fs_ls_grid *g) { delete g; }

extern "C" int fs_ls_grid_write(const fs_ls_grid *g, const char *path)
{
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    try {
        openvdb::io::File file(tmp);
        file.write({g->grid});
        file.close();
    } catch (const std::exception &e) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot write VDB level set: %s", path, e.what());
    }
    return fs_output_end(path, tmp, 1);
}

extern "C" fs_ls_tracer *fs_ls_tracer_create(const fs_ls_grid *g)
{
    fs_ls_tracer *t = new (std::nothrow) fs_ls_tracer{nullptr, g->grid->voxelSize()[0]};
    if (!t) {
        fs_fail(FS_ERR_RUNTIME, "levelset: out of memory");
        return nullptr;
    }
    if (!g->active) return t;
    try {
        t->isect = new Intersector(*g->grid);
    } catch (const std::exception &e) {
        delete t;
        fs_fail(FS_ERR_RUNTIME, "levelset: OpenVDB ray intersector: %s", e.what());
        return nullptr;
    }
    return t;
}

extern "C" void fs_ls_tracer_free(fs_ls_tracer *t)
{
    if (!t) return;
    delete t->isect;
    delete t;
}

// Layers a thickness ray walks through at most (entries and exits).
#define FS_LS_MAX_LAYERS 256

extern "C" void fs_ls_trace(fs_ls_tracer *t, const float eye[3], const float dir[3], int thickness, fs_ls_hit *h)
{
    h->hit = 0;
    h->t = INFINITY;
    h->thick = 0;
    h->queries = 0;
    if (!t->isect) return;
    using Ray = openvdb::math::Ray<openvdb::Real>;
    const openvdb::Vec3R e(eye[0], eye[1], eye[2]);
    openvdb::Vec3R d(dir[0], dir[1], dir[2]);
    d.normalize(); // unit in double precision, as Ray::worldToIndex asserts
    openvdb::Vec3R xyz, nml;
    openvdb::Real t0;
    h->queries++;
    if (!t->isect->intersectsWS(Ray(e, d), xyz, nml, t0)) return;
    h->hit = 1;
    h->t = t0;
    for (int a = 0; a < 3; a++) h->n[a] = nml[a];
    if (!thickness) return;
    // (The overload intersectsWS(ray, time) of OpenVDB 10 reads the time before
    // it searches, so it returns the previous query's: the ones used here take
    // the position too and read the time after the search.)
    // March on from just past each crossing: the intersector reports the next
    // sign change of the SDF, an exit from inside, the next entry from outside.
    const double eps = 0.1 * t->voxel;
    double entry = t0, at = t0;
    for (int layer = 0; layer < FS_LS_MAX_LAYERS; layer++) {
        openvdb::Real t1;
        h->queries++;
        if (!t->isect->intersectsWS(Ray(e, d, at + eps), xyz, t1)) break; // no exit inside the grid's box
        h->thick += t1 - entry;
        h->queries++;
        if (!t->isect->intersectsWS(Ray(e, d, t1 + eps), xyz, entry)) break; // no further layer
        at = entry;
    }
}
