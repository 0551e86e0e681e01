/* A file named relative to another file's folder (a scene's particles, its mesh solids). */
#ifndef FS_PATH_BESIDE_H
#define FS_PATH_BESIDE_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* out = file when it is absolute or base has no folder, else base's folder + "/" + file.
 * 0 when it fits in size bytes, -1 when it does not. */
int fs_path_beside(const char *base, const char *file, char *out, size_t size);

#ifdef __cplusplus
}
#endif
#endif
