/* Reading float textures back to the host without a stall per texture
 * (docs/DESIGN.md, "Read back"): a few pixel pack buffers, persistently mapped
 * in host memory, used in rotation. Each read is a glGetTextureImage into a
 * buffer followed by a fence; the reads of a batch are all started before the
 * first is copied out, so the GPU's transfers of the later textures overlap the
 * CPU's copies of the earlier ones. The copy out waits for its fence and flips
 * the rows (GL's are bottom-up) in that one copy.
 *
 * FLUIDSURF_READBACK=sync in the environment takes the old path instead
 * (fs_gl_read_texture: a synchronous glGetTextureImage into a temporary, then
 * the flip), kept for the test that compares both bit for bit. */
#ifndef FS_GL_READBACK_H
#define FS_GL_READBACK_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

enum { FS_READBACK_SLOTS = 4 };

/* One texture to read: 1 (GL_RED) or 4 (GL_RGBA) float components per pixel
 * into dst, w x h pixels, rows top to bottom. */
typedef struct fs_gl_read {
    unsigned tex;
    int comps;
    float *dst;
} fs_gl_read;

/* The buffers, each grown to the largest read it has held; zero-initialise. */
typedef struct fs_gl_readback {
    unsigned buf[FS_READBACK_SLOTS];
    void *map[FS_READBACK_SLOTS];
    size_t bytes[FS_READBACK_SLOTS];
    void *fence[FS_READBACK_SLOTS]; /* GLsync of the read in flight, NULL when none */
} fs_gl_readback;

/* Reads the n textures (w x h each) into their dst. FS_ERR_RUNTIME (fs_fail) when
 * a buffer cannot be made or mapped, or a fence fails. */
int fs_gl_readback_run(fs_gl_readback *rb, const fs_gl_read *reads, int n, int w, int h);
/* Deletes the buffers and fences (the GL context current). */
void fs_gl_readback_free(fs_gl_readback *rb);
/* 1 when FLUIDSURF_READBACK=sync asks for the old synchronous path. */
int fs_gl_readback_sync(void);
/* The old path: one synchronous glGetTextureImage into a temporary, then the flip. */
int fs_gl_read_texture(unsigned tex, int comps, int w, int h, float *dst);

#ifdef __cplusplus
}
#endif
#endif
