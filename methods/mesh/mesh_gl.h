/* The mesh method's raster (OpenGL): the triangles in one vertex buffer
 * (position, normal) and one index buffer, drawn depth-tested into the
 * G-buffer, then again without depth test for the signed additive thickness. */
#ifndef FS_MESH_GL_H
#define FS_MESH_GL_H
#include "camera.h"
#include "gl_target.h"
#include "timing.h"
#include "trimesh.h"

typedef struct fs_mesh_gl {
    unsigned prog_surface, prog_thickness, vao, vbo, ebo;
    size_t nidx;
    fs_gl_target target;
} fs_mesh_gl;

/* Programs and the vertex array; FS_ERR_RUNTIME (fs_fail) on failure. */
int fs_mesh_gl_init(fs_mesh_gl *G);
/* (Re)uploads the mesh (positions and normals). */
int fs_mesh_gl_upload(fs_mesh_gl *G, const fs_trimesh *m);
/* Draws into the target (sized to cam), stages "raster" and "thickness". */
int fs_mesh_gl_draw(fs_mesh_gl *G, const fs_camera *cam, int thickness, fs_stages *st);
void fs_mesh_gl_free(fs_mesh_gl *G);

#endif
