/* A triangle mesh as the mesh method keeps and exports it: vertices with unit
 * normals, triangles wound counter-clockwise seen from outside. */
#ifndef FS_TRIMESH_H
#define FS_TRIMESH_H
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_trimesh {
    size_t nv, nt;
    float *pos;    /* 3 nv */
    float *nrm;    /* 3 nv, NULL until normals are computed */
    uint32_t *tri; /* 3 nt vertex indices */
    float *vel;    /* 3 nv particle velocity interpolated at the vertices, or NULL (mesh_attributes.h) */
    float *col;    /* 3 nv particle colour (linear RGB) interpolated at the vertices, or NULL */
} fs_trimesh;

void fs_trimesh_free(fs_trimesh *m);
/* Six times the signed volume enclosed (positive: wound outward). */
double fs_trimesh_volume6(const fs_trimesh *m);
/* Reverses the winding of every triangle. */
void fs_trimesh_flip(fs_trimesh *m);

#ifdef __cplusplus
}
#endif
#endif
