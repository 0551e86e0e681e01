#include "gl_grid.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include <stdlib.h>
#include <string.h>

void fs_gl_grid_free(fs_gl_grid *gg)
{
    unsigned bufs[4] = {gg->start, gg->near, gg->bkey, gg->table};
    for (int b = 0; b < 4; b++)
        if (bufs[b]) glDeleteBuffers(1, &bufs[b]);
    if (gg->nchunks) glDeleteBuffers(gg->nchunks, gg->pos);
    if (gg->has_attr) glDeleteBuffers(gg->nchunks, gg->attr);
    memset(gg, 0, sizeof *gg);
}

/* An immutable buffer of `bytes` from data (at least 4 bytes, so every binding has storage). */
static unsigned buffer(const void *data, size_t bytes)
{
    static const uint32_t none = UINT32_MAX;
    unsigned b;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, (GLsizeiptr)(bytes ? bytes : sizeof none), bytes ? data : &none, 0);
    return b;
}

int fs_gl_grid_upload(fs_gl_grid *gg, const fs_grid *g)
{
    fs_gl_grid_free(gg);
    size_t chunk = fs_gl_ssbo_chunk(4 * sizeof(float)), words = fs_gl_ssbo_chunk(sizeof(uint32_t));
    if (g->ncells + 1 > words || g->table_mask + 1 > words || 3 * g->nblocks > words)
        return fs_fail(FS_ERR_INPUT, "grid: %zu cells do not fit one shader storage buffer: raise the cell size",
                       g->ncells);
    size_t n = g->n ? g->n : 1;
    int nb = fs_gl_upload_chunked(g->pos4, n, chunk, gg->pos, FS_GL_GRID_MAX_CHUNKS);
    if (nb < 0) return -nb;
    gg->nchunks = nb;
    gg->chunk = chunk;
    gg->start = buffer(g->start, (g->ncells + 1) * sizeof *g->start);
    gg->near = buffer(g->near, (g->ncells / 32 + 1) * sizeof *g->near);
    gg->bkey = buffer(g->bkey, 3 * g->nblocks * sizeof *g->bkey);
    gg->table = buffer(g->table, g->table ? (g->table_mask + 1) * sizeof *g->table : 0);
    memcpy(gg->origin, g->origin, sizeof gg->origin);
    memcpy(gg->lo, g->lo, sizeof gg->lo);
    memcpy(gg->hi, g->hi, sizeof gg->hi);
    gg->table_mask = g->table ? (unsigned)g->table_mask : 0;
    gg->cell = g->cell;
    if (glGetError() != GL_NO_ERROR) {
        fs_gl_grid_free(gg);
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate the grid buffers (out of memory?)");
    }
    return FS_OK;
}

int fs_gl_grid_upload_attr(fs_gl_grid *gg, const fs_grid *g, const float *vec4s)
{
    if (gg->has_attr) {
        glDeleteBuffers(gg->nchunks, gg->attr);
        gg->has_attr = 0;
    }
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
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_BKEY, gg->bkey);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_TABLE, gg->table);
    /* Unused chunk bindings get chunk 0, so every declared block has a buffer. */
    for (int b = 0; b < FS_GL_GRID_MAX_CHUNKS; b++) {
        int src = b < gg->nchunks ? b : 0;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_POS + b, gg->pos[src]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FS_GL_GRID_BINDING_ATTR + b,
                         gg->has_attr ? gg->attr[src] : gg->pos[src]);
    }
    glUseProgram(prog);
    glUniform3f(glGetUniformLocation(prog, "u_grid_origin"), gg->origin[0], gg->origin[1], gg->origin[2]);
    glUniform1f(glGetUniformLocation(prog, "u_grid_cell"), gg->cell);
    glUniform3iv(glGetUniformLocation(prog, "u_grid_lo"), 1, gg->lo);
    glUniform3iv(glGetUniformLocation(prog, "u_grid_hi"), 1, gg->hi);
    glUniform1ui(glGetUniformLocation(prog, "u_grid_table_mask"), gg->table_mask);
    glUniform1ui(glGetUniformLocation(prog, "u_grid_chunk"), (unsigned)gg->chunk);
}
