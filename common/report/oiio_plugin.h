/* The boundary between fluidsurf and its OpenImageIO adapter, which is built as a
 * module (fluidsurf-oiio.so) and loaded on the first image or text call
 * (oiio_load.c). OpenImageIO pulls in some 260 shared libraries (OpenCV, GDAL,
 * DICOM, video codecs): linked into the binary they cost every command about 0.4 s
 * of start-up, needed or not (docs/DESIGN.md, "Start-up"). The module is
 * self-contained: what it needs of fluidsurf comes in the host table, so its
 * errors land in the caller's fs_error and its files go through output_file.h. */
#ifndef FS_OIIO_PLUGIN_H
#define FS_OIIO_PLUGIN_H
#include "figure.h"
#include <stdarg.h>
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_OIIO_PLUGIN_ABI 3
#define FS_OIIO_PLUGIN_FILE "fluidsurf-oiio.so"
#define FS_OIIO_PLUGIN_ENTRY "fs_oiio_plugin_init"

typedef struct fs_oiio_host {
    int abi;
    int (*vfail)(int code, const char *fmt, va_list ap);
    int (*output_begin)(const char *final, char *tmp, int size);
    int (*output_end)(const char *final, const char *tmp, int ok);
    void (*text_blend)(fs_rgba_image *im, int x, int y, const float *cover, int cw, int ch, const float rgb[3]);
    size_t (*alloc_cap_begin)(const char *path); /* alloc_cap.h: the host's operator new honours it */
    void (*alloc_cap_end)(size_t previous);
} fs_oiio_host;

/* The functions of image_io.h and figure.h that OpenImageIO implements. */
typedef struct fs_oiio_api {
    int (*write_exr)(const char *path, const fs_image *img, const fs_attr *attrs, int nattrs);
    int (*read_image)(const char *path, fs_image *img);
    int (*read_image_attr)(const char *path, const char *name, char *buf, int size);
    int (*text_size)(const char *text, int size, int *w, int *h);
    int (*draw_text)(fs_rgba_image *im, int x, int y, const char *text, int size, const float rgb[3]);
} fs_oiio_api;

/* The module's one exported symbol: keeps host, fills api; 0, or -1 when the
 * host's ABI differs from the module's. */
typedef int (*fs_oiio_plugin_init_fn)(const fs_oiio_host *host, fs_oiio_api *api);

#ifdef __cplusplus
}
#endif
#endif
