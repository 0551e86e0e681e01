/* Image files through OpenImageIO (common/image/image_oiio.cpp), or, in a build with
 * FS_WITH_OIIO=OFF, OpenEXRCore and stb (image_exr_core.c, image_stb.c: PNG and EXR
 * only): PNG (sRGB 8-bit) and EXR (linear float, RGBA plus named AOV channels and
 * string attributes). */
#ifndef FS_IMAGE_IO_H
#define FS_IMAGE_IO_H
#include "provenance.h" /* fs_attr, fs_provenance */
#include "srgb.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_image {
    int w, h, nch;
    const char **chnames; /* nch names ("R","G","B","A","depth","normal.X",...) */
    float *pix;           /* w*h*nch, rows top to bottom, interleaved */
} fs_image;

/* Writes an EXR with the given channels and string header attributes, safely
 * (temporary file + rename). */
int fs_write_exr(const char *path, const fs_image *img, const fs_attr *attrs, int nattrs);
/* Writes the first 3 or 4 channels of img (linear) as sRGB 8-bit PNG. */
int fs_write_png(const char *path, const fs_image *img);
/* Writes 8-bit code values as they are (nch 1..4: gray, gray+alpha, RGB, RGBA). */
int fs_write_png8(const char *path, const unsigned char *pix, int w, int h, int nch);
/* Reads any image OpenImageIO reads. chnames/pix are malloc'd (free with fs_image_free).
 * Pixels come as stored: EXR linear; PNG sRGB-encoded codes / 255, alpha not
 * premultiplied. EXR files may list channels in another order than written
 * (R,G,B,A first): look channels up by name with fs_image_channel. */
int fs_read_image(const char *path, fs_image *img);
/* Reads the string attribute name of an image file into buf: 1 if present,
 * 0 if absent (buf = ""), -1 if the file cannot be read (fs_error_message says why). */
int fs_read_image_attr(const char *path, const char *name, char *buf, int size);
/* Every string attribute "fluidsurf:NAME" of an image file into out (in the file's
 * order, FS_PROV_MAX at most): how many, 0 for a PNG, -1 if the file cannot be read. */
int fs_read_image_provenance(const char *path, fs_provenance *out);
void fs_image_free(fs_image *img);
/* FS_ERR_INPUT (fs_fail) when a header's w x h x nch floats are more than the
 * file's bytes can unpack to (zlib's largest ratio, 1032:1, plus 1 MB): checked by
 * every reader before it allocates. */
int fs_image_fits_file(const char *path, double w, double h, int nch);
/* FS_ERR_INPUT (fs_fail) when a PNG's chunks or an EXR's header attributes do not
 * lie within the file (libraries size buffers from them): checked before a library
 * opens the file. Other files pass. */
int fs_image_structure_check(const char *path);
/* Index of the channel called name, -1 if absent. */
int fs_image_channel(const fs_image *img, const char *name);

#ifdef __cplusplus
}
#endif
#endif
