/* The GL side of the work counters (core/counters.h, docs/DESIGN.md "Work
 * counters"): one storage buffer at binding FS_GL_COUNTER_BINDING, which no
 * method uses, holding a (lo, hi) pair of uint32 per counter and a word of
 * overflow bits. Shaders built while counting get FS_COUNTERS and the FS_CNT_*
 * indices defined (shader.c) and add to it through shaders/common/counters.glsl.
 * Every stage end (fs_stages_add) reads it back into the pending counts and
 * zeroes it, so the GL work lands in the stage that waited for it. */
#ifndef FS_GL_COUNTERS_H
#define FS_GL_COUNTERS_H
#ifdef __cplusplus
extern "C" {
#endif

#define FS_GL_COUNTER_BINDING 30

/* The #define lines (without "#define ") shaders get while counting. */
const char *fs_gl_counter_defines(void);
/* Makes the zeroed buffer, binds it and installs the collector; FS_ERR_RUNTIME
 * when the context has too few storage buffer bindings. */
int fs_gl_counters_begin(void);
/* Collects what is left, removes the collector and deletes the buffer. */
void fs_gl_counters_end(void);

#ifdef __cplusplus
}
#endif
#endif
