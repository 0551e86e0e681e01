/* Writes a rendered view: PNG (shaded image, sRGB) or EXR (RGBA + the G-buffer
 * AOVs as named channels + provenance attributes), chosen by the extension. */
#ifndef FS_RENDER_OUTPUT_H
#define FS_RENDER_OUTPUT_H
#include "gbuffer.h"
#include "provenance.h"
#ifdef __cplusplus
extern "C" {
#endif

/* EXR channel names: R G B A depth normal.X normal.Y normal.Z thickness coverage,
 * then every AOV of g by name, in g's order: NAME for a 1-component AOV, NAME.R
 * NAME.G NAME.B NAME.A for a 4-component one (color.R.., own.R.., caustics). */
int fs_write_render(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov);
/* Reads an EXR written by fs_write_render (or any EXR with the same channel
 * names: R G B A depth normal.X normal.Y normal.Z coverage; thickness optional)
 * into g (allocated here) and rgba (malloc'd, 4 per pixel). Every other channel
 * NAME without a '.' and every complete group NAME.R/G/B/A comes back as the AOV
 * NAME (in the order the file lists them); channels of any other shape are skipped.
 * r_out: the particle radius from the "fluidsurf:r" attribute, 0 when absent.
 * FS_ERR_INPUT "FILE: no channel 'depth'" etc., or for a channel group that
 * cannot be an AOV (fs_gbuffer_add_aov: a 1-channel "color", too many groups). */
int fs_read_render(const char *path, fs_gbuffer *g, float **rgba, float *r_out);
/* FS_ERR_INPUT unless path ends in .png or .exr. */
int fs_check_render_path(const char *path);

#ifdef __cplusplus
}
#endif
#endif
