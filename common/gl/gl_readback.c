/* Pixel pack buffers in rotation (gl_readback.h). */
#include "gl_readback.h"
#include "fs_error.h"
#include "gl.h"
#include <stdlib.h>
#include <string.h>

int fs_gl_readback_sync(void)
{
    const char *v = getenv("FLUIDSURF_READBACK");
    return v && !strcmp(v, "sync");
}

int fs_gl_read_texture(unsigned tex, int comps, int w, int h, float *dst)
{
    size_t row = (size_t)w * comps;
    float *tmp = malloc(row * h * sizeof(float));
    if (!tmp) return fs_fail(FS_ERR_RUNTIME, "out of memory reading back a %dx%d image", w, h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(tex, 0, comps == 1 ? GL_RED : GL_RGBA, GL_FLOAT, (GLsizei)(row * h * sizeof(float)), tmp);
    for (int y = 0; y < h; y++) memcpy(dst + row * y, tmp + row * (h - 1 - y), row * sizeof(float));
    free(tmp);
    return FS_OK;
}

static void drop_slot(fs_gl_readback *rb, int s)
{
    if (rb->fence[s]) glDeleteSync((GLsync)rb->fence[s]);
    if (rb->buf[s]) glDeleteBuffers(1, &rb->buf[s]); /* unmaps it too */
    rb->fence[s] = rb->map[s] = NULL;
    rb->buf[s] = 0;
    rb->bytes[s] = 0;
}

void fs_gl_readback_free(fs_gl_readback *rb)
{
    for (int s = 0; s < FS_READBACK_SLOTS; s++) drop_slot(rb, s);
}

/* Slot s holds at least `bytes`: an immutable buffer in host memory
 * (GL_CLIENT_STORAGE_BIT), mapped for reading once and for good. */
static int ensure_slot(fs_gl_readback *rb, int s, size_t bytes)
{
    if (rb->bytes[s] >= bytes) return FS_OK;
    drop_slot(rb, s);
    const GLbitfield map = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    glCreateBuffers(1, &rb->buf[s]);
    glNamedBufferStorage(rb->buf[s], (GLsizeiptr)bytes, NULL, map | GL_CLIENT_STORAGE_BIT);
    rb->map[s] = glMapNamedBufferRange(rb->buf[s], 0, (GLsizeiptr)bytes, map);
    if (!rb->map[s] || glGetError() != GL_NO_ERROR) {
        drop_slot(rb, s);
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot map a read-back buffer of %zu bytes", bytes);
    }
    rb->bytes[s] = bytes;
    return FS_OK;
}

/* Starts read r into slot s: the texture into the buffer, then a fence. */
static int start(fs_gl_readback *rb, int s, const fs_gl_read *r, int w, int h)
{
    size_t bytes = (size_t)w * h * r->comps * sizeof(float);
    int rc = ensure_slot(rb, s, bytes);
    if (rc) return rc;
    glBindBuffer(GL_PIXEL_PACK_BUFFER, rb->buf[s]);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(r->tex, 0, r->comps == 1 ? GL_RED : GL_RGBA, GL_FLOAT, (GLsizei)bytes, NULL);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    rb->fence[s] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    return rb->fence[s] ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot place a read-back fence");
}

/* Waits for slot s's fence (flushing the commands before it), then copies its
 * rows into r->dst, top row first. */
static int finish(fs_gl_readback *rb, int s, const fs_gl_read *r, int w, int h)
{
    GLenum st = GL_TIMEOUT_EXPIRED;
    while (st == GL_TIMEOUT_EXPIRED)
        st = glClientWaitSync((GLsync)rb->fence[s], GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000u);
    glDeleteSync((GLsync)rb->fence[s]);
    rb->fence[s] = NULL;
    if (st == GL_WAIT_FAILED) return fs_fail(FS_ERR_RUNTIME, "OpenGL: waiting for a read back failed");
    size_t row = (size_t)w * r->comps;
    const float *src = rb->map[s];
    /* rows in parallel: one thread's copy does not reach the memory bus's speed */
#pragma omp parallel for schedule(static) if (row * h > 262144)
    for (int y = 0; y < h; y++) memcpy(r->dst + row * y, src + row * (h - 1 - y), row * sizeof(float));
    return FS_OK;
}

/* The old path for every read (FLUIDSURF_READBACK=sync). */
static int run_sync(const fs_gl_read *reads, int n, int w, int h)
{
    int rc = FS_OK;
    for (int i = 0; i < n && !rc; i++) rc = fs_gl_read_texture(reads[i].tex, reads[i].comps, w, h, reads[i].dst);
    return rc;
}

/* Deletes the fences an error left in flight. */
static void drop_fences(fs_gl_readback *rb)
{
    for (int s = 0; s < FS_READBACK_SLOTS; s++)
        if (rb->fence[s]) {
            glDeleteSync((GLsync)rb->fence[s]);
            rb->fence[s] = NULL;
        }
}

int fs_gl_readback_run(fs_gl_readback *rb, const fs_gl_read *reads, int n, int w, int h)
{
    if (fs_gl_readback_sync()) return run_sync(reads, n, w, h);
    int rc = FS_OK, started = 0;
    while (!rc && started < n && started < FS_READBACK_SLOTS) {
        rc = start(rb, started, &reads[started], w, h);
        started++;
    }
    /* read i sits in slot i % SLOTS; once copied out, the slot takes the next read */
    for (int i = 0; i < started && !rc; i++) {
        int s = i % FS_READBACK_SLOTS;
        rc = finish(rb, s, &reads[i], w, h);
        if (!rc && started < n) {
            rc = start(rb, s, &reads[started], w, h);
            started++;
        }
    }
    drop_fences(rb);
    return rc;
}
