/* The EXR half of image_io.h (image_exr_core.c, every build): fs_write_exr
 * itself, and the readers image_stb.c's fs_read_image / fs_read_image_attr call
 * for files that start with EXR's magic number. */
#ifndef FS_IMAGE_EXR_CORE_H
#define FS_IMAGE_EXR_CORE_H
#include "image_io.h"

/* 1 when part 0 is a scanline image (what fs_exr_read reads), 0 when it is tiled
 * or deep, -1 when OpenEXRCore cannot open the file (fs_fail says why). */
int fs_exr_is_scanline(const char *path);
int fs_exr_read(const char *path, fs_image *img);
int fs_exr_read_attr(const char *path, const char *name, char *buf, int size);
int fs_exr_read_provenance(const char *path, fs_provenance *out);
/* An image the readers above do not read (a tiled or deep EXR): through the
 * OpenImageIO module (oiio_load.c), or refused in the build without it (oiio_none.c). */
int fs_read_image_oiio(const char *path, fs_image *img);

#endif
