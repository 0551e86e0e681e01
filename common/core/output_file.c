#include "output_file.h"
#include "fs_error.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

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
    return FS_OK;
}

int fs_output_end(const char *final, const char *tmp, int ok)
{
    if (!tmp[0]) return ok ? fs_fail(FS_ERR_RUNTIME, "%s: no temporary file", final) : FS_OK;
    if (!ok) { unlink(tmp); return FS_OK; }
    if (rename(tmp, final) != 0) {
        int e = errno;
        unlink(tmp);
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot rename output: %s", final, strerror(e));
    }
    return FS_OK;
}

int fs_path_ends_with(const char *path, const char *suffix)
{
    size_t n = strlen(path), m = strlen(suffix);
    return n >= m && strcasecmp(path + n - m, suffix) == 0;
}
