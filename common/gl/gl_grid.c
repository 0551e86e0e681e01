#include "gl_grid.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include <stdlib.h>
#include <string.h>

void fs_gl_grid_free(fs_gl_grid *gg)
{
    if (gg->start) glDeleteBuffers(1, &gg->start);
    if (gg->near) glDeleteBuffers(1, &gg->near);
    if (gg->nchunks) glDeleteBuffers(gg->nchunks, gg->pos);
    if (gg->has_attr) glDeleteBuffers(gg->nchunks, gg->attr);
    memset(gg, 0, sizeof *gg);
}

/* Bit c of the result: one of the 27 cells around c holds a particle. */
static uint32_t *near_bits(const fs_grid *g)
{
    size_t words = g->ncells / 32 + 1;
    uint32_t *bits = calloc(words, sizeof *bits);
    if (!bits) return NULL;
    int nk = g->dim[2];
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nk; k++)
        for (int j = 0; j < g->dim[1]; j++)
            for (int i = 0; i < g->dim[0]; i++) {
                size_t c = fs_grid_cell_id(g, i, j, k);
                if (g->start[c + 1] == g->start[c]) continue;
                for (int kk = k - 1; kk <= k + 1; kk++)
                    for (int jj = j - 1; jj <= j + 1; jj++)
                        for (int ii = i - 1; ii <= i + 1; ii++) {
                            if (ii < 0 || jj < 0 || kk < 0 || ii >= g->dim[0] || jj >= g->dim[1] || kk >= g->dim[2])
                                continue;
                            size_t d = fs_grid_cell_id(g, ii, jj, kk);
                            __atomic_fetch_or(&bits[d / 32], 1u << (d % 32), __ATOMIC_RELAXED);
                        }
            }
    return bits;
}

int fs_gl_grid_upload(fs_gl_grid *gg, const fs_grid *g)
{
    fs_gl_grid_free(gg);
    size_t chunk = fs_gl_ssbo_chunk(4 * sizeof(float));
    if (g->ncells + 1 > fs_gl_ssbo_chunk(sizeof(uint32_t)))
        return fs_fail(FS_ERR_INPUT, "grid: %zu cells do not fit one shader storage buffer: raise the cell size",
                       g->ncells);
    size_t n = g->n ? g->n : 1;
    int nb = fs_gl_upload_chunked(g->pos4, n, chunk, gg->pos, FS_GL_GRID_MAX_CHUNKS);
    if (nb < 0) return -nb;
    gg->nchunks = nb;
    gg->chunk = chunk;
    uint32_t *bits = near_bits(g);
    if (!bits) { fs_gl_grid_free(gg); return fs_fail(FS_ERR_RUNTIME, "grid: out of memory for %zu cells", g->ncells); }
    glCreateBuffers(1, &gg->start);
    glNamedBufferStorage(gg->start, (GLsizeiptr)((g->ncells + 1) * sizeof(uint32_t)), g->start, 0);
    glCreateBuffers(1, &gg->near);
    glNamedBufferStorage(gg->near, (GLsizeiptr)((g->ncells / 32 + 1) * sizeof(uint32_t)), bits, 0);
    free(bits);
    memcpy(gg->origin, g->origin, sizeof gg->origin);
    memcpy(gg->dim, g->dim, sizeof gg->dim);
    gg->cell = g->cell;
    if (glGetError() != GL_NO_ERROR) {
        fs_gl_grid_free(gg);
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate the grid buffers (out of memory?)");
    }
    return FS_OK;
}

int fs_gl_grid_upload_attr(fs_gl_grid *gg, const fs_grid *g, const float *vec4s)
{
    if (gg->has_attr) { glDeleteBuffers(gg->nchunks, gg->attr); gg->has_attr = 0; }
    size_t n = g->n ? g->n : 1;
    float *sorted = calloc(n * 4, sizeof *sorted);
    if (!sorted) return fs_fail(FS_ERR_RUNTIME, "grid: out of memory for %zu attributes", n);
    for (size_t s = 0; s < g->n; s++) memcpy(sorted + 4 * s, vec4s + 4 * (size_t)g->index[s], 4 * sizeof(float));
    int nb = fs_gl_upload_chunked(sorted, n, gg->chunk, gg->attr, FS_GL_GRID_MAX_CHUNKS);
    free(sorted);
    if (nb < 0) return -nb;
    gg->has_attr = 1;
    return FS_OK;
}

void fs_gl_grid_bind(const fs_gl_grid *gg, unsigned prog)
{
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_START, gg->start);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_NEAR, gg->near);
    /* Unused chunk bindings get chunk 0, so every declared block has a buffer. */
    for (int b = 0; b < FS_GL_GRID_MAX_CHUNKS; b++) {
        int src = b < gg->nchunks ? b : 0;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_POS + b, gg->pos[src]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_ATTR + b, gg->has_attr ? gg->attr[src] : gg->pos[src]);
    }
    glUseProgram(prog);
    glUniform3f(glGetUniformLocation(prog, "u_grid_origin"), gg->origin[0], gg->origin[1], gg->origin[2]);
    glUniform1f(glGetUniformLocation(prog, "u_grid_cell"), gg->cell);
    glUniform3iv(glGetUniformLocation(prog, "u_grid_dim"), 1, gg->dim);
    glUniform1ui(glGetUniformLocation(prog, "u_grid_chunk"), (unsigned)gg->chunk);
}
