// Thin OpenVDB adapter of the mesh method (mesh_vdb.h): the leaves near the
// particles, found in parallel as a mask tree, become a float grid whose leaf
// buffers the C sampler fills; volumeToMesh meshes it.
#include "mesh_vdb.h"
#include "fs_error.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <new>
#include <vector>

using FloatLeaf = openvdb::FloatTree::LeafNodeType;
struct fs_mesh_volume {
    openvdb::FloatGrid::Ptr grid;
    std::vector<FloatLeaf *> leaves;
};

namespace {

// Touches, for every point, the leaves of its box grown by reach (one mask
// tree per task, joined by topology union).
struct TouchLeaves {
    const float *x, *y, *z;
    double cube, reach;
    openvdb::MaskTree tree;
    TouchLeaves(const float *x_, const float *y_, const float *z_, double c, double r)
        : x(x_), y(y_), z(z_), cube(c), reach(r) {}
    TouchLeaves(TouchLeaves &o, tbb::split) : x(o.x), y(o.y), z(o.z), cube(o.cube), reach(o.reach) {}
    void operator()(const tbb::blocked_range<size_t> &r)
    {
        openvdb::tree::ValueAccessor<openvdb::MaskTree> acc(tree);
        const int mask = ~(FS_MESH_LEAF - 1);
        for (size_t i = r.begin(); i != r.end(); i++) {
            double p[3] = {x[i], y[i], z[i]};
            int lo[3], hi[3];
            for (int a = 0; a < 3; a++) {
                lo[a] = (int)std::floor((p[a] - reach) / cube) & mask;
                hi[a] = (int)std::ceil((p[a] + reach) / cube);
            }
            for (int i0 = lo[0]; i0 <= hi[0]; i0 += FS_MESH_LEAF)
                for (int j0 = lo[1]; j0 <= hi[1]; j0 += FS_MESH_LEAF)
                    for (int k0 = lo[2]; k0 <= hi[2]; k0 += FS_MESH_LEAF)
                        acc.touchLeaf(openvdb::Coord(i0, j0, k0))->setValuesOn();
        }
    }
    void join(TouchLeaves &o) { tree.topologyUnion(o.tree); }
};

} // namespace

extern "C" fs_mesh_volume *fs_mesh_volume_create(const float *x, const float *y, const float *z, size_t n,
                                                 double cube, double reach, size_t max_leaves, size_t *need)
{
    fs_mesh_volume *v = nullptr;
    try {
        openvdb::initialize();
        TouchLeaves touch(x, y, z, cube, reach);
        tbb::parallel_reduce(tbb::blocked_range<size_t>(0, n, 4096), touch);
        size_t count = touch.tree.leafCount();
        if (max_leaves && count > max_leaves) {
            *need = count;
            return nullptr;
        }
        v = new fs_mesh_volume;
        openvdb::FloatTree::Ptr tree(new openvdb::FloatTree(touch.tree, 0.0f, openvdb::TopologyCopy()));
        touch.tree.clear();
        tree->voxelizeActiveTiles(); // a union may have merged full leaves into tiles
        v->grid = openvdb::FloatGrid::create(tree);
        v->grid->setTransform(openvdb::math::Transform::createLinearTransform(cube));
        v->grid->setName("density");
        v->leaves.reserve(tree->leafCount());
        tree->getNodes(v->leaves);
        return v;
    } catch (const std::bad_alloc &) {
        fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the sample volume (%zu particles)", n);
    } catch (const std::exception &e) {
        fs_fail(FS_ERR_RUNTIME, "mesh: OpenVDB: %s", e.what());
    }
    delete v;
    return nullptr;
}

extern "C" size_t fs_mesh_volume_leaves(const fs_mesh_volume *v) { return v->leaves.size(); }

extern "C" float *fs_mesh_volume_leaf(fs_mesh_volume *v, size_t i, int origin[3])
{
    FloatLeaf *l = v->leaves[i];
    for (int a = 0; a < 3; a++) origin[a] = l->origin()[a];
    return l->buffer().data();
}

extern "C" size_t fs_mesh_volume_bytes(const fs_mesh_volume *v) { return (size_t)v->grid->memUsage(); }

extern "C" int fs_mesh_volume_mesh(const fs_mesh_volume *v, double iso, fs_trimesh *out)
{
    *out = fs_trimesh{};
    try {
        std::vector<openvdb::Vec3s> pts;
        std::vector<openvdb::Vec4I> quads;
        openvdb::tools::volumeToMesh(*v->grid, pts, quads, iso);
        out->nv = pts.size();
        out->nt = 2 * quads.size();
        out->pos = (float *)std::malloc((out->nv ? out->nv : 1) * 3 * sizeof(float));
        out->tri = (uint32_t *)std::malloc((out->nt ? out->nt : 1) * 3 * sizeof(uint32_t));
        if (!out->pos || !out->tri) throw std::bad_alloc();
        for (size_t i = 0; i < pts.size(); i++)
            for (int a = 0; a < 3; a++) out->pos[3 * i + a] = pts[i][a];
        // volumeToMesh winds towards higher values; the density is higher inside
        for (size_t q = 0; q < quads.size(); q++) {
            const openvdb::Vec4I &c = quads[q];
            uint32_t t[6] = {c[0], c[2], c[1], c[0], c[3], c[2]};
            for (int k = 0; k < 6; k++) out->tri[6 * q + k] = t[k];
        }
        return FS_OK;
    } catch (const std::bad_alloc &) {
        fs_trimesh_free(out);
        return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the mesh");
    } catch (const std::exception &e) {
        fs_trimesh_free(out);
        return fs_fail(FS_ERR_RUNTIME, "mesh: OpenVDB volumeToMesh: %s", e.what());
    }
}

extern "C" void fs_mesh_volume_free(fs_mesh_volume *v) { delete v; }
