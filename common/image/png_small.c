/* A box-filtered small PNG (png_small.h). */
#include "png_small.h"
#include "fs_error.h"
#include "image_io.h"
#include <stdlib.h>

int fs_write_png_small(const char *path, const float *rgba, int w, int h, int max_side)
{
    if (!rgba || w < 1 || h < 1 || max_side < 1) return fs_fail(FS_ERR_INPUT, "%s: no image to write", path);
    int longer = w > h ? w : h, f = (longer + max_side - 1) / max_side;
    int sw = w / f, sh = h / f; /* a partial last block is dropped */
    float *pix = calloc((size_t)sw * sh * 4, sizeof(float));
    if (!pix) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    for (int y = 0; y < sh * f; y++)
        for (int x = 0; x < sw * f; x++)
            for (int c = 0; c < 4; c++)
                pix[((size_t)(y / f) * sw + x / f) * 4 + c] += rgba[((size_t)y * w + x) * 4 + c] / (float)(f * f);
    const char *ch[4] = {"R", "G", "B", "A"};
    fs_image img = {sw, sh, 4, ch, pix};
    int rc = fs_write_png(path, &img);
    free(pix);
    return rc;
}
