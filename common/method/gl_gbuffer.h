/* The G-buffer's GL side: a GL method's render targets (gl/gl_target.h) read
 * back into the CPU fs_gbuffer. */
#ifndef FS_GL_GBUFFER_H
#define FS_GL_GBUFFER_H
#include "gbuffer.h"
#include "gl_target.h"
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Reads the targets into g (flipping rows: GL is bottom-up), sets coverage from
 * the normal's w and depth = INFINITY where uncovered. */
int fs_gl_target_read(const fs_gl_target *t, fs_gbuffer *g);

/* The same, timed as the stage "readback". */
int fs_gl_target_read_timed(const fs_gl_target *t, fs_gbuffer *g, fs_stages *st);
#ifdef __cplusplus
}
#endif
#endif
