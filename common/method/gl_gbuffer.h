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

enum { FS_GL_TARGET_MAX_EXTRA = 4 };

/* Reads the layers g holds and no others (depth, normal, thickness, and colour
 * when g has that layer), plus the caller's extra textures of the same size
 * (an own image), in one batch through t's pixel pack buffers (gl_readback.h),
 * flipping rows (GL is bottom-up); then sets coverage from the normal's w, the
 * normal to unit length and depth = INFINITY where uncovered. Adds the stages
 * "readback" (the transfers and copies) and "renormalize" (the CPU pass over
 * the normals) to st, which may be NULL. */
int fs_gl_target_read(fs_gl_target *t, fs_gbuffer *g, const fs_gl_read *extra, int nextra, fs_stages *st);
#ifdef __cplusplus
}
#endif
#endif
