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
 * moving scenes also translate). Centred at the origin, resting on y = 0 when up is y. */
int fs_synthetic_generate(const fs_scene *s, int frame, fs_particles *p);
/* The exact G-buffer of the ideal shape for that frame: depth, normal, coverage,
 * thickness (path length through the ideal solid). */
int fs_synthetic_analytic(const fs_scene *s, int frame, const fs_camera *cam, fs_gbuffer *out);

#ifdef __cplusplus
}
#endif
#endif
