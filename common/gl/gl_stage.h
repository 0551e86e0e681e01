/* Timing a GL stage twice: on the wall clock between glFinish() calls (what a
 * user waits for), and on the GL's own clock (GL_TIMESTAMP), which on a real
 * GPU is the time the commands took there; llvmpipe's is not trustworthy
 * (docs/DESIGN.md, "Timing"). start = fs_gl_stage_start(), then
 * fs_gl_stage_end; a stage's end is the next stage's start. */
#ifndef FS_GL_STAGE_H
#define FS_GL_STAGE_H
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Waits for the GL to finish and notes the GL clock; returns the wall-clock start. */
double fs_gl_stage_start(void);
/* Waits for the GL to finish, adds the wall time since start and the GL time
 * since the matching start (or the previous stage end) to stage `name` of t;
 * returns the end, the start of the next stage. A start that matches neither
 * (a CPU stage in between) records no GL time. */
double fs_gl_stage_end(fs_stages *t, const char *name, double start);

#ifdef __cplusplus
}
#endif
#endif
