/* Statistics of a particle set that `fluidsurf info` reports (nearest-neighbour
 * spacing and the density phi at particle centres, so it sits in the field
 * layer), and the radius estimate for files that give none. Both look at
 * FS_STATS_SAMPLE particles drawn with a fixed seed: the cost is one grid
 * build plus a constant, and the answer is the same on every run. */
#ifndef FS_PARTICLE_STATS_H
#define FS_PARTICLE_STATS_H
#include "kernels.h"
#include "particles.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_STATS_SAMPLE 4096

typedef struct fs_particle_stats {
    size_t n;             /* particles */
    size_t sampled;       /* particles the medians are over: min(n, FS_STATS_SAMPLE) */
    float nn_median;      /* median distance to the nearest neighbour */
    float density_median; /* median normalised density phi at particle centres */
} fs_particle_stats;

/* Needs r, volume_scale and the kernel/support to evaluate phi. */
int fs_particles_stats(const fs_particles *p, const fs_field *f, fs_particle_stats *out);

/* The particle radius the data's spacing implies, r = (volume per particle)^(1/3) / 2
 * (fluidsurf's lattice spacing is 2r). The volume per particle is a number-density
 * estimate: the ball out to the 32nd nearest neighbour over 32, at each sampled
 * particle; the 10th percentile over the sample, since particles near a free
 * surface see empty space in their ball. Half the median nearest-neighbour
 * distance would do on a lattice but reads about a third low on a developed
 * flow, whose nearest neighbours sit closer than its mean spacing.
 * FS_ERR_INPUT for fewer than 2 particles or no spacing (all at one point). */
int fs_particles_estimate_radius(const fs_particles *p, float *r);

#ifdef __cplusplus
}
#endif
#endif
