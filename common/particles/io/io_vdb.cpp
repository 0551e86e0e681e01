// Thin OpenVDB adapter for point data: reads every PointDataGrid in a .vdb
// (positions, plus a Vec3f "v" or "velocity" attribute), writes one grid named
// "points" with uncompressed float positions and velocity "v". The particle
// radius travels as grid metadata "radius". VDB stores points voxel by voxel,
// so the order of the particles changes on a round trip.
#include "particle_io.h"
#include "alloc_cap.h"
#include "fs_error.h"
#include "output_file.h"
#include "read_in_child.h"

#include <openvdb/openvdb.h>
#include <openvdb/io/Stream.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointCount.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/tools/PointIndexGrid.h>

#include <cmath>
#include <exception>
#include <fstream>
#include <memory>
#include <vector>

using openvdb::points::PointDataGrid;

namespace
{

// Index of a Vec3f attribute named "v" or "velocity" in leaf, or INVALID_POS.
size_t velocity_index(const openvdb::points::PointDataTree::LeafNodeType &leaf)
{
    const auto &desc = leaf.attributeSet().descriptor();
    for (const char *name : {"v", "velocity"}) {
        size_t i = desc.find(name);
        if (i != openvdb::points::AttributeSet::INVALID_POS &&
            desc.valueType(i) == openvdb::typeNameAsString<openvdb::Vec3f>())
            return i;
    }
    return openvdb::points::AttributeSet::INVALID_POS;
}

int read_grids(fs_particles *p, const char *path)
{
    // Read as a stream whose every short read throws: OpenVDB's readers do not check
    // the stream (a forged tile count loops 2^32 times on a failed stream), and
    // without delayed loading the whole file is read here and closed on return.
    std::ifstream in(path, std::ios::binary);
    if (!in) return fs_fail(FS_ERR_INPUT, "%s: cannot open", path);
    in.exceptions(std::ios::failbit | std::ios::badbit);
    openvdb::io::Stream stream(in, false);
    std::vector<PointDataGrid::Ptr> grids;
    for (const auto &g : *stream.getGrids())
        if (g->isType<PointDataGrid>()) grids.push_back(openvdb::gridPtrCast<PointDataGrid>(g));
    if (grids.empty()) return fs_fail(FS_ERR_INPUT, "%s: no point data grid in the VDB file", path);

    openvdb::Index64 total = 0;
    bool has_v = false;
    for (const auto &g : grids) {
        // counted leaf by leaf, on this thread: the child process has no thread pool
        for (auto leaf = g->tree().cbeginLeaf(); leaf; ++leaf) total += leaf->pointCount();
        for (auto leaf = g->tree().cbeginLeaf(); leaf && !has_v; ++leaf)
            has_v = velocity_index(*leaf) != openvdb::points::AttributeSet::INVALID_POS;
    }
    int rc = fs_particles_alloc(p, total, has_v ? FS_HAS_VELOCITY : 0);
    if (rc) return rc;
    size_t k = 0;
    for (const auto &g : grids) {
        if (auto r = g->getMetadata<openvdb::FloatMetadata>("radius")) p->radius = r->value();
        const openvdb::math::Transform &xform = g->transform();
        for (auto leaf = g->tree().cbeginLeaf(); leaf; ++leaf) {
            openvdb::points::AttributeHandle<openvdb::Vec3f> pos(leaf->constAttributeArray("P"));
            size_t vi = velocity_index(*leaf);
            std::unique_ptr<openvdb::points::AttributeHandle<openvdb::Vec3f>> vel;
            if (vi != openvdb::points::AttributeSet::INVALID_POS)
                vel.reset(new openvdb::points::AttributeHandle<openvdb::Vec3f>(leaf->constAttributeArray(vi)));
            for (auto idx = leaf->beginIndexOn(); idx && k < total; ++idx, ++k) {
                // Positions are stored relative to the voxel centre, in index space.
                openvdb::Vec3d w = xform.indexToWorld(idx.getCoord().asVec3d() + openvdb::Vec3d(pos.get(*idx)));
                p->x[k] = static_cast<float>(w.x());
                p->y[k] = static_cast<float>(w.y());
                p->z[k] = static_cast<float>(w.z());
                if (vel) {
                    openvdb::Vec3f v = vel->get(*idx);
                    p->vx[k] = v.x();
                    p->vy[k] = v.y();
                    p->vz[k] = v.z();
                }
            }
        }
    }
    p->n = k;
    return FS_OK;
}

void write_grid(const fs_particles *p, const char *tmp)
{
    std::vector<openvdb::Vec3d> pos(p->n);
    for (size_t i = 0; i < p->n; i++) pos[i] = openvdb::Vec3d(p->x[i], p->y[i], p->z[i]);
    openvdb::points::PointAttributeVector<openvdb::Vec3d> wrapper(pos);
    float voxel = openvdb::points::computeVoxelSize(wrapper, 8);
    if (!(voxel > 0.0f) || !std::isfinite(voxel)) voxel = 0.1f;
    auto xform = openvdb::math::Transform::createLinearTransform(voxel);
    auto index = openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(wrapper, *xform);
    auto grid =
        openvdb::points::createPointDataGrid<openvdb::points::NullCodec, PointDataGrid>(*index, wrapper, *xform);
    if (fs_particles_fields(p) & FS_HAS_VELOCITY) {
        std::vector<openvdb::Vec3f> vel(p->n);
        for (size_t i = 0; i < p->n; i++) vel[i] = openvdb::Vec3f(p->vx[i], p->vy[i], p->vz[i]);
        openvdb::points::appendAttribute<openvdb::Vec3f>(grid->tree(), "v");
        openvdb::points::populateAttribute(grid->tree(), index->tree(), "v",
                                           openvdb::points::PointAttributeVector<openvdb::Vec3f>(vel));
    }
    grid->setName("points");
    if (p->radius > 0) grid->insertMeta("radius", openvdb::FloatMetadata(p->radius));
    openvdb::io::File file(tmp);
    file.write({grid});
    file.close();
}

// The read itself, in this process: fs_fail set on failure, p freed then.
int read_here(fs_particles *p, const char *path)
{
    try {
        fs::AllocCap cap(path); // OpenVDB sizes buffers from the stream
        int rc = read_grids(p, path);
        if (rc) fs_particles_free(p);
        return rc;
    } catch (const std::ios_base::failure &) {
        fs_particles_free(p);
        return fs_fail(FS_ERR_INPUT, "%s: truncated or damaged VDB file (a read past its end)", path);
    } catch (const std::bad_alloc &) {
        fs_particles_free(p);
        return fs_fail(FS_ERR_INPUT,
                       "%s: OpenVDB asked for a buffer larger than the file can fill (a damaged or forged size)", path);
    } catch (const std::exception &e) {
        fs_particles_free(p);
        return fs_fail(FS_ERR_INPUT, "%s: cannot read VDB points: %s", path, e.what());
    }
}

} // namespace

// OpenVDB reads the file in a child process (docs/DESIGN.md, "Bad input"): OpenVDB 10
// writes past a buffer on a forged raw chunk size in its blosc reader (bloscFromStream,
// tests/fuzz/README.md), which no check of the bytes before the read can rule out. A
// child that corrupts its heap or dies leaves fluidsurf whole, and the file is refused.
extern "C" int fs_read_vdb(fs_particles *p, const char *path)
{
    try {
        openvdb::initialize(); // before the fork: the registry is the parent's, copied
    } catch (const std::exception &e) {
        return fs_fail(FS_ERR_RUNTIME, "OpenVDB: %s", e.what());
    }
    return fs_read_in_child(p, path, read_here, "damaged VDB file: OpenVDB's reader");
}

extern "C" int fs_write_vdb(const fs_particles *p, const char *path)
{
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    try {
        openvdb::initialize();
        write_grid(p, tmp);
    } catch (const std::exception &e) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot write VDB points: %s", path, e.what());
    }
    return fs_output_end(path, tmp, 1);
}
