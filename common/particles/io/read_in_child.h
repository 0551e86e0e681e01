/* Reading a file with a library that may crash on a damaged one (VTK's XML reader,
 * OpenVDB): the read runs in a forked child process, which sends the particles back
 * through a pipe. A child that dies or corrupts its heap leaves this process whole,
 * and the file is refused in one line (docs/DESIGN.md, "Bad input"). */
#ifndef FS_READ_IN_CHILD_H
#define FS_READ_IN_CHILD_H
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Reads with read(p, path) in a child; what names the library and the format in the
 * message when the child fails ("damaged VDB file: OpenVDB's reader crashed on it").
 * On failure p holds nothing and fs_fail is set, with the child's own message when it
 * reported one. Without fork or pipe, reads in this process. */
int fs_read_in_child(fs_particles *p, const char *path, int (*read)(fs_particles *p, const char *path),
                     const char *what);

#ifdef __cplusplus
}
#endif
#endif
