/* The method-run layer (docs/DESIGN.md, "The run layer"): the one owner of a
 * method's lifecycle. Every command, test and tool runs a method through it:
 *
 *   fs_run_open     create the method with the scene's field and parameters
 *   fs_run_upload   hand it a frame (builds the neighbour grid unless given one)
 *   fs_run_render   render a view into a G-buffer sized to the camera
 *   fs_run_shade    the shared shading, or the method's own appearance
 *   fs_run_provenance, fs_run_export, fs_run_close
 *
 * Particle lifetime: the caller owns the particle arrays it uploads and keeps
 * them valid until the next upload or fs_run_close (the fs_particles
 * struct itself may go: the method gets the run's copy); a grid passed to
 * fs_run_upload follows the same rule, a grid the run builds is the run's.
 * After a failed upload the run holds no frame (the arrays of the frame before
 * may be freed then too): fs_run_render and fs_run_export fail with the reason. An empty frame renders an empty G-buffer without calling the
 * method. Errors are codes with one message (fs_error.h), never exit(). */
#ifndef FS_RUN_H
#define FS_RUN_H
#include "camera.h"
#include "gbuffer.h"
#include "gl_context.h"
#include "grid.h"
#include "method.h"
#include "particles.h"
#include "provenance.h"
#include "scene.h"
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

/* A rendered view: the G-buffer and, once shaded, the linear RGBA image. */
typedef struct fs_run_image {
    fs_gbuffer g;
    float *rgba; /* 4 floats per pixel, NULL until fs_run_shade */
} fs_run_image;
void fs_run_image_free(fs_run_image *im);

typedef enum { FS_APPEARANCE_SHARED = 0, FS_APPEARANCE_OWN } fs_appearance;

typedef struct fs_run fs_run;

/* Creates method m for scene s (field, light, material; s must outlive the run).
 * values: the parameter values in the order of m's table, or NULL to resolve
 * them from the scene's "M.P=V" settings (fs_method_params_resolve). A method
 * that needs GL needs a current GL 4.5 context: ctx names its renderer for every
 * timing and provenance; NULL asks the current context. */
int fs_run_open(fs_run **out, const fs_method *m, const fs_scene *s, const double *values, const fs_gl_context *ctx);
void fs_run_close(fs_run *r);

const fs_method *fs_run_method(const fs_run *r);
/* The parameter values the method was created with (table order). */
const double *fs_run_values(const fs_run *r);
/* "CPU", or the GL_RENDERER of the context for a GL method. */
const char *fs_run_renderer(const fs_run *r);

/* Hands frame p to the method, with grid g (cell >= the field's H) or NULL to
 * build one; adds the stages "grid" and "upload" to st (may be NULL). */
int fs_run_upload(fs_run *r, const fs_particles *p, const fs_grid *g, fs_stages *st);
/* Writes the method's intermediate surface (after an upload); FS_ERR_INPUT when
 * the method exports nothing or not that kind of file. prov: the file's
 * provenance (fs_run_provenance), or NULL for the run's own with frame 0. */
int fs_run_export(fs_run *r, const char *path, const fs_provenance *prov);

/* Renders the current frame: (re)allocates im->g to the camera size with the
 * layers the method writes, clears it, renders; adds the method's stages. On
 * failure im->g is still sized and empty, so a viewer can show the empty scene. */
/* With on = 1, renders leave out the layers of the method's own look (own,
 * caustics: fs_aov_own_look), so the method neither draws nor reads them back:
 * for a caller that shades with the shared shading only and writes no EXR
 * (the timing tools). Default 0: every layer the method declares. */
void fs_run_shared_only(fs_run *r, int on);
int fs_run_render(fs_run *r, const fs_camera *cam, fs_run_image *im, fs_stages *st);
/* Fills im->rgba (allocated here): the shared shading over the scene's floor,
 * or the method's own appearance (FS_ERR_INPUT when it has none); adds "shade". */
int fs_run_shade(fs_run *r, const fs_camera *cam, fs_run_image *im, fs_appearance a, fs_stages *st);
/* The floor the shared shading draws, by default the frame's lowest particle
 * minus r (fs_scene_floor); the viewer's simulator sets its container's. */
void fs_run_set_floor(fs_run *r, float y);

/* The provenance of this run's output for `frame`: base (or the scene's, when
 * base is NULL) plus method, params, gl_renderer and frame. */
void fs_run_provenance(const fs_run *r, const fs_provenance *base, int frame, fs_provenance *out);
/* The renderer a stage of this run ran on: loading, grids, shading, the normals'
 * renormalization after the read back and the own image's compositing are C on
 * the CPU; the method's other stages ran on fs_run_renderer. */
const char *fs_run_stage_renderer(const fs_run *r, const char *stage);

/* The counting render (docs/DESIGN.md, "Work counters"): a fresh run of m
 * with these values on context ctx (NULL for a CPU method), opened, uploaded
 * (grid g, or NULL to build one) and rendered once with counting on, so its
 * programs are the counting variants and the timed runs' are untouched. im
 * gets the G-buffer, st the stages with their counts. FS_ERR_INPUT when m
 * declares no counters; FS_ERR_RUNTIME naming the counter and stage when one
 * overflowed. Counting is off again on return. */
int fs_run_count(const fs_method *m, const fs_scene *s, const double *values, const fs_gl_context *ctx,
                 const fs_particles *p, const fs_grid *g, const fs_camera *cam, fs_run_image *im, fs_stages *st);
/* FS_ERR_INPUT (fs_fail) naming m when it reports no work counters. */
int fs_run_check_counters(const fs_method *m);

#ifdef __cplusplus
}
#endif
#endif
