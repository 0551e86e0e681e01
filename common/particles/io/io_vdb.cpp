// Thin OpenVDB adapter for point data: reads every PointDataGrid in a .vdb
// (positions, plus a Vec3f "v" or "velocity" attribute), writes one grid named
// "points" with uncompressed float positions and velocity "v". The particle
// radius travels as grid metadata "radius". VDB stores points voxel by voxel,
// so the order of the particles changes on a round trip.
#include "particle_io.h"
#include "alloc_cap.h"
#include "fs_error.h"
#include "output_file.h"

#include <openvdb/openvdb.h>
#include <openvdb/io/Stream.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointCount.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/tools/PointIndexGrid.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

using openvdb::points::PointDataGrid;

namespace {

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
    auto grid = openvdb::points::createPointDataGrid<openvdb::points::NullCodec, PointDataGrid>(*index, wrapper, *xform);
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
        return fs_fail(FS_ERR_INPUT, "%s: OpenVDB asked for a buffer larger than the file can fill (a damaged or forged size)",
                       path);
    } catch (const std::exception &e) {
        fs_particles_free(p);
        return fs_fail(FS_ERR_INPUT, "%s: cannot read VDB points: %s", path, e.what());
    }
}

// What the child sends back before the arrays.
struct ChildResult {
    int32_t rc, has_v;
    uint64_t n;
    float radius;
    char msg[1024];
};

bool write_all(int fd, const void *buf, size_t size)
{
    const char *c = static_cast<const char *>(buf);
    while (size) {
        ssize_t k = write(fd, c, size);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        c += k, size -= static_cast<size_t>(k);
    }
    return true;
}

bool read_all(int fd, void *buf, size_t size)
{
    char *c = static_cast<char *>(buf);
    while (size) {
        ssize_t k = read(fd, c, size);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        c += k, size -= static_cast<size_t>(k);
    }
    return true;
}

// The child: reads, sends the result and the arrays down fd, and ends without
// running the parent's exit handlers. Its stderr is closed: a library that corrupts
// its heap may print there, and the parent owns the one error line.
[[noreturn]] void child_read(int fd, const char *path)
{
    int null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, STDERR_FILENO);
    fs_particles p;
    ChildResult res{};
    res.rc = read_here(&p, path);
    if (res.rc) snprintf(res.msg, sizeof res.msg, "%s", fs_error_message());
    else res.n = p.n, res.has_v = p.vx != nullptr, res.radius = p.radius;
    bool ok = write_all(fd, &res, sizeof res);
    const float *cols[] = {p.x, p.y, p.z, p.vx, p.vy, p.vz};
    for (int c = 0; ok && !res.rc && c < (res.has_v ? 6 : 3); c++) ok = write_all(fd, cols[c], p.n * sizeof(float));
    _exit(ok ? 0 : 3);
}

// The parent: the child's result into p (FS_OK), or a refusal naming path.
int receive(int fd, pid_t pid, fs_particles *p, const char *path)
{
    ChildResult res{};
    bool ok = read_all(fd, &res, sizeof res);
    int rc = FS_OK;
    if (ok && res.rc) rc = fs_fail(res.rc, "%.1000s", res.msg);
    else if (ok && !(rc = fs_particles_alloc(p, res.n, res.has_v ? FS_HAS_VELOCITY : 0))) {
        float *cols[] = {p->x, p->y, p->z, p->vx, p->vy, p->vz};
        for (int c = 0; ok && c < (res.has_v ? 6 : 3); c++) ok = read_all(fd, cols[c], res.n * sizeof(float));
        p->radius = res.radius;
        if (!ok) fs_particles_free(p);
    }
    close(fd);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (rc) return rc;
    if (!ok || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        if (ok) fs_particles_free(p);
        if (WIFSIGNALED(status))
            return fs_fail(FS_ERR_INPUT, "%s: damaged VDB file: OpenVDB's reader crashed on it (signal %d)", path,
                           WTERMSIG(status));
        return fs_fail(FS_ERR_INPUT, "%s: damaged VDB file: OpenVDB's reader failed on it", path);
    }
    return FS_OK;
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
    int fd[2];
    if (pipe(fd)) return read_here(p, path); // no pipe: read in place, unprotected
    pid_t pid = fork();
    if (pid < 0) {
        close(fd[0]), close(fd[1]);
        return read_here(p, path);
    }
    if (pid == 0) {
        close(fd[0]);
        child_read(fd[1], path);
    }
    close(fd[1]);
    return receive(fd[0], pid, p, path);
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
