/* Writers: a real frame with velocity (plus made-up colour, phase and radius)
 * written as VTK, BGEO, PLY and VDB reads back with the same particles; writes
 * leave no temporary files and fail cleanly where they cannot write. */
#include "fs_error.h"
#include "fs_test.h"
#include "particle_io.h"
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define DATA FS_TEST_DATA "/splashsurf/"

static double rel_tol(double v) { return 1e-6 * fmax(1.0, fabs(v)); }

/* Same order: VTK, BGEO and PLY keep the particle order. */
static void compare_ordered(const fs_particles *a, const fs_particles *b, const char *fmt, unsigned carried,
                            int has_radius)
{
    CHECK(b->n == a->n, "%s: %zu particles back, wrote %zu", fmt, b->n, a->n);
    CHECK((fs_particles_fields(b) & carried) == carried, "%s: fields %u back, expected %u", fmt, fs_particles_fields(b),
          carried);
    if (b->n != a->n || (fs_particles_fields(b) & carried) != carried) return;
    size_t bad_pos = 0, bad_attr = 0;
    for (size_t i = 0; i < a->n; i++) {
        bad_pos += fabs(a->x[i] - b->x[i]) > rel_tol(a->x[i]) || fabs(a->y[i] - b->y[i]) > rel_tol(a->y[i]) ||
            fabs(a->z[i] - b->z[i]) > rel_tol(a->z[i]);
        if (carried & FS_HAS_VELOCITY)
            bad_attr += fabs(a->vx[i] - b->vx[i]) > rel_tol(a->vx[i]) ||
                fabs(a->vy[i] - b->vy[i]) > rel_tol(a->vy[i]) || fabs(a->vz[i] - b->vz[i]) > rel_tol(a->vz[i]);
        if (carried & FS_HAS_COLOR)
            for (int k = 0; k < 3; k++) bad_attr += fabs(a->color[3 * i + k] - b->color[3 * i + k]) > 1e-6;
        if (carried & FS_HAS_PHASE) bad_attr += a->phase[i] != b->phase[i];
    }
    CHECK(bad_pos == 0, "%s: %zu positions differ", fmt, bad_pos);
    CHECK(bad_attr == 0, "%s: %zu attribute values differ", fmt, bad_attr);
    if (has_radius) CHECK_NEAR(b->radius, a->radius, 1e-7, fmt);
}

/* VDB reorders particles by voxel: match each one read back to the nearest original. */
static void compare_vdb(const fs_particles *a, const fs_particles *b)
{
    CHECK(b->n == a->n, "vdb: %zu particles back, wrote %zu", b->n, a->n);
    CHECK(b->vx != NULL, "vdb: velocity lost");
    if (b->n != a->n || !b->vx) return;
    double extent = 0;
    for (int k = 0; k < 3; k++) extent = fmax(extent, a->bmax[k] - a->bmin[k]);
    double tol = 1e-6 * extent, worst = 0, worst_v = 0;
    char *used = calloc(a->n, 1);
    size_t reused = 0;
    for (size_t i = 0; i < b->n; i++) {
        size_t best = 0;
        double bd = INFINITY;
        for (size_t j = 0; j < a->n; j++) {
            double dx = a->x[j] - b->x[i], dy = a->y[j] - b->y[i], dz = a->z[j] - b->z[i];
            double d = dx * dx + dy * dy + dz * dz;
            if (d < bd) {
                bd = d;
                best = j;
            }
        }
        reused += used[best]++ != 0;
        worst = fmax(worst, sqrt(bd));
        worst_v =
            fmax(worst_v, fabs(a->vx[best] - b->vx[i]) + fabs(a->vy[best] - b->vy[i]) + fabs(a->vz[best] - b->vz[i]));
    }
    free(used);
    CHECK(worst <= tol, "vdb: a position moved by %g (tol %g)", worst, tol);
    CHECK(reused == 0, "vdb: %zu particles matched twice", reused);
    CHECK(worst_v <= 1e-6, "vdb: velocity differs by %g", worst_v);
    CHECK_NEAR(b->radius, a->radius, 1e-7, "vdb radius metadata");
}

static int count_temp_files(void)
{
    int n = 0;
    DIR *d = opendir(FS_TEST_OUT);
    if (!d) return -1;
    for (struct dirent *e; (e = readdir(d));) n += e->d_name[0] == '.' && strstr(e->d_name, ".tmp") != NULL;
    closedir(d);
    return n;
}

int main(void)
{
    fs_particles src;
    int rc = fs_particles_read(&src, DATA "dam_break_frame_9_6859_particles.bgeo", NULL);
    CHECK(rc == FS_OK, "%s", fs_error_message());
    if (rc) TEST_DONE();
    CHECK(src.vx != NULL, "source frame has no velocity");
    /* Give it colour, phase and a radius so the writers have every attribute to carry. */
    fs_particles full;
    CHECK(fs_particles_alloc(&full, src.n, FS_HAS_VELOCITY | FS_HAS_COLOR | FS_HAS_PHASE) == FS_OK, "alloc");
    for (size_t i = 0; i < src.n; i++) {
        full.x[i] = src.x[i];
        full.y[i] = src.y[i];
        full.z[i] = src.z[i];
        full.vx[i] = src.vx[i];
        full.vy[i] = src.vy[i];
        full.vz[i] = src.vz[i];
        for (int k = 0; k < 3; k++) full.color[3 * i + k] = (float)((i * (k + 3)) % 17) / 16.0f;
        full.phase[i] = (int32_t)(i % 5) - 1;
    }
    full.radius = 0.025f;
    fs_particles_bounds(&full);
    int temps_before = count_temp_files();

    const struct {
        const char *file;
        unsigned carried;
        int radius;
    } ordered[] = {
        {"io_rt.vtk", FS_HAS_VELOCITY | FS_HAS_COLOR | FS_HAS_PHASE, 0},
        {"io_rt.bgeo.gz", FS_HAS_VELOCITY | FS_HAS_COLOR | FS_HAS_PHASE, 1},
        {"io_rt.ply", FS_HAS_VELOCITY | FS_HAS_COLOR | FS_HAS_PHASE, 1},
    };
    char path[512];
    for (size_t f = 0; f < sizeof ordered / sizeof ordered[0]; f++) {
        snprintf(path, sizeof path, "%s/%s", FS_TEST_OUT, ordered[f].file);
        for (int pass = 0; pass < 2; pass++) { /* the second pass overwrites the first file */
            rc = fs_particles_write(pass ? &full : &src, path, NULL);
            CHECK(rc == FS_OK, "write %s: %s", path, fs_error_message());
            fs_particles back;
            rc = rc ? rc : fs_particles_read(&back, path, NULL);
            CHECK(rc == FS_OK, "read back %s: %s", path, fs_error_message());
            if (rc) continue;
            compare_ordered(pass ? &full : &src, &back, ordered[f].file, pass ? ordered[f].carried : FS_HAS_VELOCITY,
                            pass ? ordered[f].radius : 0);
            fs_particles_free(&back);
        }
    }

    snprintf(path, sizeof path, "%s/io_rt.vdb", FS_TEST_OUT);
    rc = fs_particles_write(&full, path, NULL);
    CHECK(rc == FS_OK, "write vdb: %s", fs_error_message());
    fs_particles back;
    if (!rc && fs_particles_read(&back, path, NULL) == FS_OK) {
        compare_vdb(&full, &back);
        fs_particles_free(&back);
    } else {
        CHECK(0, "read back vdb: %s", fs_error_message());
    }

    /* A forced format beats the extension. */
    snprintf(path, sizeof path, "%s/io_rt_forced.dat", FS_TEST_OUT);
    rc = fs_particles_write(&src, path, "ply");
    CHECK(rc == FS_OK, "forced ply write: %s", fs_error_message());
    rc = rc ? rc : fs_particles_read(&back, path, "ply");
    CHECK(rc == FS_OK, "forced ply read: %s", fs_error_message());
    if (!rc) {
        compare_ordered(&src, &back, "forced ply", FS_HAS_VELOCITY, 0);
        fs_particles_free(&back);
    }

    /* Failures: no folder, unwritable format, empty set; nothing is left behind. */
    const char *missing = FS_TEST_OUT "/no_such_folder/x.vtk";
    CHECK(fs_particles_write(&src, missing, NULL) == FS_ERR_INPUT, "write into a missing folder");
    CHECK(strncmp(fs_error_message(), missing, strlen(missing)) == 0, "message: %s", fs_error_message());
    snprintf(path, sizeof path, "%s/io_rt.vtu", FS_TEST_OUT);
    CHECK(fs_particles_write(&src, path, NULL) == FS_ERR_INPUT, "vtu writing is not offered");
    CHECK(access(path, F_OK) != 0, "a refused write left %s", path);
    fs_particles empty = {0};
    snprintf(path, sizeof path, "%s/io_rt_empty.ply", FS_TEST_OUT);
    CHECK(fs_particles_write(&empty, path, NULL) == FS_ERR_INPUT, "writing no particles");
    CHECK(access(path, F_OK) != 0, "an empty write left %s", path);
    CHECK(count_temp_files() == temps_before, "temporary files left: %d (before %d)", count_temp_files(), temps_before);

    fs_particles_free(&full);
    fs_particles_free(&src);
    TEST_DONE();
}
