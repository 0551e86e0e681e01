/* Timing a GL stage on the wall clock (timing.h: llvmpipe timer queries are not
 * trustworthy): start = fs_now_ms() after a glFinish(), then fs_gl_stage_end. */
#ifndef FS_GL_STAGE_H
#define FS_GL_STAGE_H
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Waits for the GL to finish, adds the time since start to stage `name` of t;
 * returns the end, the start of the next stage. */
double fs_gl_stage_end(fs_stages *t, const char *name, double start);

#ifdef __cplusplus
}
#endif
#endif
