/* Which EGL device fluidsurf renders on, and whether a renderer is a software
 * rasterizer. Pure functions over what EGL and GL report, so they are tested
 * without a GPU (tests/test_gl_device.c); gl_context.c feeds them. */
#ifndef FS_GL_DEVICE_H
#define FS_GL_DEVICE_H
#ifdef __cplusplus
extern "C" {
#endif

/* An 8-GPU node also lists Mesa's software device: room for all of them. */
#define FS_GL_MAX_DEVICES 32

typedef enum {
    FS_GL_DEVICE_UNKNOWN = 0, /* EGL said nothing either way: GL_RENDERER decides */
    FS_GL_DEVICE_HARDWARE,
    FS_GL_DEVICE_SOFTWARE,
} fs_gl_device_class;

/* A device's class from its extension string (eglQueryDeviceStringEXT(dev,
 * EGL_EXTENSIONS); NULL when EGL_EXT_device_query is missing). */
fs_gl_device_class fs_gl_device_classify(const char *extensions);
/* The order in which to try n devices: every device not marked software, then
 * the software ones, each group in enumeration order. Writes n indices into
 * order; FS_ERR_RUNTIME "OpenGL: EGL: no EGL device" when n < 1. */
int fs_gl_device_order(const fs_gl_device_class *cls, int n, int *order);
/* Opens device i (a context, made current): -1 when it cannot (having undone
 * what it did), else 1 when its GL_RENDERER is a software rasterizer, 0 when not. */
typedef int (*fs_gl_device_open_fn)(void *data, int i);
typedef void (*fs_gl_device_close_fn)(void *data, int i);
/* Opens the n (at most FS_GL_MAX_DEVICES) devices in fs_gl_device_order's order
 * and leaves the chosen one open: the first that opens with a hardware renderer.
 * A device EGL did not mark software whose GL_RENDERER is one (DRM devices can
 * fall back to llvmpipe) is closed again; a second pass takes the first device
 * that opens at all, so an all-software machine still gets one. Returns the
 * index, or -1 when none opens (fs_fail's message set only for n < 1). */
int fs_gl_device_choose(const fs_gl_device_class *cls, int n, fs_gl_device_open_fn open, fs_gl_device_close_fn close,
                        void *data);
/* 1 when GL_RENDERER names a software rasterizer (llvmpipe, softpipe, swrast,
 * lavapipe, "Software Rasterizer"): the one list of them. */
int fs_gl_renderer_is_software(const char *renderer);

#ifdef __cplusplus
}
#endif
#endif
