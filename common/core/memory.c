/* Available memory from /proc/meminfo (Linux), with sysinfo as the fallback. */
#include "memory.h"
#include "fs_error.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/sysinfo.h>

static size_t env_limit(void)
{
    const char *s = getenv("FLUIDSURF_MEMORY_LIMIT");
    if (!s || !*s) return SIZE_MAX;
    char *end;
    double v = strtod(s, &end);
    double unit = *end == 'K' || *end == 'k' ? 1024.0
        : *end == 'M' || *end == 'm'         ? 1048576.0
        : *end == 'G' || *end == 'g'         ? 1073741824.0
                                             : 1.0;
    return v > 0 && v * unit < (double)SIZE_MAX ? (size_t)(v * unit) : SIZE_MAX;
}

size_t fs_memory_available(void)
{
    size_t avail = SIZE_MAX;
    FILE *f = fopen("/proc/meminfo", "r");
    char line[256];
    unsigned long long kb;
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %llu kB", &kb) == 1) avail = (size_t)kb * 1024;
    if (f) fclose(f);
    struct sysinfo si;
    if (avail == SIZE_MAX && sysinfo(&si) == 0) avail = (size_t)(si.freeram + si.bufferram) * si.mem_unit;
    size_t limit = env_limit();
    return limit < avail ? limit : avail;
}

/* "240.0 GB", "292.7 kB" */
static void human(char *buf, size_t size, double bytes)
{
    const char *unit[] = {"B", "kB", "MB", "GB", "TB"};
    int u = 0;
    while (bytes >= 1000 && u < 4) bytes /= 1000, u++;
    snprintf(buf, size, u ? "%.1f %s" : "%.0f %s", bytes, unit[u]);
}

int fs_memory_check(double bytes, const char *what)
{
    size_t avail = fs_memory_available();
    if (avail == SIZE_MAX || bytes <= (double)avail) return FS_OK;
    char need[32], have[32];
    human(need, sizeof need, bytes);
    human(have, sizeof have, (double)avail);
    return fs_fail(FS_ERR_RUNTIME, "%s need %s, but only %s are available", what, need, have);
}
