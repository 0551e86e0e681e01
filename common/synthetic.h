/* Synthetic particle sets with a known ideal surface (DESIGN.md, References):
 * particle centres on a lattice of spacing 2r with a seeded jitter. The ideal
 * surface is the outermost centres +- r (a block of N particles has volume N (2r)^3);
 * the sphere's ideal radius is the one with the same volume. */
#ifndef FS_SYNTHETIC_H
#define FS_SYNTHETIC_H
#include "camera.h"
#include "gbuffer.h"
#include "particles.h"
#include "scene.h"
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
/* The exact G-buffer of the ideal shape for that frame: depth, normal, coverage,
 * thickness (path length through the ideal solid). out must already be allocated at
 * the camera's size (fs_gbuffer_alloc), as for a method's render. Like the reference,
 * only a crossing from outside ahead of the eye counts (a camera inside sees nothing). */
int fs_synthetic_analytic(const fs_scene *s, int frame, const fs_camera *cam, fs_gbuffer *out);

#ifdef __cplusplus
}
#endif
#endif
