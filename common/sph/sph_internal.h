/* Shared state of the SPH simulator (sph.c, sph_scenes.c, sph_cpu.c,
 * sph_gpu.c). Particle arrays hold the boundary particles first [0, nb), then
 * the fluid [nb, nb + cap); the active fluid is [nb, nb + nf). The arrays are
 * current on the CPU path; on the GPU path the GPU buffers are, and
 * fs_sph_sync() reads them back. */
#ifndef FS_SPH_INTERNAL_H
#define FS_SPH_INTERNAL_H
#include "grid.h"
#include "sph.h"

#define FS_SPH_MAX_SPOUTS 4

typedef struct fs_sph_spout {
    float pos[3], dir[3]; /* nozzle centre and unit direction */
    float speed;
    int width; /* nozzle is width x width particles */
    int phase;
    double next; /* time of the next emitted layer */
} fs_sph_spout;

struct fs_sph_gpu;

struct fs_sph {
    fs_sph_params prm;
    float H, mass, B, k; /* support, fluid mass, Tait B, ideal k */
    float box_lo[3], box_hi[3];
    size_t nb, cap, nf;
    float *x, *y, *z, *vx, *vy, *vz, *m; /* m: mass (fluid) or Psi (boundary) */
    int32_t *phase;                      /* per particle (boundary: -1) */
    int ncolors;                         /* > 1: write colour and phase */
    float colors[8][3];
    int nspouts;
    fs_sph_spout spout[FS_SPH_MAX_SPOUTS];
    fs_obstacles obstacles; /* the static solids at the scene's scale (their boundary particles are in [0, nb)) */
    fs_sph_stats st;
    /* CPU path scratch */
    fs_grid g;
    float *vel4, *rho, *prs; /* sorted velocity, density, pressure per slot */
    /* GPU path */
    struct fs_sph_gpu *gpu;
    int dirty; /* GPU path: CPU arrays stale */
};

/* sph_scenes.c: fills box, particles, obstacles, colours and spouts; sets prm.c when 0. */
int fs_sph_scene_build(fs_sph *s, const char *scene, size_t particles);
/* Allocates the particle arrays for nb + cap particles. */
int fs_sph_alloc(fs_sph *s, size_t nb, size_t cap);

/* Equation of state shared by both paths (the shaders repeat it). */
static inline float fs_sph_pressure(const fs_sph *s, float rho)
{
    float p;
    if (s->prm.eos == FS_SPH_TAIT) {
        float q = rho / s->prm.rho0, q2 = q * q, q4 = q2 * q2;
        p = s->B * (q4 * q2 * q - 1.0f);
    } else {
        p = s->k * (rho - s->prm.rho0);
    }
    return p > 0.0f ? p : 0.0f; /* no tension: free-surface particles would clump */
}

/* sph_cpu.c */
int fs_sph_cpu_step(fs_sph *s, float dt);
/* sph_gpu.c */
int fs_sph_gpu_init(fs_sph *s);
int fs_sph_gpu_step(fs_sph *s, float dt);
int fs_sph_gpu_upload(fs_sph *s, size_t first, size_t count); /* particles [first, first + count) */
int fs_sph_gpu_read(fs_sph *s);
void fs_sph_gpu_free(fs_sph *s);

#endif
