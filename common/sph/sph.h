/* SPH fluid simulator after Mueller et al. 2003, as inacio2010 section III uses
 * it: poly6 density, spiky pressure gradient, viscosity-kernel Laplacian,
 * gravity; ideal-gas (the paper) or Tait equation of state. Solid walls are
 * two layers of static boundary particles: mass in the density (Akinci et al.
 * 2012), extrapolated wall pressure (Adami et al. 2012), Lennard-Jones repulsion
 * inside the rest spacing (Monaghan 1994); see sph_cpu.c. A JSON scene's static
 * obstacles (boxes, spheres; obstacles.h) are the same: their lattice sites as
 * deep as two layers below the surface become boundary particles. Neighbours come
 * from the common counting-sort grid (grid.h), rebuilt every step. Two paths
 * run the same algorithm: C + OpenMP (sph_cpu.c) and GL compute shaders on the
 * current context (sph_gpu.c, shaders/sph/). Units: metres, seconds, kg; up +y.
 * The container is the box [box_lo, box_hi]; particle centres stay inside it. */
#ifndef FS_SPH_H
#define FS_SPH_H
#include <stddef.h>
#include "obstacles.h"
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef enum { FS_SPH_TAIT = 0, FS_SPH_IDEAL } fs_sph_eos;

typedef struct fs_sph_params {
    float r;        /* particle radius (lattice spacing 2r); default 0.025 */
    float support;  /* kernel support H in multiples of r; default 4 */
    float rho0;     /* rest density, default 1000 */
    fs_sph_eos eos; /* default Tait */
    float c;        /* speed of sound; 0: 10x the scene's expected peak speed */
    float k;        /* ideal gas p = k (rho - rho0); 0: c^2 (same stiffness at rho0) */
    float nu;       /* kinematic viscosity (m^2/s) of the Laplacian term; default 0.05 */
    float gravity;  /* along -y, default 9.81 */
    float cfl;      /* lambda of dt <= lambda H / (c + v_max); default 0.2 */
    float fixed_dt; /* > 0: every step is this long, whatever the bound (inacio2010 Fig. 6) */
} fs_sph_params;

/* Running totals since creation; per frame values are differences. */
typedef struct fs_sph_stats {
    double t; /* simulated time */
    long steps;
    float dt_min, dt_max; /* over the steps taken */
    float bound_min;      /* smallest stability bound met (CFL, viscosity) */
    long violations;      /* steps whose dt exceeded the bound (fixed-dt mode only) */
    float v_max;          /* largest speed after the last step */
    long clamps;          /* safety clamps: particle centres put back into the box */
    long nonfinite;       /* particles with a NaN/Inf position or velocity, last step */
    double step_ms;       /* wall time in fs_sph_step, glFinish included on the GPU path */
} fs_sph_stats;

typedef struct fs_sph fs_sph;

/* Scene names: dam_break, double_dam_break, drop, spouts, pool (at rest). */
extern const char *const fs_sph_scene_names[];
void fs_sph_params_default(fs_sph_params *p);
/* Builds the scene with about `particles` fluid particles (0: the scene's
 * default; the box scales with the count at fixed r) on the CPU path, or on
 * the GPU path (gpu = 1; needs a current GL 4.5 context). FS_ERR_INPUT for an
 * unknown scene or bad parameter, FS_ERR_RUNTIME otherwise. */
int fs_sph_create(fs_sph **out, const char *scene, size_t particles, const fs_sph_params *p, int gpu);
void fs_sph_destroy(fs_sph *s);
/* Advances by frame_dt: adaptive steps within the bound, or fixed_dt steps. */
int fs_sph_advance(fs_sph *s, double frame_dt);
/* One step of length dt (no bound applied; violations counted). */
int fs_sph_step(fs_sph *s, float dt);
/* The largest dt the CFL and viscosity conditions allow now. */
float fs_sph_dt_bound(const fs_sph *s);
/* The fluid particles now (positions, velocities, colour and phase for
 * coloured scenes, radius r). p is allocated; free with fs_particles_free. */
int fs_sph_get(fs_sph *s, fs_particles *p);
const fs_sph_stats *fs_sph_get_stats(const fs_sph *s);
const fs_sph_params *fs_sph_get_params(const fs_sph *s);
void fs_sph_box(const fs_sph *s, float lo[3], float hi[3]);
int fs_sph_move_box(fs_sph *s, const float delta[3],
                    double frame_dt); /* advances frame_dt while the walls move by delta (0: jump; sph_move.c) */
size_t fs_sph_count(const fs_sph *s); /* active fluid particles */
size_t fs_sph_boundary_count(const fs_sph *s);
float fs_sph_mass(const fs_sph *s); /* fluid particle mass */
/* The scene's static obstacles in the simulation's frame (the JSON's
 * coordinates times the scene scale: exactly them at particles 0); none for
 * the built-in scenes. fs_sph_move_box moves them with the walls. */
const fs_obstacles *fs_sph_obstacles(const fs_sph *s);

/* Density and depth measures of the current state (CPU, from fs_sph_get). */
typedef struct fs_sph_measure {
    double density_err;     /* mean max(rho, rho0)/rho0 - 1 over the fluid (compression) */
    double density_abs_err; /* mean |rho - rho0| / rho0 over interior particles (>= H below the surface) */
    double depth;           /* mean over the floor (columns of 2r) of the free-surface height, where
                             * the fluid fraction sum m/rho0 W falls to 1/2: the water's volume over the
                             * floor area, waves or not (a dry column counts 0) */
    double depth_expected;  /* N (2r)^3 / floor area */
    size_t outside;         /* particle centres outside the box (or non-finite) */
    double kinetic;         /* mean kinetic energy per unit mass, 0.5 |v|^2 */
} fs_sph_measure;
int fs_sph_measure_state(fs_sph *s, fs_sph_measure *m);

#ifdef __cplusplus
}
#endif
#endif
