#include "gl_sprites.h"
#include "gl.h"

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

void fs_gl_draw_sprites(unsigned vao, const unsigned *bufs, int nbufs, size_t chunk, size_t n)
{
    glBindVertexArray(vao);
    for (int b = 0; b < nbufs; b++) {
        size_t first = (size_t)b * chunk, cnt = n - first < chunk ? n - first : chunk;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bufs[b]);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)cnt);
    }
}
