/* What `fluidsurf info` and the library's fluidsurf_particles_stats report on a
 * particle set: the r its numbers use (given, the file's, the spacing's, or the
 * default), the r the spacing implies, and the statistics of particle_stats.h
 * with the default field at that r. */
#ifndef FS_PARTICLE_INFO_H
#define FS_PARTICLE_INFO_H
#include "particle_stats.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_particle_info {
    float radius;            /* the r below */
    fs_radius_source source; /* FS_R_OPTION (given), FS_R_FILE, FS_R_ESTIMATED or FS_R_DEFAULT */
    float estimated;         /* the r the spacing implies, 0 when there is no spacing to measure */
    float volume_scale;
    fs_particle_stats st; /* nearest-neighbour median, density median at r */
} fs_particle_info;

/* radius > 0: the caller's r. FS_ERR_INPUT when the spacing cannot be measured
 * (all particles at one point) and neither radius nor the file gives r. */
int fs_particle_info_compute(const fs_particles *p, float radius, float volume_scale, fs_particle_info *out);

/* The bytes fs_particle_info_arrays needs for any set (FS_MAX_POINT_ARRAYS names). */
#define FS_ARRAYS_TEXT_SIZE (64 * 96)
/* "NAME (K x TYPE), ..." of p's other point arrays (particle_arrays.h), the ones
 * `info` lists and convert writes, into out (size bytes, cut to fit); "" when none. */
void fs_particle_info_arrays(const fs_particles *p, char *out, size_t size);

#ifdef __cplusplus
}
#endif
#endif
