/* The mesh method's options from its parameter values, for `fluidsurf mesh`,
 * which builds and writes meshes without rendering (mesh_build.h). */
#ifndef FS_MESH_H
#define FS_MESH_H
#include "kernels.h"
#include "mesh_build.h"

/* values: the method's parameters in table order (fs_method_params_resolve). */
int fs_mesh_opts_from_values(const double *values, const fs_field *f, fs_mesh_opts *o);

#endif
