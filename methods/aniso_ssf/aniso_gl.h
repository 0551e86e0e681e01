/* The anisotropy compute pass (shaders/common/anisotropy.comp.glsl) over the
 * GL neighbour grid: per sorted slot a kernel centre and stretch matrix, in
 * buffers of at most `chunk` particles (3 vec4 each) that the ellipsoid
 * sprites read directly. */
#ifndef FS_ANISO_GL_H
#define FS_ANISO_GL_H
#include "anisotropy.h"
#include "gl_grid.h"
#ifdef __cplusplus
extern "C" {
#endif

#define ANISO_GL_MAX_BUFS 16

typedef struct aniso_gl {
    unsigned prog;
    unsigned bufs[ANISO_GL_MAX_BUFS];
    size_t counts[ANISO_GL_MAX_BUFS], chunk;
    int nbufs;
} aniso_gl;

int aniso_gl_init(aniso_gl *a);
/* (Re)computes the anisotropy of the n particles of gg. */
int aniso_gl_run(aniso_gl *a, const fs_gl_grid *gg, size_t n, const fs_aniso_params *ap);
/* Reads slot s's centre[3] and A[9] back (tests). */
int aniso_gl_read(const aniso_gl *a, size_t s, float centre[3], float A[9], int *neighbours);
void aniso_gl_free(aniso_gl *a);

#ifdef __cplusplus
}
#endif
#endif
