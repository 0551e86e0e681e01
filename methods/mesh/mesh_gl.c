/* The mesh raster (mesh_gl.h). */
#include "mesh_gl.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_sprites.h"
#include "gl_stage.h"
#include "shader.h"
#include <stdlib.h>
#include <string.h>

int fs_mesh_gl_init(fs_mesh_gl *G)
{
    memset(G, 0, sizeof *G);
    const char *st[] = {"mesh/mesh.vert.glsl", "mesh/mesh.frag.glsl", NULL};
    G->prog_surface = fs_program_build(st, NULL);
    if (G->prog_surface) G->prog_thickness = fs_program_build(st, "MODE_THICKNESS 1");
    if (!G->prog_thickness) {
        fs_mesh_gl_free(G);
        return FS_ERR_RUNTIME;
    }
    glCreateVertexArrays(1, &G->vao);
    for (unsigned a = 0; a < 2; a++) {
        glEnableVertexArrayAttrib(G->vao, a);
        glVertexArrayAttribFormat(G->vao, a, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(G->vao, a, a);
    }
    return FS_OK;
}

int fs_mesh_gl_upload(fs_mesh_gl *G, const fs_trimesh *m)
{
    if (G->vbo) glDeleteBuffers(1, &G->vbo);
    if (G->ebo) glDeleteBuffers(1, &G->ebo);
    G->vbo = G->ebo = 0;
    G->nidx = 0;
    if (!m->nt) return FS_OK;
    size_t vb = m->nv * 3 * sizeof(float);
    glCreateBuffers(1, &G->vbo);
    glCreateBuffers(1, &G->ebo);
    /* positions then normals, one buffer: two bindings at offsets 0 and vb */
    glNamedBufferData(G->vbo, (GLsizeiptr)(2 * vb), NULL, GL_STATIC_DRAW);
    glNamedBufferSubData(G->vbo, 0, (GLsizeiptr)vb, m->pos);
    glNamedBufferSubData(G->vbo, (GLintptr)vb, (GLsizeiptr)vb, m->nrm);
    glNamedBufferData(G->ebo, (GLsizeiptr)(m->nt * 3 * sizeof(uint32_t)), m->tri, GL_STATIC_DRAW);
    glVertexArrayVertexBuffer(G->vao, 0, G->vbo, 0, 3 * sizeof(float));
    glVertexArrayVertexBuffer(G->vao, 1, G->vbo, (GLintptr)vb, 3 * sizeof(float));
    glVertexArrayElementBuffer(G->vao, G->ebo);
    if (glGetError() != GL_NO_ERROR)
        return fs_fail(FS_ERR_RUNTIME, "mesh: the GL could not take %zu vertices and %zu triangles", m->nv, m->nt);
    G->nidx = m->nt * 3;
    return FS_OK;
}

static void draw(const fs_mesh_gl *G, unsigned prog, const fs_camera *cam)
{
    fs_gl_camera_uniforms(prog, cam);
    if (!G->nidx) return;
    glBindVertexArray(G->vao);
    glDrawElements(GL_TRIANGLES, (GLsizei)G->nidx, GL_UNSIGNED_INT, NULL);
    glBindVertexArray(0);
}

int fs_mesh_gl_draw(fs_mesh_gl *G, const fs_camera *cam, int thickness, fs_stages *st)
{
    if (G->target.w != cam->width || G->target.h != cam->height) {
        fs_gl_target_destroy(&G->target);
        int rc = fs_gl_target_create(&G->target, cam->width, cam->height);
        if (rc) return rc;
    }
    double t0 = fs_gl_stage_start();
    fs_gl_target_clear(&G->target);
    fs_gl_target_begin_surface(&G->target);
    draw(G, G->prog_surface, cam);
    double t1 = fs_gl_stage_end(st, "raster", t0);
    if (thickness) {
        fs_gl_target_begin_thickness(&G->target);
        draw(G, G->prog_thickness, cam);
        fs_gl_stage_end(st, "thickness", t1);
    }
    fs_gl_target_end_pass();
    return FS_OK;
}

void fs_mesh_gl_free(fs_mesh_gl *G)
{
    if (G->prog_surface) glDeleteProgram(G->prog_surface);
    if (G->prog_thickness) glDeleteProgram(G->prog_thickness);
    if (G->vao) glDeleteVertexArrays(1, &G->vao);
    if (G->vbo) glDeleteBuffers(1, &G->vbo);
    if (G->ebo) glDeleteBuffers(1, &G->ebo);
    fs_gl_target_destroy(&G->target);
    memset(G, 0, sizeof *G);
}
