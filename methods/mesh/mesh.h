/* The mesh method's options from its parameter values, for `fluidsurf mesh`,
 * which builds and writes meshes without rendering (mesh_build.h). */
#ifndef FS_MESH_H
#define FS_MESH_H
#include "kernels.h"
#include "mesh_build.h"
#include "provenance.h"
#include "scene.h"

/* values: the method's parameters in table order (fs_method_params_resolve). */
int fs_mesh_opts_from_values(const double *values, const fs_field *f, fs_mesh_opts *o);
/* The provenance of a mesh file built on the CPU from frame `frame` of scene s
 * with these values: the scene's entries (fs_provenance_init: version, commit,
 * source, r, field, ...) and the method's (method, params, frame). */
void fs_mesh_provenance(fs_provenance *out, const fs_scene *s, const double *values, int frame);

#endif
