/* The implementation-dependent OpenGL limits (GL_MAX_*) fluidsurf's shaders and GL
 * code rely on, each with the value fluidsurf needs and what needs it
 * (docs/DESIGN.md, "GL limits"). fs_gl_context_create checks them once the function
 * table is loaded, so a driver below a need fails with one line naming the limit,
 * the renderer, the need and its user, instead of a compile error or a crash later. */
#ifndef FS_GL_LIMITS_H
#define FS_GL_LIMITS_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_gl_limit {
    unsigned pname;   /* GL_MAX_... */
    int index;        /* -1: glGetInteger64v; 0..2: glGetIntegeri_v's index (x, y, z) */
    const char *name; /* "GL_MAX_..." (with "[x]" for an indexed one) */
    long long need;   /* the smallest value fluidsurf works with */
    const char *what; /* what needs it */
} fs_gl_limit;

/* The table, in docs/DESIGN.md's order; *n gets its length. */
const fs_gl_limit *fs_gl_limits(int *n);
/* Checks driver values (have[i] for table entry i) against the needs: FS_OK, or
 * FS_ERR_RUNTIME with "OpenGL: GL_MAX_X is N on RENDERER; fluidsurf needs M (what)"
 * for the first limit below its need (a negative value: "is not reported on").
 * Pure: unit-testable without a context. */
int fs_gl_limits_check(const long long *have, const char *renderer);
/* Queries every limit on the current context into have (the table's length). */
void fs_gl_limits_query(long long *have);
/* Both, on the current context. */
int fs_gl_limits_check_current(const char *renderer);

#ifdef __cplusplus
}
#endif
#endif
