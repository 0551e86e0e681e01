/* PNG files through header-only stb (libstb-dev), and the image readers'
 * dispatch, for the build without OpenImageIO (FS_WITH_OIIO=OFF). A file is
 * read by its first bytes: EXR goes to image_exr_core.c, PNG to stb_image;
 * any other format is refused with one line naming the option. */
#include "image_exr_core.h"
#include "image_io.h"
#include "fs_error.h"
#include "output_file.h"

#include <errno.h>
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
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_LINEAR
#define STBI_NO_HDR
/* stb declares static functions this file never uses: reported at the file's end. */
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

int fs_write_png8(const char *path, const unsigned char *pix, int w, int h, int nch)
{
    if (!pix || w <= 0 || h <= 0 || nch < 1 || nch > 4)
        return fs_fail(FS_ERR_INPUT, "%s: no 8-bit image with 1 to 4 channels to write", path);
    /* libpng's (so OpenImageIO's) limit, kept so both builds accept the same images. */
    if (w > 1000000 || h > 1000000)
        return fs_fail(FS_ERR_RUNTIME, "%s: a %dx%d PNG exceeds 1000000 pixels a side", path, w, h);
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    int ok = stbi_write_png(tmp, w, h, nch, pix, w * nch);
    if (!ok) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot write the PNG (disk full or out of memory?)", path);
    }
    return fs_output_end(path, tmp, 1);
}

int fs_write_png(const char *path, const fs_image *img)
{
    if (!img || img->w <= 0 || img->h <= 0 || img->nch <= 0 || !img->pix)
        return fs_fail(FS_ERR_INPUT, "%s: no image to write", path);
    /* As image_oiio.cpp: first 3 channels sRGB-encoded (gray for 1-2 channels); alpha linear. */
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

typedef enum { KIND_EXR, KIND_PNG, KIND_OTHER } file_kind;

static int sniff(const char *path, file_kind *kind)
{
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    unsigned char m[8] = {0};
    size_t got = fread(m, 1, sizeof m, f);
    fclose(f);
    if (got == 0) return fs_fail(FS_ERR_INPUT, "%s: empty file", path);
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01}, png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    *kind = got >= 4 && !memcmp(m, exr, 4) ? KIND_EXR : got == 8 && !memcmp(m, png, 8) ? KIND_PNG : KIND_OTHER;
    if (*kind == KIND_OTHER)
        return fs_fail(FS_ERR_INPUT, "%s: not a PNG or EXR file (reading other image formats needs a build with FS_WITH_OIIO=ON)",
                       path);
    return FS_OK;
}

/* PNG codes / 255 (or / 65535 for 16-bit files), as stored: alpha not premultiplied. */
static int read_png(const char *path, fs_image *img)
{
    int w, h, nch;
    int sixteen = stbi_is_16_bit(path);
    void *data = sixteen ? (void *)stbi_load_16(path, &w, &h, &nch, 0) : (void *)stbi_load(path, &w, &h, &nch, 0);
    if (!data) return fs_fail(FS_ERR_INPUT, "%s: bad PNG: %s", path, stbi_failure_reason());
    static const char *const names[4][4] = {{"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    size_t count = (size_t)w * h * nch;
    img->pix = malloc(count * sizeof(float));
    img->chnames = calloc((size_t)nch, sizeof(char *));
    img->w = w, img->h = h, img->nch = nch;
    int ok = img->pix && img->chnames;
    for (int c = 0; ok && c < nch; c++) ok = (img->chnames[c] = strdup(names[nch - 1][c])) != NULL;
    if (ok)
        for (size_t i = 0; i < count; i++)
            img->pix[i] = sixteen ? ((const unsigned short *)data)[i] / 65535.0f : ((const unsigned char *)data)[i] / 255.0f;
    stbi_image_free(data);
    if (!ok) {
        fs_image_free(img);
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for a %dx%dx%d image", path, w, h, nch);
    }
    return FS_OK;
}

int fs_read_image(const char *path, fs_image *img)
{
    memset(img, 0, sizeof *img);
    file_kind kind;
    int rc = sniff(path, &kind);
    if (rc) return rc;
    return kind == KIND_EXR ? fs_exr_read(path, img) : read_png(path, img);
}

int fs_read_image_attr(const char *path, const char *name, char *buf, int size)
{
    if (size > 0) buf[0] = 0;
    file_kind kind;
    if (sniff(path, &kind)) return -1;
    if (kind == KIND_EXR) return fs_exr_read_attr(path, name, buf, size);
    return 0; /* our PNGs carry no attributes */
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
