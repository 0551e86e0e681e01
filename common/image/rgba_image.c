/* RGBA images to draw into (rgba_image.h). */
#include "rgba_image.h"
#include "fs_error.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int fs_rgba_alloc(fs_rgba_image *im, int w, int h, const float fill[4])
{
    static const float clear[4] = {0, 0, 0, 0};
    memset(im, 0, sizeof *im);
    if (w <= 0 || h <= 0 || (size_t)w > SIZE_MAX / 16 / (size_t)h)
        return fs_fail(FS_ERR_INPUT, "image: bad size %dx%d", w, h);
    size_t n = (size_t)w * h;
    float *pix = malloc(n * 4 * sizeof(float));
    if (!pix) return fs_fail(FS_ERR_RUNTIME, "image: out of memory for %dx%d RGBA", w, h);
    if (!fill) fill = clear;
    for (size_t i = 0; i < n; i++) memcpy(pix + 4 * i, fill, 4 * sizeof(float));
    im->w = w;
    im->h = h;
    im->pix = pix;
    return FS_OK;
}

void fs_rgba_free(fs_rgba_image *im)
{
    if (!im) return;
    free(im->pix);
    memset(im, 0, sizeof *im);
}
