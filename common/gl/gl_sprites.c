#include "gl_sprites.h"
#include "gl.h"
#include <stdint.h>

void fs_gl_camera_uniforms(unsigned prog, const fs_camera *cam)
{
    float view[16], proj[16], rot[9];
    fs_camera_view_matrix(cam, view);
    fs_camera_proj_matrix(cam, proj);
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++) rot[3 * c + r] = view[4 * c + r];
    glUseProgram(prog);
    /* a uniform the program does not declare has location -1: GL ignores it */
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_view"), 1, GL_FALSE, view);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_proj"), 1, GL_FALSE, proj);
    glUniformMatrix3fv(glGetUniformLocation(prog, "u_view_rot"), 1, GL_FALSE, rot);
    glUniform3f(glGetUniformLocation(prog, "u_eye"), cam->eye[0], cam->eye[1], cam->eye[2]);
    glUniform2f(glGetUniformLocation(prog, "u_viewport"), (float)cam->width, (float)cam->height);
}

/* Waits until the GPU has finished the commands before fence f (none: 0). */
static void wait_fence(GLsync f)
{
    if (!f) return;
    glClientWaitSync(f, GL_SYNC_FLUSH_COMMANDS_BIT, UINT64_MAX);
    glDeleteSync(f);
}

void fs_gl_draw_sprites(unsigned vao, const unsigned *bufs, int nbufs, size_t chunk, size_t n, size_t stride)
{
    GLint align = 1;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
    /* a batch starts at a multiple of the alignment (else draw whole chunks) */
    size_t batch = (FS_GL_SPRITE_BATCH * stride) % (size_t)(align > 0 ? align : 1) ? chunk : FS_GL_SPRITE_BATCH;
    GLsync prev = 0;
    glBindVertexArray(vao);
    for (int b = 0; b < nbufs; b++) {
        size_t first = (size_t)b * chunk, cnt = n - first < chunk ? n - first : chunk;
        for (size_t o = 0; o < cnt; o += batch) {
            size_t m = cnt - o < batch ? cnt - o : batch;
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, bufs[b], (GLintptr)(o * stride), (GLsizeiptr)(m * stride));
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)m);
            /* the fence flushes this batch; waiting on the one before keeps the
             * binning of the next batch overlapped with rasterising this one */
            GLsync f = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
            wait_fence(prev);
            prev = f;
        }
    }
    if (prev) glDeleteSync(prev); /* the caller waits (glFinish) when it needs to */
}
