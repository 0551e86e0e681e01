#include "path_beside.h"
#include <stdio.h>
#include <string.h>

int fs_path_beside(const char *base, const char *file, char *out, size_t size)
{
    const char *slash = strrchr(base, '/');
    int n = file[0] != '/' && slash ? snprintf(out, size, "%.*s/%s", (int)(slash - base), base, file)
                                    : snprintf(out, size, "%s", file);
    return n >= 0 && (size_t)n < size ? 0 : -1;
}
