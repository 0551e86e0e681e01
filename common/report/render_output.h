/* Writes a rendered view: PNG (shaded image, sRGB) or EXR (RGBA + the G-buffer
 * AOVs as named channels + provenance attributes), chosen by the extension. */
#ifndef FS_RENDER_OUTPUT_H
#define FS_RENDER_OUTPUT_H
#include "gbuffer.h"
#include "provenance.h"
#ifdef __cplusplus
extern "C" {
#endif

/* EXR channel names: R G B A depth normal.X normal.Y normal.Z thickness coverage
 * (+ color.R color.G color.B color.A when the method wrote colour; + own.R own.G
 * own.B own.A caustics when it wrote its own appearance). */
int fs_write_render(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov);
/* Reads an EXR written by fs_write_render (or any EXR with the same channel
 * names: R G B A depth normal.X normal.Y normal.Z coverage; thickness and
 * color.* optional) into g (allocated here) and rgba (malloc'd, 4 per pixel).
 * r_out: the particle radius from the "fluidsurf:r" attribute, 0 when absent.
 * FS_ERR_INPUT "FILE: no channel 'depth'" etc. */
int fs_read_render(const char *path, fs_gbuffer *g, float **rgba, float *r_out);
/* FS_ERR_INPUT unless path ends in .png or .exr. */
int fs_check_render_path(const char *path);

#ifdef __cplusplus
}
#endif
#endif
