/* Synthetic particle sets with a known ideal surface (docs/DESIGN.md, "References"):
 * particle centres on a lattice of spacing 2r with a seeded jitter. The ideal
 * surface is the outermost centres +- r (a block of N particles has volume N (2r)^3);
 * the sphere's ideal radius is the one with the same volume. */
#ifndef FS_SYNTHETIC_H
#define FS_SYNTHETIC_H
#include "particles.h"
#include "scene.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Generates frame `frame` of the synthetic scene (frame re-seeds the jitter;
 * moving scenes also translate). Centred at the origin, resting on y = 0 when up is y.
 * synth.size counts particles per world axis (x, y, z); 0 picks the default:
 * slab 48 x 6 x 48 (6 along the up axis), box 16^3; the sphere uses size[0] as its
 * diameter in particles (default 20). `moving` shifts by 2r per frame along x (along y
 * when x is up). Jitter is uniform in [-jitter r, +jitter r) per coordinate from a
 * splitmix64 stream seeded by seed and frame. FS_ERR_INPUT on a bad shape/size/jitter/r. */
int fs_synthetic_generate(const fs_scene *s, int frame, fs_particles *p);
/* The lattice of one frame: index (i,j,k) in [0,n) has its centre at
 * base + 2r (i,j,k); the sphere keeps the points within rc of centre. */
typedef struct fs_synthetic_layout {
    int n[3];
    double base[3];
    double r;
    int sphere;
    double centre[3], rc, R; /* sphere: keep radius, ideal radius */
    size_t count;
    double lo[3], hi[3]; /* block: the ideal box */
} fs_synthetic_layout;
/* The layout of frame `frame`; FS_ERR_INPUT on a bad shape/size/jitter/r. */
int fs_synthetic_layout_of(const fs_scene *s, int frame, fs_synthetic_layout *L);

#ifdef __cplusplus
}
#endif
#endif
