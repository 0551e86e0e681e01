/* fs_read_in_child (common/particles/io/read_in_child.h), the isolation the VTU and
 * VDB readers run in: every field a reader fills comes back unchanged through the
 * pipe; a reader's own refusal comes back as it was; a reader that crashes or exits
 * early leaves this process running, with one error line naming the file and an
 * empty particle set, and neither this process's crash handlers nor its sanitizer
 * death callback run in the child (a fuzzer's would save the input as its own
 * crash). The readers here are small functions that do exactly that. */
#include "fs_error.h"
#include "fs_test.h"
#include "read_in_child.h"
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define FS_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FS_TEST_ASAN 1
#endif
#endif
#ifdef FS_TEST_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

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

static int read_segfaulting(fs_particles *p, const char *path)
{
    read_all_fields(p, path);
    raise(SIGSEGV);
    return 0;
}

#ifdef FS_TEST_ASAN
/* A write past a buffer: the sanitizer reports it and the child exits. */
static int read_overflowing(fs_particles *p, const char *path)
{
    read_all_fields(p, path);
    volatile char *b = malloc(8);
    b[8] = 1;
    free((void *)b);
    return 0;
}
#endif

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
    CHECK(fs_read_in_child(&p, "pos.vtu", read_positions_only, "test reader") == FS_OK, "read: %s", fs_error_message());
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

/* What a fuzzer (libFuzzer) or a host application does on a crash: it records one
 * (libFuzzer writes the input as crash-*) and exits. In the child it must not run:
 * there the crash is the reader's, contained, and the parent reports it. */
static char marker[64];
static void host_records_crash(void)
{
    int fd = open(marker, O_WRONLY | O_CREAT, 0600);
    if (fd >= 0) close(fd);
}
static void host_crash_handler(int sig)
{
    (void)sig;
    host_records_crash();
    _exit(42);
}

static void test_host_crash_handling_stays_out(void)
{
    snprintf(marker, sizeof marker, "/tmp/fs_test_child_crash_%d", (int)getpid());
    unlink(marker);
    struct sigaction sa, old_abrt, old_segv;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = host_crash_handler;
    sigaction(SIGABRT, &sa, &old_abrt);
    sigaction(SIGSEGV, &sa, &old_segv);
    expect_refused(read_crashing, "test reader crashed on it (signal 6)");
    expect_refused(read_segfaulting, "test reader crashed on it (signal 11)");
#ifdef FS_TEST_ASAN
    __sanitizer_set_death_callback(host_records_crash);
    expect_refused(read_overflowing, "test reader failed on it");
    __sanitizer_set_death_callback(NULL);
#endif
    sigaction(SIGABRT, &old_abrt, NULL);
    sigaction(SIGSEGV, &old_segv, NULL);
    CHECK(access(marker, F_OK) != 0, "the parent's crash handling ran in the child (%s written)", marker);
    unlink(marker);
}

int main(void)
{
    test_fields_come_back();
    expect_refused(read_refusing, "the reader's own refusal");
    expect_refused(read_crashing, "test reader crashed on it (signal 6)");
    expect_refused(read_exiting, "test reader failed on it");
    test_host_crash_handling_stays_out();
    TEST_DONE();
}
