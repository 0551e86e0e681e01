/* PNG writing in every build, through header-only stb_image_write with zlib's
 * deflate: each write and the close are checked, and the file is renamed into place
 * only after both succeed (OpenImageIO's PNG writer reports no error on a full disk:
 * it left a truncated file and exit 0). */
#include "image_io.h"
#include "fs_error.h"
#include "output_file.h"
#include "srgb.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

/* zlib instead of stb's own deflate: smaller files, and the library is linked anyway. */
static unsigned char *zlib_compress(unsigned char *data, int len, int *out_len, int quality)
{
    (void)quality;
    uLongf n = compressBound((uLong)len);
    unsigned char *out = malloc(n);
    if (!out || compress2(out, &n, data, (uLong)len, 6) != Z_OK) {
        free(out);
        return NULL;
    }
    *out_len = (int)n;
    return out;
}
#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

/* Writes n bytes to path through a temporary, checking every step. */
static int write_all(const char *path, const unsigned char *data, size_t n)
{
    fs_output out;
    int rc = fs_output_open(&out, path);
    if (rc) return rc;
    fwrite(data, 1, n, out.f); /* a short write sets the stream's error: fs_output_close reports it */
    return fs_output_close(&out, 1);
}

int fs_write_png8(const char *path, const unsigned char *pix, int w, int h, int nch)
{
    if (!pix || w <= 0 || h <= 0 || nch < 1 || nch > 4)
        return fs_fail(FS_ERR_INPUT, "%s: no 8-bit image with 1 to 4 channels to write", path);
    /* libpng's limit, kept so that OpenImageIO reads back what is written. */
    if (w > 1000000 || h > 1000000)
        return fs_fail(FS_ERR_RUNTIME, "%s: a %dx%d PNG exceeds 1000000 pixels a side", path, w, h);
    /* stb_image_write sizes its filtered copy, (w*nch + 1) * h bytes, in int. */
    if (((size_t)w * nch + 1) * (size_t)h > INT_MAX)
        return fs_fail(FS_ERR_INPUT,
                       "%s: a %dx%d PNG of %d channels is too large to write (stb_image_write counts its bytes in int)",
                       path, w, h, nch);
    int len = 0;
    unsigned char *png = stbi_write_png_to_mem(pix, w * nch, w, h, nch, &len);
    if (!png || len <= 0) {
        free(png);
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for a %dx%d PNG", path, w, h);
    }
    int rc = write_all(path, png, (size_t)len);
    free(png);
    return rc;
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
