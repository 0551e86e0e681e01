/* fs_read_in_child (common/particles/io/read_in_child.h), the isolation the VTU and
 * VDB readers run in: every field a reader fills comes back unchanged through the
 * pipe; a reader's own refusal comes back as it was; a reader that crashes or exits
 * early leaves this process running, with one error line naming the file and an
 * empty particle set. The readers here are small functions that do exactly that. */
#include "fs_error.h"
#include "fs_test.h"
#include "read_in_child.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define N 5000

static int read_all_fields(fs_particles *p, const char *path)
{
    (void)path;
    int rc = fs_particles_alloc(p, N, FS_HAS_VELOCITY | FS_HAS_COLOR | FS_HAS_PHASE);
    for (size_t i = 0; !rc && i < N; i++) {
        p->x[i] = (float)i, p->y[i] = -(float)i, p->z[i] = 0.5f * (float)i;
        p->vx[i] = 1, p->vy[i] = 2, p->vz[i] = (float)i / N;
        for (int k = 0; k < 3; k++) p->color[3 * i + k] = (float)k / 3;
        p->phase[i] = (int32_t)(i % 7) - 3;
    }
    p->radius = 0.0125f;
    return rc;
}

static int read_positions_only(fs_particles *p, const char *path)
{
    (void)path;
    int rc = fs_particles_alloc(p, 3, 0);
    if (!rc) p->x[2] = 7;
    return rc;
}

static int read_refusing(fs_particles *p, const char *path)
{
    (void)p;
    return fs_fail(FS_ERR_INPUT, "%s: the reader's own refusal", path);
}

/* glibc aborts so on a heap it finds corrupted (the sanitizers leave SIGABRT alone) */
static int read_crashing(fs_particles *p, const char *path)
{
    read_all_fields(p, path);
    abort();
}

static int read_exiting(fs_particles *p, const char *path)
{
    read_all_fields(p, path);
    _exit(1); /* as a sanitizer does after its report */
}

static void test_fields_come_back(void)
{
    fs_particles p;
    memset(&p, 0, sizeof p);
    fs_particles ref;
    memset(&ref, 0, sizeof ref);
    CHECK(fs_read_in_child(&p, "all.vtu", read_all_fields, "test reader") == FS_OK, "read: %s", fs_error_message());
    read_all_fields(&ref, "all.vtu");
    CHECK(p.n == N && fs_particles_fields(&p) == fs_particles_fields(&ref), "n %zu, fields %u", p.n,
          fs_particles_fields(&p));
    int same = p.n == N;
    for (size_t i = 0; same && i < N; i++)
        same = p.x[i] == ref.x[i] && p.y[i] == ref.y[i] && p.z[i] == ref.z[i] && p.vx[i] == ref.vx[i] &&
               p.vy[i] == ref.vy[i] && p.vz[i] == ref.vz[i] && p.phase[i] == ref.phase[i] &&
               !memcmp(p.color + 3 * i, ref.color + 3 * i, 3 * sizeof(float));
    CHECK(same, "a field changed on its way through the pipe");
    CHECK(p.radius == 0.0125f, "radius %g", p.radius);
    fs_particles_free(&p);
    fs_particles_free(&ref);
    CHECK(fs_read_in_child(&p, "pos.vtu", read_positions_only, "test reader") == FS_OK, "read: %s",
          fs_error_message());
    CHECK(p.n == 3 && p.x[2] == 7 && !p.vx && !p.color && !p.phase, "positions only: n %zu", p.n);
    fs_particles_free(&p);
}

static void expect_refused(int (*reader)(fs_particles *, const char *), const char *want)
{
    fs_particles p;
    memset(&p, 0, sizeof p);
    fs_error_clear();
    int rc = fs_read_in_child(&p, "bad.vtu", reader, "test reader");
    const char *msg = fs_error_message();
    CHECK(rc == FS_ERR_INPUT, "rc %d for '%s'", rc, want);
    CHECK(strncmp(msg, "bad.vtu: ", 9) == 0 && strstr(msg, want) && !strchr(msg, '\n'), "message '%s', want '%s'", msg,
          want);
    CHECK(p.n == 0 && !p.x, "a refused read left %zu particles", p.n);
}

int main(void)
{
    test_fields_come_back();
    expect_refused(read_refusing, "the reader's own refusal");
    expect_refused(read_crashing, "test reader crashed on it (signal 6)");
    expect_refused(read_exiting, "test reader failed on it");
    TEST_DONE();
}
