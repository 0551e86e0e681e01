// Thin OpenVDB adapter of the mesh method (mesh_vdb.h): the leaves near the
// particles are found in parallel as a mask tree; the C sampler fills them slab
// by slab into plain buffers, and the leaves the surface can cross go into a
// float grid, the others become tiles; volumeToMesh meshes it.
#include "mesh_vdb.h"
#include "fs_error.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <unordered_map>
#include <vector>

using FloatLeaf = openvdb::FloatTree::LeafNodeType;
// Per leaf: the minimum of all its values, then of its faces -x, +x, -y, +y, -z, +z.
using LeafMins = std::array<float, 7>;

struct fs_mesh_volume {
    openvdb::FloatGrid::Ptr grid;
    std::vector<int> origin;                    // 3 per leaf, sorted by x, then y, then z
    std::vector<size_t> slab;                   // slab s: leaves slab[s] .. slab[s + 1] - 1
    std::vector<LeafMins> mins;                 // per leaf, once its slab is filled
    std::unordered_map<uint64_t, size_t> index; // leaf lattice position -> leaf
    std::vector<std::vector<float>> buf;        // per slab, alive while it or its neighbour is undecided
    float iso;
    bool keep_all;
    double cube, mem_limit;
    size_t kept = 0;
};

namespace
{

// Touches, for every point, the leaves of its box grown by reach (one mask
// tree per task, joined by topology union).
struct TouchLeaves {
    const float *x, *y, *z;
    double cube, reach;
    openvdb::MaskTree tree;
    TouchLeaves(const float *x_, const float *y_, const float *z_, double c, double r)
        : x(x_), y(y_), z(z_), cube(c), reach(r)
    {
    }
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

namespace
{

uint64_t lattice_key(const int *o)
{
    uint64_t k = 0;
    for (int a = 0; a < 3; a++) k = k << 21 | ((uint64_t)(o[a] / FS_MESH_LEAF) & 0x1fffff);
    return k;
}

LeafMins mins_of(const float *b)
{
    const int L = FS_MESH_LEAF;
    LeafMins m;
    m.fill(INFINITY);
    for (int x = 0; x < L; x++)
        for (int y = 0; y < L; y++)
            for (int z = 0; z < L; z++) {
                float v = b[(x * L + y) * L + z];
                m[0] = std::min(m[0], v);
                if (x == 0) m[1] = std::min(m[1], v);
                if (x == L - 1) m[2] = std::min(m[2], v);
                if (y == 0) m[3] = std::min(m[3], v);
                if (y == L - 1) m[4] = std::min(m[4], v);
                if (z == 0) m[5] = std::min(m[5], v);
                if (z == L - 1) m[6] = std::min(m[6], v);
            }
    return m;
}

// 1 when no edge of leaf i's voxels crosses iso: it is inside, and so is the
// facing layer of each face neighbour (a missing one is background, outside).
bool interior(const fs_mesh_volume *v, size_t i)
{
    if (!(v->mins[i][0] > v->iso)) return false;
    const int *o = &v->origin[3 * i];
    for (int a = 0; a < 3; a++)
        for (int side = 0; side < 2; side++) {
            int n[3] = {o[0], o[1], o[2]};
            n[a] += side ? FS_MESH_LEAF : -FS_MESH_LEAF;
            auto it = v->index.find(lattice_key(n));
            if (it == v->index.end() || !(v->mins[it->second][1 + 2 * a + (1 - side)] > v->iso)) return false;
        }
    return true;
}

// Slab s: its surface leaves into the grid, the others as tiles; frees its buffer.
void decide(fs_mesh_volume *v, size_t s)
{
    openvdb::tree::ValueAccessor<openvdb::FloatTree> acc(v->grid->tree());
    const float *b = v->buf[s].data();
    for (size_t i = v->slab[s]; i < v->slab[s + 1]; i++, b += FS_MESH_LEAF3) {
        openvdb::Coord c(v->origin[3 * i], v->origin[3 * i + 1], v->origin[3 * i + 2]);
        if (!v->keep_all && interior(v, i)) {
            acc.addTile(1, c, v->mins[i][0], true);
            continue;
        }
        FloatLeaf *leaf = new FloatLeaf(c, 0.0f, true);
        std::memcpy(leaf->buffer().data(), b, FS_MESH_LEAF3 * sizeof(float));
        acc.addLeaf(leaf);
        v->kept++;
    }
    std::vector<float>().swap(v->buf[s]);
}

} // namespace

extern "C" fs_mesh_volume *fs_mesh_volume_create(const float *x, const float *y, const float *z, size_t n, double cube,
                                                 double reach, double iso, int keep_all, double mem_limit, size_t *need)
{
    fs_mesh_volume *v = nullptr;
    try {
        openvdb::initialize();
        TouchLeaves touch(x, y, z, cube, reach);
        tbb::parallel_reduce(tbb::blocked_range<size_t>(0, n, 4096), touch);
        touch.tree.voxelizeActiveTiles(); // a union may have merged full leaves into tiles
        size_t count = touch.tree.leafCount();
        if (mem_limit > 0 && (double)count * FS_MESH_INDEX_BYTES > mem_limit) {
            *need = count;
            return nullptr;
        }
        v = new fs_mesh_volume;
        v->iso = (float)iso;
        v->keep_all = keep_all != 0;
        v->cube = cube;
        v->mem_limit = mem_limit;
        std::vector<std::array<int, 3>> org;
        org.reserve(count);
        for (auto it = touch.tree.cbeginLeaf(); it; ++it)
            org.push_back({it->origin()[0], it->origin()[1], it->origin()[2]});
        touch.tree.clear();
        std::sort(org.begin(), org.end());
        v->origin.resize(3 * count);
        v->index.reserve(count);
        for (size_t i = 0; i < count; i++) {
            std::memcpy(&v->origin[3 * i], org[i].data(), sizeof org[i]);
            v->index.emplace(lattice_key(org[i].data()), i);
            if (i == 0 || org[i][0] != org[i - 1][0]) v->slab.push_back(i);
        }
        v->slab.push_back(count);
        v->mins.resize(count);
        v->buf.resize(v->slab.size() - 1);
        v->grid = openvdb::FloatGrid::create(0.0f);
        v->grid->setTransform(openvdb::math::Transform::createLinearTransform(cube));
        v->grid->setName("density");
        return v;
    } catch (const std::bad_alloc &) {
        fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the sample volume (%zu particles)", n);
    } catch (const std::exception &e) {
        fs_fail(FS_ERR_RUNTIME, "mesh: OpenVDB: %s", e.what());
    }
    delete v;
    return nullptr;
}

extern "C" size_t fs_mesh_volume_leaves(const fs_mesh_volume *v) { return v->origin.size() / 3; }
extern "C" size_t fs_mesh_volume_slabs(const fs_mesh_volume *v) { return v->slab.size() - 1; }
extern "C" size_t fs_mesh_volume_kept(const fs_mesh_volume *v) { return v->kept; }

extern "C" float *fs_mesh_volume_slab(fs_mesh_volume *v, size_t s, size_t *count, const int **origins)
{
    *count = v->slab[s + 1] - v->slab[s];
    *origins = &v->origin[3 * v->slab[s]];
    size_t leaves = fs_mesh_volume_leaves(v), before = s ? v->slab[s] - v->slab[s - 1] : 0;
    double held = (double)leaves * FS_MESH_INDEX_BYTES + (double)v->kept * FS_MESH_LEAF_BYTES +
        (double)(*count + before) * FS_MESH_LEAF3 * sizeof(float);
    if (v->mem_limit > 0 && held > v->mem_limit) {
        // the kept surface grows about as 1 / cube^2: extrapolate it to the whole volume
        double total = (double)leaves * FS_MESH_INDEX_BYTES +
            (double)v->kept * FS_MESH_LEAF_BYTES * (double)fs_mesh_volume_slabs(v) / (double)(s ? s : 1);
        fs_fail(
            FS_ERR_INPUT,
            "mesh: cube %g: the surface needs more than the %.3g GB available (%zu leaves kept after %zu of %zu slabs): use cube >= %.3g",
            v->cube, v->mem_limit / 1e9, v->kept, s, fs_mesh_volume_slabs(v),
            v->cube * std::sqrt(std::max(total, held) / v->mem_limit) * 1.1);
        return nullptr;
    }
    try {
        v->buf[s].assign(*count * FS_MESH_LEAF3, 0.0f);
        return v->buf[s].data();
    } catch (const std::bad_alloc &) {
        fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for a slab of %zu leaves", *count);
        return nullptr;
    }
}

extern "C" int fs_mesh_volume_slab_done(fs_mesh_volume *v, size_t s)
{
    try {
        const float *b = v->buf[s].data();
        for (size_t i = v->slab[s]; i < v->slab[s + 1]; i++, b += FS_MESH_LEAF3) v->mins[i] = mins_of(b);
        // slab s - 1's x neighbours (s - 2 and s) are filled now; the last slab has none after it
        if (s > 0) decide(v, s - 1);
        if (s + 1 == fs_mesh_volume_slabs(v)) decide(v, s);
        return FS_OK;
    } catch (const std::bad_alloc &) {
        return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the sample volume's leaves");
    } catch (const std::exception &e) {
        return fs_fail(FS_ERR_RUNTIME, "mesh: OpenVDB: %s", e.what());
    }
}

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
