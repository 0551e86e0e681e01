// The entry point of the OpenImageIO module (oiio_plugin.h). image_oiio.cpp,
// image_text.cpp and image_util.c are compiled into the module unchanged: the
// other fluidsurf functions they call are defined here as forwards to the host's, and everything but the
// entry point is hidden, so nothing clashes with the host's own definitions.
#include "oiio_plugin.h"
#include "alloc_cap.h"
#include "fs_error.h"
#include "text_blend.h"

namespace
{
const fs_oiio_host *host;
}

extern "C" int fs_fail(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int rc = host->vfail(code, fmt, ap);
    va_end(ap);
    return rc;
}

extern "C" void fs_text_blend(fs_rgba_image *im, int x, int y, const float *cover, int cw, int ch, const float rgb[3])
{
    host->text_blend(im, x, y, cover, cw, ch, rgb);
}

extern "C" size_t fs_alloc_cap_begin(const char *path) { return host->alloc_cap_begin(path); }
extern "C" void fs_alloc_cap_end(size_t previous) { host->alloc_cap_end(previous); }

extern "C" __attribute__((visibility("default"))) int fs_oiio_plugin_init(const fs_oiio_host *h, fs_oiio_api *api)
{
    if (!h || h->abi != FS_OIIO_PLUGIN_ABI) return -1;
    host = h;
    *api = fs_oiio_api{fs_read_image, fs_text_size, fs_draw_text};
    return 0;
}
