/* The mesh's edge graph: each vertex's distinct edge neighbours as compressed
 * rows, shared by the position smoothing (mesh_smooth.c) and the normal
 * smoothing (mesh_normals.c). */
#ifndef FS_MESH_ADJACENCY_H
#define FS_MESH_ADJACENCY_H
#include "trimesh.h"

typedef struct fs_mesh_adjacency {
    size_t *start; /* nv + 1: the neighbours of v are nbr[start[v] .. start[v + 1]) */
    uint32_t *nbr;
} fs_mesh_adjacency;

/* FS_ERR_RUNTIME (fs_fail) out of memory; A is then empty. */
int fs_mesh_adjacency_build(const fs_trimesh *m, fs_mesh_adjacency *A);
void fs_mesh_adjacency_free(fs_mesh_adjacency *A);

#endif
