/* The method interface (docs/DESIGN.md, "Adding a method"): a struct of function
 * pointers, registered in one registry (registry.c; the built-in table is in the
 * layer above, methods/builtin_methods.h). A method turns particles + camera into a G-buffer; only the
 * run layer (common/run/run.h) calls its functions. */
#ifndef FS_METHOD_H
#define FS_METHOD_H
#include "camera.h"
#include "gbuffer.h"
#include "grid.h"
#include "kernels.h"
#include "params.h"
#include "particles.h"
#include "provenance.h"
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

/* What every method sees of the scene. */
struct fs_scene;
typedef struct fs_method_setup {
    fs_field field; /* r, V, kernel, H, iso */
    /* The method's parameter struct, every field filled (fs_method_params_fill);
     * create() copies what it keeps, so it need only live during create(). */
    const void *params;
    /* Light, material, floor and up axis, for methods with their own appearance
     * (the "own" AOV); NULL means fs_scene_defaults(). */
    const struct fs_scene *scene;
} fs_method_setup;

/* An optional G-buffer layer a method writes (gbuffer.h): the run layer
 * allocates each declared one, the EXR writer and reader keep it by name. */
typedef struct fs_aov_def {
    const char *name; /* FS_AOV_COLOR, FS_AOV_OWN, ... or a method's own */
    int ncomp;        /* 1 or 4 */
    int needs_color;  /* 1: written only when the particles carry colour */
} fs_aov_def;

typedef struct fs_method {
    const char *name;
    const char *description; /* one line */
    const char *paper;       /* "" for our own */
    const char *appearance;  /* its own look, for `methods` (NULL: only the shared shading) */
    const char *exports;     /* what export_file writes, for `methods` (NULL: nothing) */
    int needs_gl;            /* 1: an OpenGL 4.5 context must be current */
    int grid_use;            /* FS_GRID_KEPT (0), FS_GRID_AT_UPLOAD or FS_GRID_UNUSED, below */
    /* One view's render cost relative to spheres (1), for compare --shard's
     * split (only the shards' balance depends on it). Every method declares one,
     * > 0 (test_method_params); the built-ins' are their frame totals in one
     * llvmpipe run (docs/DESIGN.md, "Sharded studies"). */
    double cost;
    /* The work counters it reports (FS_CNT_BIT of counters.h, or-ed); 0: none
     * yet, and --counters refuses it. */
    unsigned counters;
    /* The AOVs render() fills (render finds each in out by name); a method with
     * its own appearance declares FS_AOV_OWN. */
    const fs_aov_def *aovs;
    int naovs;
    const fs_param_def *params; /* one entry per field of its parameter struct */
    int nparams;
    size_t params_size; /* sizeof that struct */
    /* Returns NULL on failure with fs_fail() set. */
    void *(*create)(const fs_method_setup *setup);
    /* The frame and a grid with cell >= field.H (NULL for FS_GRID_UNUSED). Called by the run layer only (run.h),
     * which keeps both (structs and arrays) valid and in place until the next upload
     * or destroy, so a method may keep these pointers until then. */
    int (*upload)(void *self, const fs_particles *p, const fs_grid *g);
    /* Renders one view into out (already sized to the camera); adds stage times. */
    int (*render)(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *t);
    void (*destroy)(void *self);
    /* Optional (NULL when none): after upload, writes the method's intermediate
     * surface to path, its kind chosen by the extension (surfels: .vdb density
     * grid, .ply surfels). FS_ERR_INPUT for an extension it does not write.
     * prov: the output's provenance, for the files that carry it (mesh). */
    int (*export_file)(void *self, const char *path, const fs_provenance *prov);
} fs_method;

/* What upload() does with the grid it is given, so that the run layer builds
 * and keeps no grid that nobody reads (20 bytes a particle): KEPT, the default,
 * keeps pointers into it until the next upload; AT_UPLOAD reads it only during
 * upload (a grid the run built is freed right after); UNUSED ignores it (the run
 * builds none and passes NULL). */
enum { FS_GRID_KEPT = 0, FS_GRID_AT_UPLOAD = 1, FS_GRID_UNUSED = 2 };

enum { FS_METHOD_HIDDEN = 1 }; /* registered, found by name, not listed */
/* Adds m to the registry (again: no-op). FS_ERR_INPUT when another method has its name. */
int fs_method_register(const fs_method *m, int flags);
/* By name, hidden ones included; NULL when none. */
const fs_method *fs_method_find(const char *name);
/* The listed (not hidden) methods, in registration order. */
int fs_method_count(void);
const fs_method *fs_method_at(int i);
/* m's declaration of the AOV called name, NULL when it writes none such
 * (fs_method_aov(m, FS_AOV_OWN): whether m has its own appearance). */
const fs_aov_def *fs_method_aov(const fs_method *m, const char *name);
/* 1 when m writes AOV d for particles p (a colour layer needs particle colours). */
int fs_method_aov_wanted(const fs_aov_def *d, const fs_particles *p);
/* Index of a parameter in m->params, or -1. */
int fs_method_param_index(const fs_method *m, const char *name);
/* For create(): FS_OK when r, H, V and iso are all positive, else FS_ERR_INPUT
 * (fs_fail) naming the method. */
int fs_method_check_field(const char *method, const fs_field *f);
/* Writes m's parameter values (in table order; NULL: the defaults) into dst, a
 * struct of m->params_size bytes, each at its table entry's offset (any other
 * byte 0). FS_ERR_RUNTIME (fs_fail) when the table does not fit the struct. */
int fs_method_params_fill(const fs_method *m, const double *values, void *dst);
/* The same into malloc'd memory (free() it after create()); NULL with fs_fail set on failure. */
void *fs_method_params_alloc(const fs_method *m, const double *values);
/* For create(): copies the setup's parameter struct (size bytes) into dst;
 * FS_ERR_RUNTIME (fs_fail) naming the method when the setup has none. */
int fs_method_params_copy(const char *method, const fs_method_setup *setup, void *dst, size_t size);
/* For create(): the field checked (fs_method_check_field) into f, the
 * parameters copied into params (size bytes), and the scene into scene (the
 * defaults when the setup has none). */
int fs_method_setup_take(const char *method, const fs_method_setup *setup, fs_field *f, void *params, size_t size,
                         struct fs_scene *scene);

#ifdef __cplusplus
}
#endif
#endif
