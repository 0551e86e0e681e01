/* PNG reading through header-only stb (libstb-dev), and the image readers'
 * dispatch, in every build: a file is read by its first bytes, a PNG here with
 * stb_image, a scanline EXR by image_exr_core.c, a tiled or deep EXR by the
 * OpenImageIO module (fs_read_image_oiio: refused in the build without it); any
 * other format is refused. Attributes come from OpenEXRCore for every EXR. */
#include "image_exr_core.h"
#include "image_io.h"
#include "fs_error.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_LINEAR
#define STBI_NO_HDR
/* -Wunused-function is off for the whole file, on purpose before the push: stb
 * declares static functions that STBI_ONLY_PNG leaves undefined
 * (stbi_load_gif_from_memory, ...), and GCC reports "declared 'static' but never
 * defined" at the end of the file, where a pop would have restored the warning. */
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb_image.h>
#pragma GCC diagnostic pop

typedef enum { KIND_EXR, KIND_PNG, KIND_OTHER } file_kind;

static int sniff(const char *path, file_kind *kind)
{
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && !S_ISREG(st.st_mode)) {
        fclose(f);
        return fs_fail(FS_ERR_INPUT, S_ISDIR(st.st_mode) ? "%s: is a folder" : "%s: not a regular file", path);
    }
    unsigned char m[8] = {0};
    size_t got = fread(m, 1, sizeof m, f);
    int err = ferror(f) ? (errno ? errno : EIO) : 0;
    fclose(f);
    if (err) return fs_fail(FS_ERR_INPUT, "%s: cannot read: %s", path, strerror(err));
    if (got == 0) return fs_fail(FS_ERR_INPUT, "%s: empty file", path);
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01},
                               png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    *kind = got >= 4 && !memcmp(m, exr, 4) ? KIND_EXR : got == 8 && !memcmp(m, png, 8) ? KIND_PNG : KIND_OTHER;
    if (*kind == KIND_OTHER) return fs_fail(FS_ERR_INPUT, "%s: not an EXR or PNG image", path);
    return FS_OK;
}

/* PNG codes / 255 (or / 65535 for 16-bit files), as stored: alpha not premultiplied. */
static int read_png(const char *path, fs_image *img)
{
    int w, h, nch;
    /* what the header declares must be what the file's bytes can unpack to (zlib: at most 1032:1) */
    if (stbi_info(path, &w, &h, &nch) && fs_image_fits_file(path, w, h, nch)) return FS_ERR_INPUT;
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
            img->pix[i] =
                sixteen ? ((const unsigned short *)data)[i] / 65535.0f : ((const unsigned char *)data)[i] / 255.0f;
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
    if (!rc) rc = fs_image_structure_check(path);
    if (rc) return rc;
    if (kind == KIND_PNG) return read_png(path, img);
    int scanline = fs_exr_is_scanline(path);
    if (scanline < 0) return FS_ERR_INPUT;
    return scanline ? fs_exr_read(path, img) : fs_read_image_oiio(path, img);
}

int fs_read_image_attr(const char *path, const char *name, char *buf, int size)
{
    if (size > 0) buf[0] = 0;
    file_kind kind;
    if (sniff(path, &kind) || fs_image_structure_check(path)) return -1;
    if (kind == KIND_EXR) return fs_exr_read_attr(path, name, buf, size);
    return 0; /* our PNGs carry no attributes */
}

int fs_read_image_provenance(const char *path, fs_provenance *out)
{
    out->n = 0;
    file_kind kind;
    if (sniff(path, &kind) || fs_image_structure_check(path)) return -1;
    return kind == KIND_EXR ? fs_exr_read_provenance(path, out) : 0;
}
