#include "output_file.h"
#include "fs_error.h"
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* The temporaries in progress, for fs_output_abandon_all (from a signal handler:
 * it reads the slots without the lock, and a slot is marked used only once its
 * path is complete). */
#define MAX_LIVE 64
static struct {
    char path[4096];
    volatile sig_atomic_t used;
} live[MAX_LIVE];
static pthread_mutex_t live_lock = PTHREAD_MUTEX_INITIALIZER;

static void remember(const char *tmp)
{
    pthread_mutex_lock(&live_lock);
    for (int i = 0; i < MAX_LIVE; i++)
        if (!live[i].used && strlen(tmp) < sizeof live[i].path) {
            strcpy(live[i].path, tmp);
            live[i].used = 1;
            break;
        }
    pthread_mutex_unlock(&live_lock);
}

static void forget(const char *tmp)
{
    pthread_mutex_lock(&live_lock);
    for (int i = 0; i < MAX_LIVE; i++)
        if (live[i].used && strcmp(live[i].path, tmp) == 0) {
            live[i].used = 0;
            break;
        }
    pthread_mutex_unlock(&live_lock);
}

void fs_output_abandon_all(void)
{
    for (int i = 0; i < MAX_LIVE; i++)
        if (live[i].used) unlink(live[i].path);
}

int fs_output_begin(const char *final, char *tmp, int size)
{
    const char *slash = strrchr(final, '/');
    int dirlen = slash ? (int)(slash - final) + 1 : 0;
    if (!final[dirlen]) return fs_fail(FS_ERR_INPUT, "%s: output path names a folder", final);
    struct stat st;
    if (stat(final, &st) == 0 && S_ISDIR(st.st_mode))
        return fs_fail(FS_ERR_INPUT, "%s: output path is a folder", final);
    /* the rename would replace a device node or FIFO (run as root, /dev/null itself) */
    if (stat(final, &st) == 0 && !S_ISREG(st.st_mode))
        return fs_fail(FS_ERR_INPUT, "%s: not a regular file; outputs replace only regular files", final);
    if (snprintf(tmp, size, "%.*s.%s.tmpXXXXXX", dirlen, final, final + dirlen) >= size)
        return fs_fail(FS_ERR_INPUT, "%s: output path too long", final);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        int e = errno;
        tmp[0] = 0;
        return fs_fail(FS_ERR_INPUT, "%s: cannot write there: %s", final, strerror(e));
    }
    fchmod(fd, 0644);
    close(fd);
    remember(tmp);
    return FS_OK;
}

int fs_output_end(const char *final, const char *tmp, int ok)
{
    if (!tmp[0]) return ok ? fs_fail(FS_ERR_RUNTIME, "%s: no temporary file", final) : FS_OK;
    /* forgotten only once gone or renamed: a signal in between finds nothing to remove */
    if (!ok) {
        unlink(tmp);
        forget(tmp);
        return FS_OK;
    }
    int moved = rename(tmp, final) == 0, e = errno;
    if (!moved) unlink(tmp);
    forget(tmp);
    return moved ? FS_OK : fs_fail(FS_ERR_RUNTIME, "%s: cannot rename output: %s", final, strerror(e));
}

int fs_output_open(fs_output *o, const char *final)
{
    o->f = NULL;
    if (snprintf(o->final, sizeof o->final, "%s", final) >= (int)sizeof o->final)
        return fs_fail(FS_ERR_INPUT, "%.200s...: output path too long", final);
    int rc = fs_output_begin(final, o->tmp, sizeof o->tmp);
    if (rc) return rc;
    if ((o->f = fopen(o->tmp, "wb"))) return FS_OK;
    int e = errno;
    fs_output_end(final, o->tmp, 0);
    return fs_fail(FS_ERR_RUNTIME, "%s: cannot write: %s", final, strerror(e));
}

int fs_output_close(fs_output *o, int ok)
{
    int e = 0;
    if (ferror(o->f) || fflush(o->f) != 0) e = errno ? errno : EIO;
    if (fclose(o->f) != 0 && !e) e = errno ? errno : EIO;
    o->f = NULL;
    if (ok && !e) return fs_output_end(o->final, o->tmp, 1);
    fs_output_end(o->final, o->tmp, 0);
    /* ok 0 without a stream error: the caller failed and its message stands */
    return e ? fs_fail(FS_ERR_RUNTIME, "%s: cannot write: %s", o->final, strerror(e)) : FS_ERR_RUNTIME;
}

int fs_path_ends_with(const char *path, const char *suffix)
{
    size_t n = strlen(path), m = strlen(suffix);
    return n >= m && strcasecmp(path + n - m, suffix) == 0;
}
