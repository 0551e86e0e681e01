/* Statistics of a particle set that `fluidsurf info` reports: nearest-neighbour
 * spacing and the density phi at particle centres (so it sits in the field layer). */
#ifndef FS_PARTICLE_STATS_H
#define FS_PARTICLE_STATS_H
#include "kernels.h"
#include "particles.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_particle_stats {
    size_t n;
    float nn_median;       /* median distance to the nearest neighbour */
    float density_median;  /* median normalised density phi at particle centres */
} fs_particle_stats;

/* Needs r, volume_scale and the kernel/support to evaluate phi. */
int fs_particles_stats(const fs_particles *p, const fs_field *f, fs_particle_stats *out);

#ifdef __cplusplus
}
#endif
#endif
