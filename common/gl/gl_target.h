/* The G-buffer as GL render targets, shared by every GL method: float
 * attachments for eye depth, view normal (w = coverage), thickness, optional
 * colour, and a depth buffer (read back by method/gl_gbuffer.h through the
 * target's pixel pack buffers, gl_readback.h). */
#ifndef FS_GL_TARGET_H
#define FS_GL_TARGET_H
#include "gl_readback.h"
#include "timing.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

enum { FS_TARGET_DEPTH = 0, FS_TARGET_NORMAL, FS_TARGET_THICKNESS, FS_TARGET_COLOR, FS_TARGET_COUNT };

typedef struct fs_gl_target {
    int w, h;
    unsigned fbo_surface;   /* depth + normal (+ colour) with the depth buffer */
    unsigned fbo_thickness; /* thickness alone, for additive passes */
    unsigned tex[FS_TARGET_COUNT];
    unsigned zbuf;
    fs_gl_readback rb;  /* the read back's buffers, kept between frames */
    float *normal_rgba; /* the normal target as read back, w*h*4 floats (allocated on first read) */
} fs_gl_target;

int fs_gl_target_create(fs_gl_target *t, int w, int h);
void fs_gl_target_destroy(fs_gl_target *t);
/* Clears everything: depth 1, eye depth 0, normal 0, thickness 0, colour 0. */
void fs_gl_target_clear(fs_gl_target *t);
/* Binds the surface framebuffer for a depth-tested splat pass (viewport set,
 * depth test LESS with writes, no blending). */
void fs_gl_target_begin_surface(const fs_gl_target *t);
/* Binds the thickness framebuffer for an additive pass (no depth test, ONE+ONE). */
void fs_gl_target_begin_thickness(const fs_gl_target *t);
/* Back to the default framebuffer, blending off. */
void fs_gl_target_end_pass(void);
/* A 2D texture of one level, nearest filtering (render targets, image load/store). */
unsigned fs_gl_texture_2d(unsigned format, int w, int h);
/* A 2D texture array of one level, linear filtering, clamped (maps sampled by position). */
unsigned fs_gl_texture_2d_array(unsigned format, int w, int h, int layers);

/* Uploads n vec4s as shader storage buffers of at most `chunk` elements each
 * (the context's SSBO limit, 128 MiB on llvmpipe, docs/DESIGN.md); returns the number of buffers made,
 * or minus the error code (fs_fail set). */
int fs_gl_upload_chunked(const float *vec4s, size_t n, size_t chunk, unsigned *bufs, int maxbufs);
/* Elements of `elem_bytes` that fit one SSBO binding on this context. */
size_t fs_gl_ssbo_chunk(size_t elem_bytes);
/* A set of vec4s in as many storage buffers of at most `chunk` elements as it
 * takes: the splatters' particles (slice_splat.c, layered_splat.c). */
typedef struct fs_gl_chunks {
    unsigned *bufs;
    int n;        /* buffers */
    size_t chunk; /* elements per buffer (fs_gl_ssbo_chunk of a vec4) */
} fs_gl_chunks;
/* Replaces c's buffers with the n vec4s; `who` names the caller in a message. */
int fs_gl_chunks_upload(fs_gl_chunks *c, const float *vec4s, size_t n, const char *who);
void fs_gl_chunks_free(fs_gl_chunks *c);
/* Uploads the positions x, y, z (n each) as packed float triples (12 bytes a
 * particle; std430 float[], since a vec3 array would have a 16-byte stride) in
 * buffers of at most `chunk` particles, through a small staging block rather
 * than a host copy of the whole set. Returns the buffer count, or minus an
 * error code as fs_gl_upload_chunked does. */
int fs_gl_upload_xyz(const float *x, const float *y, const float *z, size_t n, size_t chunk, unsigned *bufs,
                     int maxbufs);

#ifdef __cplusplus
}
#endif
#endif
