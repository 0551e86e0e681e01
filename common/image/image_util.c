/* Image helpers that need no OpenImageIO, shared by both builds' image files
 * (image_oiio.cpp, compiled into the OpenImageIO module with this file, and
 * image_stb.c / image_exr_core.c without it): channel lookup, the checks a file passes before a library reads
 * it (size, PNG chunks, EXR header attributes), and fs_image_free. */
#include "image_io.h"
#include "fs_error.h"

#include "bytes.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>

int fs_image_channel(const fs_image *img, const char *name)
{
    for (int c = 0; c < img->nch; c++)
        if (img->chnames && img->chnames[c] && strcmp(img->chnames[c], name) == 0) return c;
    return -1;
}

int fs_image_fits_file(const char *path, double w, double h, int nch)
{
    struct stat st;
    if (stat(path, &st) == 0 && w * h * nch * 4 > 2064.0 * (double)st.st_size + 1e6)
        return fs_fail(FS_ERR_INPUT, "%s: image of %.0fx%.0fx%d is more than the file's %lld bytes can hold", path, w,
                       h, nch, (long long)st.st_size);
    return FS_OK;
}

/* The whole file in memory (images here are small: a G-buffer EXR of a few MB). */
static unsigned char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    unsigned char *b = NULL;
    size_t cap = 0, got;
    *n = 0;
    do {
        if (*n == cap) {
            unsigned char *nb = realloc(b, cap = cap ? 2 * cap : 65536);
            if (!nb) return fclose(f), free(b), NULL;
            b = nb;
        }
        *n += got = fread(b + *n, 1, cap - *n, f);
    } while (got > 0);
    fclose(f);
    return b;
}

/* Both libpng and stb_image size buffers from a chunk's declared length before
 * reading it; libpng also prints its own errors. Every chunk must lie within the
 * file with its CRC right, and IEND come last. */
static const char *png_chunks_problem(const unsigned char *b, size_t n)
{
    for (size_t at = 8; at + 12 <= n;) {
        uint32_t len = fs_be32(b + at);
        if (len > n - at - 12) return "truncated PNG chunk";
        if (crc32(0, b + at + 4, len + 4) != fs_be32(b + at + 8 + len)) return "PNG chunk with a bad CRC";
        if (!memcmp(b + at + 4, "IEND", 4)) return NULL;
        at += 12 + (size_t)len;
    }
    return "PNG ends before its IEND chunk";
}

/* OpenEXR allocates each header attribute at the size the file declares: every
 * attribute (name, type, int32 size, value) must lie within the file, in each
 * header of a multi-part file (an empty name ends a header, an empty header the list). */
static const char *exr_header_problem(const unsigned char *b, size_t n)
{
    int multipart = n >= 8 && (b[5] & 0x10);
    size_t at = 8;
    for (int attrs = 0;; attrs++) {
        const unsigned char *name_end = at < n ? memchr(b + at, 0, n - at) : NULL;
        if (!name_end) return "truncated EXR header";
        if (name_end == b + at) { /* end of a header */
            at++;
            if (!multipart || attrs == 0) return NULL;
            attrs = -1;
            continue;
        }
        size_t type = (size_t)(name_end - b) + 1;
        const unsigned char *type_end = type < n ? memchr(b + type, 0, n - type) : NULL;
        if (!type_end || (size_t)(type_end - b) + 5 > n) return "truncated EXR header";
        size_t value = (size_t)(type_end - b) + 5;
        int32_t size = (int32_t)fs_le32(b + value - 4);
        if (size < 0 || (size_t)size > n - value) return "EXR header attribute larger than the file";
        at = value + (size_t)size;
    }
}

int fs_image_structure_check(const char *path)
{
    size_t n;
    unsigned char *b = slurp(path, &n);
    if (!b) return fs_fail(FS_ERR_INPUT, "%s: cannot read", path);
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'},
                               exr[4] = {0x76, 0x2f, 0x31, 0x01};
    const char *why = n >= 8 && !memcmp(b, png, 8) ? png_chunks_problem(b, n)
        : n >= 4 && !memcmp(b, exr, 4)             ? exr_header_problem(b, n)
                                                   : NULL;
    free(b);
    return why ? fs_fail(FS_ERR_INPUT, "%s: %s", path, why) : FS_OK;
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
