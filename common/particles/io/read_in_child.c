/* fs_read_in_child: the child reads and writes a header, then every array it has
 * and its point arrays (particle_arrays.h), each after a description, down a
 * pipe; the parent allocates from the header and reads them back. */
#include "read_in_child.h"
#include "fs_error.h"
#include "particle_arrays.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* What the child sends before the arrays. */
typedef struct {
    int32_t rc;
    uint32_t fields;
    uint64_t n;
    float radius;
    int32_t narrays;
    char msg[1024];
} child_result;

/* What the child sends before each point array's values. */
typedef struct {
    char name[64];
    int32_t ncomp, type;
} array_head;

static int write_all(int fd, const void *buf, size_t size)
{
    const char *c = buf;
    while (size) {
        ssize_t k = write(fd, c, size);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return 0;
        c += k, size -= (size_t)k;
    }
    return 1;
}

static int read_all(int fd, void *buf, size_t size)
{
    char *c = buf;
    while (size) {
        ssize_t k = read(fd, c, size);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return 0;
        c += k, size -= (size_t)k;
    }
    return 1;
}

/* p's arrays in a fixed order, with their sizes in bytes (0 for an absent one). */
static int arrays_of(const fs_particles *p, void *ptr[8], size_t bytes[8])
{
    void *a[8] = {p->x, p->y, p->z, p->vx, p->vy, p->vz, p->color, p->phase};
    size_t per[8] = {4, 4, 4, 4, 4, 4, 12, 4};
    for (int i = 0; i < 8; i++) ptr[i] = a[i], bytes[i] = a[i] ? per[i] * p->n : 0;
    return 8;
}

/* The sanitizers' death callback (set by libFuzzer); absent outside sanitized builds. */
extern void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

/* A crash in the child is contained by design: the parent refuses the file. The
 * parent's own crash handling must not run for it: a fuzzer's (libFuzzer's signal
 * handlers, and the death callback it gives the sanitizers, which runs after a memory
 * error's report) would save the input as the fuzzer's crash-* finding, and a host
 * application's handler would report a crash of its own. So the child dies by the
 * default action of each crash signal, or exits after a sanitizer's report. */
static void child_crash_handling(void)
{
    static const int sigs[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
    for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++) signal(sigs[i], SIG_DFL);
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(NULL);
}

/* The child: reads, sends, and ends without the parent's exit handlers. Its stderr
 * goes to /dev/null: a library that corrupts its heap may print there, and the
 * parent owns the one error line. FLUIDSURF_CHILD_STDERR=1 keeps it, to see what the
 * library printed or a sanitizer reported before the child died. */
static void child_read(int fd, const char *path, int (*read_fn)(fs_particles *, const char *))
{
    child_crash_handling();
    const char *keep = getenv("FLUIDSURF_CHILD_STDERR");
    int null = keep && !strcmp(keep, "1") ? -1 : open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, STDERR_FILENO);
    fs_particles p;
    memset(&p, 0, sizeof p);
    child_result res;
    memset(&res, 0, sizeof res);
    res.rc = read_fn(&p, path);
    if (res.rc) snprintf(res.msg, sizeof res.msg, "%s", fs_error_message());
    else res.n = p.n, res.fields = fs_particles_fields(&p), res.radius = p.radius, res.narrays = p.narrays;
    int ok = write_all(fd, &res, sizeof res);
    void *ptr[8];
    size_t bytes[8];
    for (int i = 0, k = arrays_of(&p, ptr, bytes); ok && !res.rc && i < k; i++)
        if (bytes[i]) ok = write_all(fd, ptr[i], bytes[i]);
    for (int i = 0; ok && !res.rc && i < p.narrays; i++) {
        const fs_point_array *a = &p.arrays[i];
        array_head h = {"", a->ncomp, (int32_t)a->type};
        memcpy(h.name, a->name, sizeof h.name);
        ok =
            write_all(fd, &h, sizeof h) && write_all(fd, a->data, p.n * (size_t)a->ncomp * fs_array_type_size(a->type));
    }
    _exit(ok ? 0 : 3);
}

/* The point arrays after the particles: 1 when all came, else 0 (the pipe ran dry,
 * or one could not be held: *rc then says why). */
static int receive_arrays(int fd, fs_particles *p, int narrays, int *rc)
{
    for (int i = 0; i < narrays; i++) {
        array_head h;
        fs_point_array *a;
        if (!read_all(fd, &h, sizeof h)) return 0;
        h.name[sizeof h.name - 1] = 0;
        if (h.type < FS_ARRAY_F32 || h.type > FS_ARRAY_U32) return 0;
        if ((*rc = fs_particles_add_array(p, h.name, h.ncomp, (fs_array_type)h.type, &a))) return 0;
        if (!read_all(fd, a->data, p->n * (size_t)a->ncomp * fs_array_type_size(a->type))) return 0;
    }
    return 1;
}

/* The parent: the child's particles into p (FS_OK), the child's own refusal, this
 * process's allocation failure, or -1 when the pipe ran dry (the child died). */
static int receive(int fd, fs_particles *p, child_result *res)
{
    if (!read_all(fd, res, sizeof *res)) return -1;
    if (res->rc) return res->rc;
    int rc = fs_particles_alloc(p, (size_t)res->n, res->fields);
    if (rc) return rc;
    void *ptr[8];
    size_t bytes[8];
    int ok = 1;
    for (int i = 0, k = arrays_of(p, ptr, bytes); ok && i < k; i++)
        if (bytes[i]) ok = read_all(fd, ptr[i], bytes[i]);
    p->radius = res->radius;
    if (ok) ok = receive_arrays(fd, p, res->narrays, &rc);
    if (ok) return FS_OK;
    fs_particles_free(p);
    return rc ? rc : -1;
}

int fs_read_in_child(fs_particles *p, const char *path, int (*read_fn)(fs_particles *, const char *), const char *what)
{
    int fd[2];
    if (pipe(fd)) return read_fn(p, path); /* no pipe: read in place, unprotected */
    pid_t pid = fork();
    if (pid < 0) {
        close(fd[0]), close(fd[1]);
        return read_fn(p, path);
    }
    if (pid == 0) {
        close(fd[0]);
        child_read(fd[1], path, read_fn);
    }
    close(fd[1]);
    child_result res;
    memset(&res, 0, sizeof res);
    int rc = receive(fd[0], p, &res);
    close(fd[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (rc == FS_OK && WIFEXITED(status) && WEXITSTATUS(status) == 0) return FS_OK;
    if (rc == FS_OK) fs_particles_free(p);
    if (res.rc) return fs_fail(res.rc, "%.1000s", res.msg);
    if (rc > 0) return rc; /* our own allocation failed; its message is set */
    if (WIFSIGNALED(status))
        return fs_fail(FS_ERR_INPUT, "%s: %s crashed on it (signal %d)", path, what, WTERMSIG(status));
    return fs_fail(FS_ERR_INPUT, "%s: %s failed on it", path, what);
}
