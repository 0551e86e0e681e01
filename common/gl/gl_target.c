#include "gl_target.h"
#include "fs_error.h"
#include "gl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int fs_gl_target_create(fs_gl_target *t, int w, int h)
{
    memset(t, 0, sizeof *t);
    t->w = w;
    t->h = h;
    const GLenum fmt[FS_TARGET_COUNT] = {GL_R32F, GL_RGBA32F, GL_R32F, GL_RGBA32F};
    glCreateTextures(GL_TEXTURE_2D, FS_TARGET_COUNT, t->tex);
    for (int i = 0; i < FS_TARGET_COUNT; i++) {
        glTextureStorage2D(t->tex[i], 1, fmt[i], w, h);
        glTextureParameteri(t->tex[i], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t->tex[i], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glCreateRenderbuffers(1, &t->zbuf);
    glNamedRenderbufferStorage(t->zbuf, GL_DEPTH_COMPONENT32F, w, h);
    glCreateFramebuffers(1, &t->fbo_surface);
    glNamedFramebufferTexture(t->fbo_surface, GL_COLOR_ATTACHMENT0, t->tex[FS_TARGET_DEPTH], 0);
    glNamedFramebufferTexture(t->fbo_surface, GL_COLOR_ATTACHMENT1, t->tex[FS_TARGET_NORMAL], 0);
    glNamedFramebufferTexture(t->fbo_surface, GL_COLOR_ATTACHMENT2, t->tex[FS_TARGET_COLOR], 0);
    glNamedFramebufferRenderbuffer(t->fbo_surface, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t->zbuf);
    const GLenum bufs[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(t->fbo_surface, 3, bufs);
    glCreateFramebuffers(1, &t->fbo_thickness);
    glNamedFramebufferTexture(t->fbo_thickness, GL_COLOR_ATTACHMENT0, t->tex[FS_TARGET_THICKNESS], 0);
    if (glCheckNamedFramebufferStatus(t->fbo_surface, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
        glCheckNamedFramebufferStatus(t->fbo_thickness, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        fs_gl_target_destroy(t);
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: float render targets of %dx%d are incomplete", w, h);
    }
    return FS_OK;
}

void fs_gl_target_destroy(fs_gl_target *t)
{
    if (t->fbo_surface) glDeleteFramebuffers(1, &t->fbo_surface);
    if (t->fbo_thickness) glDeleteFramebuffers(1, &t->fbo_thickness);
    if (t->tex[0]) glDeleteTextures(FS_TARGET_COUNT, t->tex);
    if (t->zbuf) glDeleteRenderbuffers(1, &t->zbuf);
    fs_gl_readback_free(&t->rb);
    free(t->normal_rgba);
    memset(t, 0, sizeof *t);
}

void fs_gl_target_clear(fs_gl_target *t)
{
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    for (int i = 0; i < 3; i++) glClearNamedFramebufferfv(t->fbo_surface, GL_COLOR, i, zero);
    glClearNamedFramebufferfv(t->fbo_surface, GL_DEPTH, 0, &one);
    glClearNamedFramebufferfv(t->fbo_thickness, GL_COLOR, 0, zero);
}

void fs_gl_target_begin_surface(const fs_gl_target *t)
{
    glViewport(0, 0, t->w, t->h);
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo_surface);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void fs_gl_target_begin_thickness(const fs_gl_target *t)
{
    glViewport(0, 0, t->w, t->h);
    glBindFramebuffer(GL_FRAMEBUFFER, t->fbo_thickness);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
}

void fs_gl_target_end_pass(void)
{
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* The context's own limit (llvmpipe: 128 MiB; NVIDIA: about 2 GiB), at most
 * 1 GiB so that byte offsets inside a block stay far from 32-bit overflow in
 * any driver; 128 MiB when the context reports nothing. */
size_t fs_gl_ssbo_chunk(size_t elem_bytes)
{
    GLint64 max = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max);
    if (max <= 0) max = (GLint64)128 << 20;
    if (max > (GLint64)1 << 30) max = (GLint64)1 << 30;
    return (size_t)max / elem_bytes;
}

int fs_gl_upload_chunked(const float *vec4s, size_t n, size_t chunk, unsigned *bufs, int maxbufs)
{
    int nb = (int)((n + chunk - 1) / chunk);
    if (nb > maxbufs) return -fs_fail(FS_ERR_INPUT, "%zu particles need %d buffers of %zu: too many", n, nb, chunk);
    for (int b = 0; b < nb; b++) {
        size_t cnt = n - b * chunk < chunk ? n - b * chunk : chunk;
        glCreateBuffers(1, &bufs[b]);
        glNamedBufferStorage(bufs[b], (GLsizeiptr)(cnt * 4 * sizeof(float)), vec4s + 4 * b * chunk, 0);
    }
    if (glGetError() != GL_NO_ERROR)
        return -fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate particle buffers (out of memory?)");
    return nb;
}

void fs_gl_chunks_free(fs_gl_chunks *c)
{
    if (c->n) glDeleteBuffers(c->n, c->bufs);
    free(c->bufs);
    c->bufs = NULL;
    c->n = 0;
}

int fs_gl_chunks_upload(fs_gl_chunks *c, const float *vec4s, size_t n, const char *who)
{
    fs_gl_chunks_free(c);
    c->chunk = fs_gl_ssbo_chunk(4 * sizeof(float));
    int maxb = (int)((n + c->chunk - 1) / c->chunk);
    if (!(c->bufs = calloc(maxb ? maxb : 1, sizeof *c->bufs))) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", who);
    int nb = fs_gl_upload_chunked(vec4s, n, c->chunk, c->bufs, maxb);
    if (nb < 0) {
        fs_gl_chunks_free(c);
        return -nb;
    }
    c->n = nb;
    return FS_OK;
}

/* Fills buffer buf with particles [first, first + cnt) as float triples. */
static void fill_xyz(unsigned buf, const float *x, const float *y, const float *z, size_t first, size_t cnt,
                     float *stage, size_t stage_n)
{
    for (size_t o = 0; o < cnt; o += stage_n) {
        size_t m = cnt - o < stage_n ? cnt - o : stage_n;
        for (size_t i = 0; i < m; i++) {
            stage[3 * i] = x[first + o + i];
            stage[3 * i + 1] = y[first + o + i];
            stage[3 * i + 2] = z[first + o + i];
        }
        glNamedBufferSubData(buf, (GLintptr)(o * 3 * sizeof(float)), (GLsizeiptr)(m * 3 * sizeof(float)), stage);
    }
}

int fs_gl_upload_xyz(const float *x, const float *y, const float *z, size_t n, size_t chunk, unsigned *bufs,
                     int maxbufs)
{
    enum { STAGE = 65536 };
    int nb = (int)((n + chunk - 1) / chunk);
    if (nb > maxbufs) return -fs_fail(FS_ERR_INPUT, "%zu particles need %d buffers of %zu: too many", n, nb, chunk);
    float *stage = malloc(STAGE * 3 * sizeof *stage);
    if (!stage) return -fs_fail(FS_ERR_RUNTIME, "out of memory uploading %zu particles", n);
    for (int b = 0; b < nb; b++) {
        size_t first = (size_t)b * chunk, cnt = n - first < chunk ? n - first : chunk;
        glCreateBuffers(1, &bufs[b]);
        glNamedBufferStorage(bufs[b], (GLsizeiptr)(cnt * 3 * sizeof(float)), NULL, GL_DYNAMIC_STORAGE_BIT);
        fill_xyz(bufs[b], x, y, z, first, cnt, stage, STAGE);
    }
    free(stage);
    if (glGetError() != GL_NO_ERROR)
        return -fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate particle buffers (out of memory?)");
    return nb;
}

unsigned fs_gl_texture_2d(unsigned format, int w, int h)
{
    unsigned t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, format, w, h);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

unsigned fs_gl_texture_2d_array(unsigned format, int w, int h, int layers)
{
    unsigned t = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
    glTextureStorage3D(t, 1, format, w, h, layers);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}
