/* The per-particle arrays of a file that fluidsurf carries without using them
 * (fs_point_array, particles.h): added by the readers, listed by `info`, written
 * by `convert`. */
#ifndef FS_PARTICLE_ARRAYS_H
#define FS_PARTICLE_ARRAYS_H
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* At most this many arrays a set, of at most this many components. */
#define FS_MAX_POINT_ARRAYS 64
#define FS_MAX_ARRAY_COMPONENTS 1024

/* Adds a zeroed array of p->n x ncomp values named name (cut to 63 bytes) and
 * returns it in *out. FS_ERR_INPUT beyond the limits above, FS_ERR_RUNTIME out of
 * memory (fs_fail; p unchanged then). */
int fs_particles_add_array(fs_particles *p, const char *name, int ncomp, fs_array_type type, fs_point_array **out);
/* Value k (particle k / ncomp, component k % ncomp) as a double, and set from one
 * (converted to the array's type: integers rounded and clamped). */
double fs_point_array_get(const fs_point_array *a, size_t k);
void fs_point_array_set(fs_point_array *a, size_t k, double v);
size_t fs_array_type_size(fs_array_type t);
/* "float32", "float64", "int32", "uint32". */
const char *fs_array_type_name(fs_array_type t);
/* The array named name, or NULL. */
const fs_point_array *fs_particles_array(const fs_particles *p, const char *name);
/* name with every character a file format cannot hold in a name (whitespace and
 * controls) as '_', into out (64 bytes). */
void fs_array_safe_name(const char *name, char out[64]);

#ifdef __cplusplus
}
#endif
#endif
