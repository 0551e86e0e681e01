/* Writes a rendered view: PNG (shaded image, sRGB) or EXR (RGBA + the G-buffer
 * AOVs as named channels + provenance attributes), chosen by the extension. */
#ifndef FS_RENDER_OUTPUT_H
#define FS_RENDER_OUTPUT_H
#include "gbuffer.h"
#include "provenance.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* The depth an EXR holds where coverage is 0 (infinity in memory): 0, never a
 * surface's depth (which is positive), finite so that OpenImageIO's idiff reports
 * finite errors (it gives inf or nan for inf or NaN pixels), and OpenImageIO's own
 * "zero is infinitely far" convention (oiiotool --zover:zeroisinf=1). Written as
 * the attribute fluidsurf:empty_depth = "0" (docs/DESIGN.md, "The G-buffer"). */
#define FS_EXR_EMPTY_DEPTH 0.0f
#define FS_EXR_EMPTY_DEPTH_TEXT "0"

/* EXR channel names: R G B A depth normal.X normal.Y normal.Z thickness coverage,
 * then every AOV of g by name, in g's order: NAME for a 1-component AOV, NAME.R
 * NAME.G NAME.B NAME.A for a 4-component one (color.R.., own.R.., caustics). */
int fs_write_render(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov);
/* fs_write_render of a view of scene s through cam: an EXR also gets the layer
 * solid_depth when s has solids (fs_solids_layer), so that diff and the C API
 * leave out the pixels compare leaves out. */
int fs_write_render_in_scene(const char *path, const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g,
                             const float *rgba, const fs_provenance *prov);
/* Reads an EXR written by fs_write_render (or any EXR with the same channel
 * names: R G B A depth normal.X normal.Y normal.Z coverage; thickness optional)
 * into g (allocated here) and rgba (malloc'd, 4 per pixel). Every other channel
 * NAME without a '.' and every complete group NAME.R/G/B/A comes back as the AOV
 * NAME (in the order the file lists them); channels of any other shape are skipped.
 * Depth is infinity wherever coverage is not above 0.5, whatever the file holds
 * there (0 in fluidsurf's files since fluidsurf:empty_depth, infinity before, NaN).
 * r_out: the particle radius from the "fluidsurf:r" attribute, 0 when absent.
 * FS_ERR_INPUT "FILE: no channel 'depth'" etc., or for a channel group that
 * cannot be an AOV (fs_gbuffer_add_aov: a 1-channel "color", too many groups). */
int fs_read_render(const char *path, fs_gbuffer *g, float **rgba, float *r_out);
/* The camera an EXR was rendered with (its fluidsurf:camera), exactly: eye,
 * target, up, fov and size; the clip planes are left as c has them.
 * FS_ERR_INPUT "FILE: no fluidsurf:camera ..." for an EXR without one (not
 * rendered by fluidsurf), or the file's or the text's own error. */
int fs_read_render_camera(const char *path, fs_camera *c);
/* FS_ERR_INPUT unless path ends in .png or .exr. */
int fs_check_render_path(const char *path);

#ifdef __cplusplus
}
#endif
#endif
