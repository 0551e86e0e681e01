/* Glyph coverage composited into a figure, shared by both builds' text
 * (image_text.cpp through OpenImageIO, text_stb.c without it). */
#ifndef FS_TEXT_BLEND_H
#define FS_TEXT_BLEND_H
#include "rgba_image.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Blends a cw x ch coverage buffer (values in [0,1], clamped; row-major) of colour
 * rgb into im with the buffer's top-left pixel at (x, y), clipped to the image.
 * Blending is in sRGB-encoded values, as text renderers do. */
void fs_text_blend(fs_rgba_image *im, int x, int y, const float *cover, int cw, int ch, const float rgb[3]);

#ifdef __cplusplus
}
#endif
#endif
