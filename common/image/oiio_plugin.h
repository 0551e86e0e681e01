/* The boundary between fluidsurf and its OpenImageIO adapter, which is built as a
 * module (fluidsurf-oiio.so) and loaded on the first text call or read of a tiled
 * or deep EXR (oiio_load.c); PNGs and EXRs are written without it. OpenImageIO pulls in some 260 shared libraries (OpenCV, GDAL,
 * DICOM, video codecs): linked into the binary they cost every command about 0.4 s
 * of start-up, needed or not (docs/DESIGN.md, "Start-up"). The module is
 * self-contained: what it needs of fluidsurf comes in the host table, so its
 * errors land in the caller's fs_error. */
#ifndef FS_OIIO_PLUGIN_H
#define FS_OIIO_PLUGIN_H
#include "rgba_image.h"
#include <stdarg.h>
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

#define FS_OIIO_PLUGIN_ABI 4
#define FS_OIIO_PLUGIN_FILE "fluidsurf-oiio.so"
#define FS_OIIO_PLUGIN_ENTRY "fs_oiio_plugin_init"

typedef struct fs_oiio_host {
    int abi;
    int (*vfail)(int code, const char *fmt, va_list ap);
    void (*text_blend)(fs_rgba_image *im, int x, int y, const float *cover, int cw, int ch, const float rgb[3]);
    size_t (*alloc_cap_begin)(const char *path); /* alloc_cap.h: the host's operator new honours it */
    void (*alloc_cap_end)(size_t previous);
} fs_oiio_host;

/* What OpenImageIO implements: image_io.h's fs_read_image (for the files that
 * image_stb.c hands on) and figure.h's text. */
typedef struct fs_oiio_api {
    int (*read_image)(const char *path, fs_image *img);
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
