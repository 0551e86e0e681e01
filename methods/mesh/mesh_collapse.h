/* Degenerate faces collapsed (methods/mesh/README.md, "Deviations"): smoothing
 * can pull a small closed piece (a droplet) down to a point or a line, leaving
 * faces of no area whose normals are undefined. A face whose smallest height is
 * below eps has its shortest edge collapsed (both ends merged at their mean; a
 * vertex merges at most once a round, so it moves at most half an edge a round);
 * faces left with two equal corners go, as do a face and its reverse on the same
 * three corners (they enclose nothing), and so do vertices that no face uses.
 * Repeated until no such face is left (each round merges a pair or drops a face). */
#ifndef FS_MESH_COLLAPSE_H
#define FS_MESH_COLLAPSE_H
#include "trimesh.h"

/* The height below which a face is degenerate, in multiples of the cube size. */
#define FS_MESH_DEGENERATE_CUBE 1e-3

/* On m's positions and triangles, before normals and attributes (m->nrm, vel,
 * col NULL). removed: the faces taken out (may be NULL). FS_ERR_RUNTIME
 * (fs_fail) out of memory; m is then unchanged. */
int fs_mesh_collapse_degenerate(fs_trimesh *m, double eps, size_t *removed);

#endif
