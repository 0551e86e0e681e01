/* The GL side of surfels (iwasaki2006 section 5.3): the surfel buffer, the
 * three splatting passes (visibility with an epsilon offset, Gaussian-weighted
 * blending, per-pixel normalisation), the own appearance, and the thickness
 * march through the density grid for the shared shading. */
#ifndef FS_SURFEL_GL_H
#define FS_SURFEL_GL_H
#include "camera.h"
#include "density_grid.h"
#include "gbuffer.h"
#include "gl_target.h"
#include "surfel_set.h"
#include "timing.h"

/* What the appearance shaders need of the scene (all world space). */
typedef struct surfel_look {
    float light_dir[3], light_color[3], ambient;
    float ior, extinction[3], tint[3];
    int up_axis, checker;
    float floor_h, check;
    unsigned caustic_tex; /* GL_TEXTURE_2D_ARRAY or 0 */
    float rect_min[2], rect_max[2];
    unsigned slice_tex; /* GL_TEXTURE_2D_ARRAY of sliced object images, or 0 */
    int nslices;
    float slice_h[9]; /* nslices + 1 plane heights */
} surfel_look;

typedef struct surfel_gl {
    unsigned prog_vis, prog_blend, prog_norm, prog_thick, vao;
    unsigned buf; /* one storage buffer: FS_ERR_INPUT beyond the SSBO limit (4M surfels) */
    size_t n;
    unsigned fbo, zbuf, acc[3], own_tex;
    unsigned grid_tex;
    int grid_dim[3];
    fs_gl_target target;
} surfel_gl;

int surfel_gl_create(surfel_gl *s); /* fs_fail set on error */
void surfel_gl_destroy(surfel_gl *s);
int surfel_gl_upload(surfel_gl *s, const fs_surfel_set *set);
/* Uploads the density grid as a 3D texture for the thickness march. */
int surfel_gl_upload_grid(surfel_gl *s, const fs_density_grid *g);

typedef struct surfel_draw_opts {
    float epsilon;   /* visibility offset, eye-depth units */
    float gauss;     /* g(t) = exp(-gauss t^2) */
    int thickness;   /* march the grid for thickness */
    float step, iso; /* thickness march step (world) and iso value */
    float grid_origin[3], grid_spacing;
} surfel_draw_opts;

/* Renders the surfels into out (and its "own" / "caustics" AOVs when it has them). */
int surfel_gl_render(surfel_gl *s, const fs_camera *cam, const surfel_look *look, const surfel_draw_opts *o,
                     fs_gbuffer *out, fs_stages *t);

#endif
