/* What this machine can hold, for refusing work up front instead of failing midway. */
#ifndef FS_MEMORY_H
#define FS_MEMORY_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Bytes the process can still allocate without swapping: MemAvailable of
 * /proc/meminfo, else sysinfo's free RAM; FLUIDSURF_MEMORY_LIMIT (bytes, or with a
 * K/M/G suffix) lowers it. SIZE_MAX when nothing can be read. */
size_t fs_memory_available(void);
/* FS_OK, or FS_ERR_RUNTIME with "WHAT need X GB, but only Y GB are available" when
 * bytes exceed fs_memory_available(). */
int fs_memory_check(double bytes, const char *what);

#ifdef __cplusplus
}
#endif
#endif
