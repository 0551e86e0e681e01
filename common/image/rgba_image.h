/* An RGBA image to draw into (linear, 4 floats a pixel, rows top to bottom)
 * and text drawn onto it: through OpenImageIO (image_text.cpp, in the module
 * oiio_load.c opens) or stb_truetype without it (text_stb.c). The figures
 * (common/figure) are drawn on it. */
#ifndef FS_RGBA_IMAGE_H
#define FS_RGBA_IMAGE_H
#include "image_io.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_rgba_image {
    int w, h;
    float *pix; /* 4*w*h */
} fs_rgba_image;

int fs_rgba_alloc(fs_rgba_image *im, int w, int h, const float fill[4]);
void fs_rgba_free(fs_rgba_image *im);
/* Draws text with its top-left corner at (x, y), DejaVuSans at size px.
 * A missing font: FS_ERR_RUNTIME in the build with OpenImageIO; without it
 * (text_stb.c) FS_OK, nothing drawn, and one fs_note for the process. */
int fs_draw_text(fs_rgba_image *im, int x, int y, const char *text, int size, const float rgb[3]);
/* Width and height in pixels that text would take. A missing font: as
 * fs_draw_text (without OpenImageIO, FS_OK with an estimate: 0.6 em a code point
 * wide, 1.2 em high). */
int fs_text_size(const char *text, int size, int *w, int *h);

#ifdef __cplusplus
}
#endif
#endif
