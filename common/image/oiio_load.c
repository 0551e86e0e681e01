/* What the build with OpenImageIO leaves to it: text (figure.h) and reading the
 * EXRs OpenEXRCore's scanline reader does not (tiled, deep: fs_read_image_oiio).
 * Forwards to the OpenImageIO module (oiio_plugin.h), loaded once, on the first
 * call; PNGs and EXRs are written, and read, without it. The module is looked for in $FLUIDSURF_PLUGIN_DIR alone when
 * it is set; else in LIBDIR/fluidsurf of the installed tree the running binary or
 * library sits in (wherever that tree was moved), then in the build tree. */
#define _GNU_SOURCE
#include "alloc_cap.h"
#include "rgba_image.h"
#include "fs_error.h"
#include "image_exr_core.h"
#include "oiio_plugin.h"
#include "text_blend.h"

#include <dlfcn.h>
#include <libgen.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const fs_oiio_host host = {FS_OIIO_PLUGIN_ABI, fs_vfail, fs_text_blend, fs_alloc_cap_begin, fs_alloc_cap_end};
static fs_oiio_api api;
static char load_error[1024];
static pthread_once_t once = PTHREAD_ONCE_INIT;

/* Opens dir/fluidsurf-oiio.so; NULL (and load_error says why) if it is not there. */
static void *open_in(const char *dir)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, FS_OIIO_PLUGIN_FILE);
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) snprintf(load_error, sizeof load_error, "%s", dlerror());
    return h;
}

/* Folder of path (a copy in buf). */
static const char *dir_of(const char *path, char *buf, size_t size)
{
    snprintf(buf, size, "%s", path);
    return dirname(buf);
}

static void *open_module(void)
{
    const char *env = getenv("FLUIDSURF_PLUGIN_DIR");
    if (env && *env) return open_in(env); /* named explicitly: no fallback */
    char exe[4096], buf[4096], dir[8300];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    void *h = NULL;
    if (n > 0) { /* an installed binary: PREFIX/bin/fluidsurf, PREFIX/LIBDIR/fluidsurf */
        exe[n] = 0;
        snprintf(dir, sizeof dir, "%s/../%s/fluidsurf", dir_of(exe, buf, sizeof buf), FS_PLUGIN_LIBDIR);
        h = open_in(dir);
    }
    Dl_info self; /* an installed library: PREFIX/LIBDIR/libfluidsurf.so */
    if (!h && dladdr((void *)open_module, &self) && self.dli_fname && strstr(self.dli_fname, ".so")) {
        snprintf(dir, sizeof dir, "%s/fluidsurf", dir_of(self.dli_fname, buf, sizeof buf));
        h = open_in(dir);
    }
    return h ? h : open_in(FS_PLUGIN_BUILD_DIR);
}

static void load(void)
{
    void *h = open_module();
    if (!h) return;
    fs_oiio_plugin_init_fn init = (fs_oiio_plugin_init_fn)dlsym(h, FS_OIIO_PLUGIN_ENTRY);
    if (!init || init(&host, &api) != 0) {
        snprintf(load_error, sizeof load_error, "%s is not the module of this fluidsurf (ABI %d)", FS_OIIO_PLUGIN_FILE,
                 FS_OIIO_PLUGIN_ABI);
        memset(&api, 0, sizeof api);
    }
}

/* 1 when the module is loaded; else 0 with fs_error naming what (file or text). */
static int ready(const char *what)
{
    pthread_once(&once, load);
    if (api.read_image) return 1;
    fs_fail(FS_ERR_RUNTIME, "%s: cannot load the OpenImageIO module: %s (set FLUIDSURF_PLUGIN_DIR)", what, load_error);
    return 0;
}

int fs_read_image_oiio(const char *path, fs_image *img)
{
    memset(img, 0, sizeof *img);
    return ready(path) ? api.read_image(path, img) : FS_ERR_RUNTIME;
}

int fs_text_size(const char *text, int size, int *w, int *h)
{
    *w = *h = 0;
    return ready("text") ? api.text_size(text, size, w, h) : FS_ERR_RUNTIME;
}

int fs_draw_text(fs_rgba_image *im, int x, int y, const char *text, int size, const float rgb[3])
{
    return ready("text") ? api.draw_text(im, x, y, text, size, rgb) : FS_ERR_RUNTIME;
}
