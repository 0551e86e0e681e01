/* One small interface over the three ways fluidsurf gets an OpenGL 4.5 core
 * context: OSMesa (default, headless, CPU), EGL (headless on a GPU machine,
 * loaded at run time), GLFW (a window, for `view`). Creating one makes it current
 * and (re)loads the function table (gl.h). */
#ifndef FS_GL_CONTEXT_H
#define FS_GL_CONTEXT_H
#ifdef __cplusplus
extern "C" {
#endif

typedef enum { FS_CTX_OSMESA = 0, FS_CTX_EGL, FS_CTX_GLFW } fs_ctx_kind;

typedef struct fs_gl_context {
    fs_ctx_kind kind;
    void *handle; /* OSMesaContext, EGLContext or GLFWwindow* */
    void *extra;  /* backend data (OSMesa buffer, EGL display) */
    int width, height;
    char renderer[256];   /* GL_RENDERER, for every timing and provenance */
    char version[128];    /* GL_VERSION */
    int device, ndevices; /* EGL: the device's enumeration index and how many EGL lists; -1, 0 otherwise */
    int software;         /* a software rasterizer: EGL marks the device so, or GL_RENDERER names one */
} fs_gl_context;

/* kind from "osmesa", "egl", "glfw"; -1 when unknown. */
int fs_ctx_kind_from_name(const char *name);
const char *fs_ctx_kind_name(fs_ctx_kind k);
/* FS_ERR_RUNTIME "OpenGL: ..." when no 4.5 core context can be created.
 * width/height size the default framebuffer (window size for GLFW). EGL takes
 * a hardware device before a software one (gl_device.h). */
int fs_gl_context_create(fs_gl_context *c, fs_ctx_kind kind, int width, int height);
int fs_gl_context_make_current(fs_gl_context *c);
void fs_gl_context_destroy(fs_gl_context *c);
/* The context kind to use: FLUIDSURF_GL=osmesa|egl in the environment, else osmesa
 * (egl in a build with FS_WITH_OSMESA=OFF, where an OSMesa request is refused). */
fs_ctx_kind fs_gl_context_default_kind(void);
/* --require-gpu: from then on, creating a context on a software rasterizer fails
 * with FS_ERR_RUNTIME and one line naming its renderer. FLUIDSURF_REQUIRE_GPU set
 * to anything but "" or "0" does the same in every program and in the library,
 * so a timing run cannot silently measure llvmpipe. */
void fs_gl_context_require_gpu(int on);
#if defined(FS_WITH_OSMESA) && !FS_WITH_OSMESA
#define FS_CTX_DEFAULT_NAME "egl"
#else
#define FS_CTX_DEFAULT_NAME "osmesa"
#endif

#ifdef __cplusplus
}
#endif
#endif
