/* Image helpers that need no OpenImageIO, shared by both builds' image files
 * (image_oiio.cpp, compiled into the OpenImageIO module with this file, and
 * image_stb.c / image_exr_core.c without it): channel lookup, the linear to sRGB
 * 8-bit conversion of fs_write_png, the size check of a read, and fs_image_free. */
#include "image_io.h"
#include "fs_error.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int fs_image_channel(const fs_image *img, const char *name)
{
    for (int c = 0; c < img->nch; c++)
        if (img->chnames && img->chnames[c] && strcmp(img->chnames[c], name) == 0) return c;
    return -1;
}

int fs_write_png(const char *path, const fs_image *img)
{
    if (!img || img->w <= 0 || img->h <= 0 || img->nch <= 0 || !img->pix)
        return fs_fail(FS_ERR_INPUT, "%s: no image to write", path);
    /* First 3 channels sRGB-encoded (gray for 1-2 channel images); alpha linear. */
    int color = img->nch >= 3 ? 3 : 1, out_nch = img->nch >= 4 ? 4 : color;
    size_t n = (size_t)img->w * img->h;
    unsigned char *buf = malloc(n * out_nch);
    if (!buf) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for a %dx%d PNG", path, img->w, img->h);
    for (size_t i = 0; i < n; i++) {
        const float *p = img->pix + i * img->nch;
        for (int c = 0; c < color; c++) buf[i * out_nch + c] = fs_srgb_encode8(p[c]);
        if (out_nch == 4) {
            float a = p[3] > 0 ? (p[3] < 1 ? p[3] : 1) : 0; /* also NaN -> 0 */
            buf[i * out_nch + 3] = (unsigned char)(a * 255.0f + 0.5f);
        }
    }
    int rc = fs_write_png8(path, buf, img->w, img->h, out_nch);
    free(buf);
    return rc;
}

int fs_image_fits_file(const char *path, double w, double h, int nch)
{
    struct stat st;
    if (stat(path, &st) == 0 && w * h * nch * 4 > 2064.0 * (double)st.st_size + 1e6)
        return fs_fail(FS_ERR_INPUT, "%s: image of %.0fx%.0fx%d is more than the file's %lld bytes can hold", path, w, h,
                       nch, (long long)st.st_size);
    return FS_OK;
}

void fs_image_free(fs_image *img)
{
    if (!img) return;
    if (img->chnames)
        for (int c = 0; c < img->nch; c++) free((void *)img->chnames[c]);
    free((void *)img->chnames);
    free(img->pix);
    memset(img, 0, sizeof *img);
}
