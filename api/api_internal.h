/* The library's objects behind include/fluidsurf/fluidsurf.h (docs/DESIGN.md,
 * "The library"): thin wrappers of the run layer's types. */
#ifndef FS_API_INTERNAL_H
#define FS_API_INTERNAL_H
#include "fluidsurf/fluidsurf.h"
#include "mesh/trimesh.h"
#include "particles.h"
#include "provenance.h"
#include "run.h"
#include "scene.h"
#include "timing.h"

struct fluidsurf_particles {
    fs_particles p;
    int owned; /* 1: read from a file, the arrays are ours */
};

struct fluidsurf_scene {
    fs_scene s;
    int radius_set; /* set by the caller: wins over the file's and the estimate */
};

struct fluidsurf_mesh {
    fs_trimesh m;
    float radius;
    fs_provenance prov;
};

struct fluidsurf_image {
    fs_run_image im;
    float radius;
    int has_camera; /* rendered here: camera is the one it was rendered with */
    fs_camera camera;
    fs_stages st;
    char renderer[FS_MAX_STAGES][256];
    fs_provenance prov;
};

/* The run layer's camera as the API's. */
void fs_api_camera_out(const fs_camera *k, fluidsurf_camera *c);
/* Once per process: the built-in methods registered, notes and progress silenced. */
void fs_api_init(void);
/* The scene of one render or mesh of method m on particles fp into sc (the
 * caller's, with params "param=value" of m added), m's parameter values, and
 * p, the particles validated: r and the camera settled as the command line's
 * first frame settles them. sc is large: the caller allocates it. */
int fs_api_prepare(const fluidsurf_scene *s, const fluidsurf_particles *fp, const fs_method *m,
                   const char *const *params, int nparams, fs_scene *sc, fs_particles *p, double *values);
/* Takes (on = 1) or releases the lock that runs renders and meshes one at a time:
 * each uses every core, and the methods' process-wide state needs no more care. */
void fs_api_lock(int on);
/* With the lock held: the shared GL context made (on first use) and current;
 * fs_api_gl gives it (NULL before). */
int fs_api_gl_acquire(void);
const struct fs_gl_context *fs_api_gl(void);
/* code with the message of fs_fail kept (the library never prints). */
int fs_api_check(const void *ptr, const char *what);
/* Adds or replaces name ("fluidsurf:NAME") = value in p, after the checks of
 * fluidsurf_image_set_provenance (FS_ERR_INPUT naming what is wrong). */
int fs_api_set_provenance(fs_provenance *p, const char *name, const char *value);

#endif
