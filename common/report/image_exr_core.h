/* The EXR half of the build without OpenImageIO (image_exr_core.c): fs_write_exr
 * itself, and the readers image_stb.c's fs_read_image / fs_read_image_attr call
 * for files that start with EXR's magic number. */
#ifndef FS_IMAGE_EXR_CORE_H
#define FS_IMAGE_EXR_CORE_H
#include "image_io.h"

int fs_exr_read(const char *path, fs_image *img);
int fs_exr_read_attr(const char *path, const char *name, char *buf, int size);

#endif
