/* Runs shaders/common/anisotropy.comp.glsl (aniso_gl.h). */
#include "aniso_ssf/aniso_gl.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include "shader.h"
#include <string.h>

int aniso_gl_init(aniso_gl *a)
{
    memset(a, 0, sizeof *a);
    const char *st[] = {"common/anisotropy.comp.glsl", NULL};
    a->prog = fs_program_build(st, NULL);
    return a->prog ? FS_OK : FS_ERR_RUNTIME;
}

static void free_bufs(aniso_gl *a)
{
    if (a->nbufs) glDeleteBuffers(a->nbufs, a->bufs);
    a->nbufs = 0;
}

void aniso_gl_free(aniso_gl *a)
{
    free_bufs(a);
    if (a->prog) glDeleteProgram(a->prog);
    a->prog = 0;
}

int aniso_gl_run(aniso_gl *a, const fs_gl_grid *gg, size_t n, const fs_aniso_params *ap)
{
    free_bufs(a);
    a->chunk = fs_gl_ssbo_chunk(3 * 4 * sizeof(float));
    size_t nb = n ? (n + a->chunk - 1) / a->chunk : 0;
    if (nb > ANISO_GL_MAX_BUFS)
        return fs_fail(FS_ERR_INPUT, "aniso_ssf: %zu particles need %zu anisotropy buffers (at most %d)", n, nb,
                       ANISO_GL_MAX_BUFS);
    unsigned P = a->prog;
    fs_gl_grid_bind(gg, P); /* makes P current */
    glUniform1i(glGetUniformLocation(P, "u_kernel"), (int)ap->kernel);
    glUniform1f(glGetUniformLocation(P, "u_R"), ap->radius);
    glUniform1f(glGetUniformLocation(P, "u_kappa"), ap->kappa);
    glUniform1f(glGetUniformLocation(P, "u_scale"), ap->scale);
    glUniform1f(glGetUniformLocation(P, "u_lambda"), ap->lambda);
    glUniform1f(glGetUniformLocation(P, "u_sigma_ref"), ap->sigma_ref);
    glUniform1i(glGetUniformLocation(P, "u_n_eps"), ap->n_eps);
    glUniform1i(glGetUniformLocation(P, "u_per_particle"), ap->per_particle);
    for (size_t b = 0; b < nb; b++) {
        size_t first = b * a->chunk, cnt = n - first < a->chunk ? n - first : a->chunk;
        glCreateBuffers(1, &a->bufs[b]);
        a->nbufs = (int)b + 1;
        a->counts[b] = cnt;
        glNamedBufferStorage(a->bufs[b], (GLsizeiptr)(cnt * 12 * sizeof(float)), NULL, 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, a->bufs[b]);
        glUniform1ui(glGetUniformLocation(P, "u_first"), (unsigned)first);
        glUniform1ui(glGetUniformLocation(P, "u_count"), (unsigned)cnt);
        glDispatchCompute((unsigned)((cnt + 63) / 64), 1, 1);
    }
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    return glGetError() == GL_NO_ERROR ? FS_OK
                                       : fs_fail(FS_ERR_RUNTIME, "aniso_ssf: OpenGL error in the anisotropy pass");
}

int aniso_gl_read(const aniso_gl *a, size_t s, float centre[3], float A[9], int *neighbours)
{
    if (!a->chunk || s / a->chunk >= (size_t)a->nbufs)
        return fs_fail(FS_ERR_RUNTIME, "aniso_ssf: slot %zu not computed", s);
    float v[12];
    glGetNamedBufferSubData(a->bufs[s / a->chunk], (GLintptr)((s % a->chunk) * sizeof v), sizeof v, v);
    memcpy(centre, v, 3 * sizeof *v);
    A[0] = v[4];
    A[1] = A[3] = v[5];
    A[2] = A[6] = v[6];
    A[4] = v[7];
    A[5] = A[7] = v[8];
    A[8] = v[9];
    if (neighbours) *neighbours = (int)v[10];
    return FS_OK;
}
