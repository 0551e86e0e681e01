/* Surfels as a PLY point cloud (binary little endian): x y z nx ny nz radius,
 * readable by MeshLab, CloudCompare, Blender and fluidsurf's own PLY reader. */
#ifndef FS_SURFEL_PLY_H
#define FS_SURFEL_PLY_H
#include "surfel_set.h"

/* Written through a temporary file renamed into place; "path: what" errors. */
int fs_surfels_write_ply(const fs_surfel_set *set, const char *path);

#endif
