#include "gl_device.h"
#include "fs_error.h"
#include <ctype.h>
#include <string.h>

/* 1 when the space-separated list holds word exactly: Mesa's software device
 * lists EGL_EXT_device_drm_render_node, which must not read as EGL_EXT_device_drm. */
static int has_word(const char *list, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = list; (p = strstr(p, word)) != NULL; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0)) return 1;
    return 0;
}

fs_gl_device_class fs_gl_device_classify(const char *extensions)
{
    if (!extensions) return FS_GL_DEVICE_UNKNOWN;
    /* first: Mesa marks its software device, whatever else it lists */
    if (has_word(extensions, "EGL_MESA_device_software")) return FS_GL_DEVICE_SOFTWARE;
    /* a DRM device file (EGL_DRM_DEVICE_FILE_EXT) or a CUDA device is a GPU */
    if (has_word(extensions, "EGL_EXT_device_drm") || has_word(extensions, "EGL_NV_device_cuda"))
        return FS_GL_DEVICE_HARDWARE;
    return FS_GL_DEVICE_UNKNOWN;
}

int fs_gl_device_order(const fs_gl_device_class *cls, int n, int *order)
{
    if (n < 1) return fs_fail(FS_ERR_RUNTIME, "OpenGL: EGL: no EGL device");
    int k = 0;
    for (int i = 0; i < n; i++)
        if (cls[i] != FS_GL_DEVICE_SOFTWARE) order[k++] = i;
    for (int i = 0; i < n; i++)
        if (cls[i] == FS_GL_DEVICE_SOFTWARE) order[k++] = i;
    return FS_OK;
}

int fs_gl_device_choose(const fs_gl_device_class *cls, int n, fs_gl_device_open_fn open, fs_gl_device_close_fn close,
                        void *data)
{
    int order[FS_GL_MAX_DEVICES];
    char failed[FS_GL_MAX_DEVICES] = {0}; /* not opened twice */
    if (n > FS_GL_MAX_DEVICES) n = FS_GL_MAX_DEVICES;
    if (fs_gl_device_order(cls, n, order)) return -1;
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; k < n; k++) {
            int i = order[k];
            if (failed[i] || (pass == 0 && cls[i] == FS_GL_DEVICE_SOFTWARE)) continue;
            int soft = open(data, i);
            if (soft < 0) failed[i] = 1;
            else if (pass == 1 || !soft) return i;
            else close(data, i);
        }
    return -1;
}

/* Case-insensitive substring. */
static int has_text(const char *s, const char *what)
{
    size_t n = strlen(what);
    for (; *s; s++) {
        size_t i = 0;
        while (i < n && s[i] && tolower((unsigned char)s[i]) == tolower((unsigned char)what[i])) i++;
        if (i == n) return 1;
    }
    return 0;
}

int fs_gl_renderer_is_software(const char *renderer)
{
    static const char *const software[] = {"llvmpipe", "softpipe", "swrast", "lavapipe", "Software Rasterizer"};
    for (size_t i = 0; i < sizeof software / sizeof *software; i++)
        if (renderer && has_text(renderer, software[i])) return 1;
    return 0;
}
