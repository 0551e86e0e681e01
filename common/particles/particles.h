/* A particle set: structure-of-arrays positions plus optional attributes. */
#ifndef FS_PARTICLES_H
#define FS_PARTICLES_H
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

enum { FS_HAS_VELOCITY = 1, FS_HAS_COLOR = 2, FS_HAS_PHASE = 4 };

/* A per-particle array a file holds besides position, velocity, colour and phase
 * (an id, a density, a pressure, normals): the readers of VTK, VTU, BGEO and PLY
 * keep every numeric one, `info` lists them, `convert` writes them
 * (particle_arrays.h). Integer types narrower than 32 bits are kept as int32,
 * 64-bit integers as float64. */
typedef enum { FS_ARRAY_F32, FS_ARRAY_F64, FS_ARRAY_I32, FS_ARRAY_U32 } fs_array_type;
typedef struct fs_point_array {
    char name[64];
    int ncomp;          /* components per particle */
    fs_array_type type; /* of every value */
    void *data;         /* n * ncomp values, particle after particle */
} fs_point_array;

typedef struct fs_particles {
    size_t n;
    float *x, *y, *z;       /* positions, scene units */
    float *vx, *vy, *vz;    /* velocity or NULL */
    float *color;           /* linear RGB, 3 floats per particle, or NULL */
    int32_t *phase;         /* phase / material id or NULL */
    float bmin[3], bmax[3]; /* bounding box, kept current by fs_particles_bounds */
    float radius;           /* radius stored in the file, 0 when unknown */
    int narrays;            /* the file's other arrays (fs_point_array), freed with the set */
    fs_point_array *arrays;
} fs_particles;

/* Allocates n particles with positions and the attributes named in fields
 * (FS_HAS_*), zero-filled. Returns FS_OK or FS_ERR_RUNTIME. */
int fs_particles_alloc(fs_particles *p, size_t n, unsigned fields);
void fs_particles_free(fs_particles *p);
unsigned fs_particles_fields(const fs_particles *p);
void fs_particles_bounds(fs_particles *p);
/* FS_ERR_INPUT with "name: ..." when there are no particles, a position is NaN/Inf
 * or the radius (0: none given) lies outside [1e-9, 1e9]. */
int fs_particles_validate(const fs_particles *p, const char *name);
/* Per-axis quantile box [frac, 1 - frac] (from at most 65536 evenly spaced
 * particles) over the sampled particles inside [in_lo, in_hi] (the grid's bulk
 * box): frames the body of the fluid without far-flung spray, and far strays
 * neither widen the box nor shift its quantiles. */
void fs_particles_core_bounds_in(const fs_particles *p, float frac, const float in_lo[3], const float in_hi[3],
                                 float lo[3], float hi[3]);

#ifdef __cplusplus
}
#endif
#endif
