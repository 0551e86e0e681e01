#define _GNU_SOURCE /* dl_iterate_phdr */
#include "caller_words.h"
#include "gl_context.h"
#include "fs_error.h"
#include "gl_device.h"
#include "gl_limits.h"

typedef void *(*fs_gl_getproc)(const char *name);
int fs_gl_load(fs_gl_getproc getproc);
int fs_gl_check_core45(char *renderer, int rsize, char *version, int vsize);
#include <EGL/egl.h>
#include <EGL/eglext.h>
/* The OSMesa and GLFW parts compile only with their libraries (FS_WITH_OSMESA,
 * FS_WITH_GLFW); without them a request for that kind is refused with one line. */
#if FS_WITH_OSMESA
#include <GL/osmesa.h> /* pulls GL/gl.h: so this file must not include gl.h */
#endif
#if FS_WITH_GLFW
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#endif
#include <dlfcn.h>
#include <link.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const kind_names[] = {"osmesa", "egl", "glfw"};

int fs_ctx_kind_from_name(const char *name)
{
    for (int i = 0; i < 3; i++)
        if (!strcmp(name, kind_names[i])) return i;
    return -1;
}
const char *fs_ctx_kind_name(fs_ctx_kind k) { return (unsigned)k < 3 ? kind_names[k] : "?"; }

fs_ctx_kind fs_gl_context_default_kind(void)
{
    const char *e = getenv("FLUIDSURF_GL");
    int k = e ? fs_ctx_kind_from_name(e) : -1;
#if FS_WITH_OSMESA
    return k == FS_CTX_EGL ? FS_CTX_EGL : FS_CTX_OSMESA;
#else
    /* EGL is the default; FLUIDSURF_GL=osmesa stays a request, refused at creation. */
    return k == FS_CTX_OSMESA ? FS_CTX_OSMESA : FS_CTX_EGL;
#endif
}

/* ---- OSMesa ---- */
#if !FS_WITH_OSMESA
static int create_osmesa(fs_gl_context *c)
{
    (void)c;
    return fs_fail(FS_ERR_INPUT, "OpenGL: an OSMesa context needs a build with FS_WITH_OSMESA=ON (use %s)",
                   fs_word("gl_egl"));
}
#else
/* OSMesa is opened with dlopen at the first OSMesa context, not linked: libOSMesa
 * brings LLVM (some 400,000 relocations and its static constructors), about 60 ms
 * of start-up that every command paid, GL or not (docs/DESIGN.md, "Start-up").
 * Opened once and never closed, like the driver libraries below. */
#define FS_OSMESA_LIB "libOSMesa.so.8"
typedef OSMesaContext (*osm_create_fn)(const int *attribs, OSMesaContext share);
typedef GLboolean (*osm_current_fn)(OSMesaContext ctx, void *buf, GLenum type, GLsizei w, GLsizei h);
typedef void (*osm_destroy_fn)(OSMesaContext ctx);
typedef OSMESAproc (*osm_getproc_fn)(const char *name);
static struct {
    osm_create_fn CreateContextAttribs;
    osm_current_fn MakeCurrent;
    osm_destroy_fn DestroyContext;
    osm_getproc_fn GetProcAddress;
} osm;
static char osm_error[512];
static pthread_once_t osm_once = PTHREAD_ONCE_INIT;

static void osmesa_load(void)
{
    void *h = dlopen(FS_OSMESA_LIB, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!h) {
        snprintf(osm_error, sizeof osm_error, "%s", dlerror());
        return;
    }
    osm.CreateContextAttribs = (osm_create_fn)dlsym(h, "OSMesaCreateContextAttribs");
    osm.MakeCurrent = (osm_current_fn)dlsym(h, "OSMesaMakeCurrent");
    osm.DestroyContext = (osm_destroy_fn)dlsym(h, "OSMesaDestroyContext");
    osm.GetProcAddress = (osm_getproc_fn)dlsym(h, "OSMesaGetProcAddress");
    if (!osm.CreateContextAttribs || !osm.MakeCurrent || !osm.DestroyContext || !osm.GetProcAddress) {
        snprintf(osm_error, sizeof osm_error, "%s lacks an OSMesa entry point (OSMesaCreateContextAttribs, ...)",
                 FS_OSMESA_LIB);
        memset(&osm, 0, sizeof osm);
    }
}

static void *osmesa_getproc(const char *name) { return (void *)osm.GetProcAddress(name); }

static int create_osmesa(fs_gl_context *c)
{
    pthread_once(&osm_once, osmesa_load);
    if (!osm.CreateContextAttribs) return fs_fail(FS_ERR_RUNTIME, "OpenGL: OSMesa: %s", osm_error);
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           4,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           5,
                           0};
    OSMesaContext ctx = osm.CreateContextAttribs(attribs, NULL);
    if (!ctx) return fs_fail(FS_ERR_RUNTIME, "OpenGL: OSMesa cannot create a 4.5 core context (Mesa too old?)");
    c->extra = calloc((size_t)c->width * c->height, 4);
    if (!c->extra) {
        osm.DestroyContext(ctx);
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: out of memory");
    }
    c->handle = ctx;
    return FS_OK;
}
#endif

/* ---- driver libraries ----
 * libEGL and libGL (loaded by GLFW) load vendor libraries and Mesa's DRI driver
 * (swrast_dri.so, with its own LLVM JIT) at run time, and unload them again on
 * eglTerminate / glfwTerminate. Once loaded they stay for the life of the
 * process: drivers are not reliably unloadable, a second context need not load
 * them again, and LeakSanitizer can then name the library a driver leak comes
 * from (tests/lsan.supp) instead of "<unknown module>". */
typedef struct name_list {
    char **names;
    size_t n, cap;
} name_list;

static int collect_name(struct dl_phdr_info *info, size_t size, void *data)
{
    (void)size;
    name_list *l = data;
    if (!info->dlpi_name || !info->dlpi_name[0]) return 0; /* the executable */
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        char **grown = realloc(l->names, cap * sizeof *grown);
        if (!grown) return 1;
        l->names = grown;
        l->cap = cap;
    }
    if ((l->names[l->n] = strdup(info->dlpi_name)) != NULL) l->n++;
    return 0;
}

static void pin_loaded_libraries(void)
{
    name_list l = {0};
    dl_iterate_phdr(collect_name, &l); /* no dlopen while it holds the loader lock */
    for (size_t i = 0; i < l.n; i++) {
        void *h = dlopen(l.names[i], RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        if (h) dlclose(h); /* drops our reference, the no-delete mark stays */
        free(l.names[i]);
    }
    free(l.names);
}

/* ---- EGL, loaded with dlopen so the binary never links libEGL/libGL ---- */
typedef struct egl_fns {
    void *lib;
    EGLDisplay dpy;
    PFNEGLGETPROCADDRESSPROC GetProcAddress;
    PFNEGLMAKECURRENTPROC MakeCurrent;
    PFNEGLDESTROYCONTEXTPROC DestroyContext;
    PFNEGLTERMINATEPROC Terminate;
    /* for creation only */
    PFNEGLQUERYDEVICESEXTPROC QueryDevices;
    PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString; /* NULL without EGL_EXT_device_query */
    PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay;
    PFNEGLINITIALIZEPROC Initialize;
    PFNEGLBINDAPIPROC BindAPI;
    PFNEGLCHOOSECONFIGPROC ChooseConfig;
    PFNEGLCREATECONTEXTPROC CreateContext;
} egl_fns;
static egl_fns *egl_current;
/* EGL displays are per device and eglTerminate ends every context on one, so
 * only the last EGL context terminates it. */
static int egl_users;
#ifndef GL_RENDERER
#define GL_RENDERER 0x1F01 /* gl.h is not included here (see the OSMesa include) */
#endif
typedef const unsigned char *(*gl_get_string_fn)(unsigned int name);

static void *egl_getproc(const char *name) { return (void *)egl_current->GetProcAddress(name); }

/* libEGL and its entry points; NULL, or why not. */
static const char *egl_load(egl_fns *e)
{
    e->lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!e->lib) return "libEGL.so.1 not found";
    e->GetProcAddress = (PFNEGLGETPROCADDRESSPROC)dlsym(e->lib, "eglGetProcAddress");
    if (!e->GetProcAddress) return "eglGetProcAddress missing";
#define LOAD(field, T, name) e->field = (T)e->GetProcAddress(name)
    LOAD(MakeCurrent, PFNEGLMAKECURRENTPROC, "eglMakeCurrent");
    LOAD(DestroyContext, PFNEGLDESTROYCONTEXTPROC, "eglDestroyContext");
    LOAD(Terminate, PFNEGLTERMINATEPROC, "eglTerminate");
    LOAD(QueryDevices, PFNEGLQUERYDEVICESEXTPROC, "eglQueryDevicesEXT");
    LOAD(QueryDeviceString, PFNEGLQUERYDEVICESTRINGEXTPROC, "eglQueryDeviceStringEXT");
    LOAD(GetPlatformDisplay, PFNEGLGETPLATFORMDISPLAYEXTPROC, "eglGetPlatformDisplayEXT");
    LOAD(Initialize, PFNEGLINITIALIZEPROC, "eglInitialize");
    LOAD(BindAPI, PFNEGLBINDAPIPROC, "eglBindAPI");
    LOAD(ChooseConfig, PFNEGLCHOOSECONFIGPROC, "eglChooseConfig");
    LOAD(CreateContext, PFNEGLCREATECONTEXTPROC, "eglCreateContext");
#undef LOAD
    if (!e->QueryDevices || !e->GetPlatformDisplay)
        return "device enumeration (EGL_EXT_device_enumeration) unavailable";
    if (!e->MakeCurrent || !e->DestroyContext || !e->Terminate || !e->Initialize || !e->BindAPI || !e->ChooseConfig ||
        !e->CreateContext)
        return "an EGL 1.4 entry point is missing";
    return NULL;
}

/* A 4.5 core context on dev, current, its GL_RENDERER in c->renderer; NULL, or
 * why not (egl_close undoes what was done either way). */
static const char *egl_open(egl_fns *e, EGLDeviceEXT dev, fs_gl_context *c)
{
    EGLint major, minor, ncfg = 0;
    EGLConfig cfg;
    EGLDisplay d = e->GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, dev, NULL);
    if (d == EGL_NO_DISPLAY || !e->Initialize(d, &major, &minor)) return "no EGL display initialises";
    e->dpy = d;
    const EGLint cfg_attr[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    if (!e->BindAPI(EGL_OPENGL_API) || !e->ChooseConfig(d, cfg_attr, &cfg, 1, &ncfg) || ncfg < 1)
        return "no OpenGL config";
    const EGLint ctx_attr[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = e->CreateContext(d, cfg, EGL_NO_CONTEXT, ctx_attr);
    if (ctx == EGL_NO_CONTEXT) return "cannot create a 4.5 core context";
    c->handle = ctx;
    if (!e->MakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) return "cannot make the context current";
    gl_get_string_fn get_string = (gl_get_string_fn)e->GetProcAddress("glGetString");
    const unsigned char *r = get_string ? get_string(GL_RENDERER) : NULL;
    snprintf(c->renderer, sizeof c->renderer, "%s", r ? (const char *)r : "");
    return NULL;
}

/* Undoes egl_open. The display stays initialised while another context uses it. */
static void egl_close(egl_fns *e, fs_gl_context *c)
{
    if (c->handle) {
        e->MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        e->DestroyContext(e->dpy, c->handle);
        c->handle = NULL;
    }
    if (e->dpy && !egl_users) e->Terminate(e->dpy);
    e->dpy = NULL;
    c->renderer[0] = 0;
}

/* fs_gl_device_choose's view of the devices */
typedef struct egl_pick {
    egl_fns *e;
    fs_gl_context *c;
    EGLDeviceEXT devs[FS_GL_MAX_DEVICES];
    fs_gl_device_class cls[FS_GL_MAX_DEVICES];
    const char *why; /* the last device's reason not to open */
} egl_pick;

static int egl_pick_open(void *data, int i)
{
    egl_pick *p = data;
    const char *why = egl_open(p->e, p->devs[i], p->c);
    if (why) {
        egl_close(p->e, p->c);
        p->why = why;
        return -1;
    }
    return p->cls[i] == FS_GL_DEVICE_SOFTWARE || fs_gl_renderer_is_software(p->c->renderer);
}

static void egl_pick_close(void *data, int i)
{
    egl_pick *p = data;
    (void)i;
    egl_close(p->e, p->c);
}

/* Opens the device fs_gl_device_choose picks (hardware before software), its
 * index, count and software flag in c; NULL, or why none opened. */
static const char *egl_choose(egl_fns *e, fs_gl_context *c)
{
    egl_pick p = {.e = e, .c = c, .why = "no EGL device opens"};
    EGLint n = 0;
    if (!e->QueryDevices(FS_GL_MAX_DEVICES, p.devs, &n)) n = 0;
    for (int i = 0; i < n; i++) /* what EGL says before any context is made */
        p.cls[i] = fs_gl_device_classify(e->QueryDeviceString ? e->QueryDeviceString(p.devs[i], EGL_EXTENSIONS) : NULL);
    if (n < 1) return "no EGL device";
    int i = fs_gl_device_choose(p.cls, n, egl_pick_open, egl_pick_close, &p);
    if (i < 0) return p.why;
    c->device = i, c->ndevices = n;
    c->software = p.cls[i] == FS_GL_DEVICE_SOFTWARE; /* fs_gl_context_create adds GL_RENDERER's word */
    return NULL;
}

static int create_egl(fs_gl_context *c)
{
    egl_fns *e = calloc(1, sizeof *e);
    if (!e) return fs_fail(FS_ERR_RUNTIME, "OpenGL: out of memory");
    const char *why = egl_load(e);
    if (!why) why = egl_choose(e, c);
    pin_loaded_libraries();
    if (why) {
        if (e->lib) dlclose(e->lib);
        free(e);
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: EGL: %s", why);
    }
    c->extra = e;
    egl_users++;
    return FS_OK;
}

/* ---- GLFW ---- */
#if !FS_WITH_GLFW
static int create_glfw(fs_gl_context *c)
{
    (void)c;
    return fs_fail(FS_ERR_INPUT, "OpenGL: a GLFW window needs a build with FS_WITH_GLFW=ON");
}
#else
static void *glfw_getproc(const char *name) { return (void *)glfwGetProcAddress(name); }
/* glfwTerminate destroys every window: only the last GLFW context calls it. */
static int glfw_users;

static int create_glfw(fs_gl_context *c)
{
    if (!glfw_users && !glfwInit()) return fs_fail(FS_ERR_RUNTIME, "OpenGL: GLFW cannot initialise (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow *w = glfwCreateWindow(c->width, c->height, "fluidsurf", NULL, NULL);
    pin_loaded_libraries();
    if (!w) {
        if (!glfw_users) glfwTerminate();
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: GLFW cannot create a 4.5 core window");
    }
    glfw_users++;
    c->handle = w;
    return FS_OK;
}
#endif

/* ---- switching ----
 * OSMesa, GLX (libGLX_mesa, loaded by GLFW) and EGL (libEGL_mesa) all dispatch
 * GL calls through one per-thread slot in Mesa's shared libglapi. Unbinding a
 * GLX context (glfwCreateWindow does it on return, glfwDestroyWindow does it
 * for the window current in GLFW) empties that slot even while OSMesa believes
 * its context is current: every later GL call is then a silent no-op (measured
 * on Mesa 22.3; EGL did not do it there, but is treated alike). So the context
 * bound last is released before another one is bound or created, and a context
 * is unbound at destruction only if it is the bound one.
 * A copy, so the caller may move its struct; per thread, as GL binding is. */
static _Thread_local fs_gl_context bound;

static void release_bound(void)
{
    if (!bound.handle) return;
    switch (bound.kind) {
#if FS_WITH_OSMESA
    case FS_CTX_OSMESA: osm.MakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0); break;
#endif
    case FS_CTX_EGL: {
        egl_fns *e = bound.extra;
        e->MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        break;
    }
#if FS_WITH_GLFW
    case FS_CTX_GLFW: glfwMakeContextCurrent(NULL); break;
#endif
    default: break;
    }
    bound.handle = NULL;
}

int fs_gl_context_make_current(fs_gl_context *c)
{
    int ok = 0;
    fs_gl_getproc gp = NULL;
    if (bound.handle != c->handle) release_bound();
    switch (c->kind) {
#if FS_WITH_OSMESA
    case FS_CTX_OSMESA:
        ok = osm.MakeCurrent(c->handle, c->extra, GL_UNSIGNED_BYTE, c->width, c->height);
        gp = osmesa_getproc;
        break;
#endif
    case FS_CTX_EGL: {
        egl_fns *e = c->extra;
        ok = e->MakeCurrent(e->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, c->handle);
        egl_current = e;
        gp = egl_getproc;
        break;
    }
#if FS_WITH_GLFW
    case FS_CTX_GLFW:
        glfwMakeContextCurrent(c->handle);
        ok = glfwGetCurrentContext() == c->handle;
        gp = glfw_getproc;
        break;
#endif
    default: break;
    }
    if (!ok) return fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot make the %s context current", fs_ctx_kind_name(c->kind));
    bound = *c;
    int rc = fs_gl_load(gp);
    if (rc) return rc;
    return fs_gl_check_core45(c->renderer, sizeof c->renderer, c->version, sizeof c->version);
}

/* fs_gl_context_require_gpu, or FLUIDSURF_REQUIRE_GPU in the environment */
static int require_gpu;

void fs_gl_context_require_gpu(int on) { require_gpu = on; }

/* A software rasterizer when a GPU is required: one line naming the renderer and
 * what asked for a GPU. */
static int check_required_gpu(const fs_gl_context *c)
{
    const char *env = getenv("FLUIDSURF_REQUIRE_GPU");
    int from_env = env && *env && strcmp(env, "0");
    if (!c->software || !(require_gpu || from_env)) return FS_OK;
    char who[64];
    snprintf(who, sizeof who, "%s", fs_word("require_gpu"));
    if (!require_gpu) snprintf(who, sizeof who, "FLUIDSURF_REQUIRE_GPU=%s", env);
    return fs_fail(FS_ERR_RUNTIME, "%s: the OpenGL renderer is %s, a software rasterizer", who, c->renderer);
}

int fs_gl_context_create(fs_gl_context *c, fs_ctx_kind kind, int width, int height)
{
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->width = width > 0 ? width : 16;
    c->height = height > 0 ? height : 16;
    c->device = -1;
    /* Creating may bind and unbind (GLFW): release the bound context first and
     * give it back if creation fails. */
    fs_gl_context prev = bound;
    release_bound();
    int rc = kind == FS_CTX_EGL ? create_egl(c) : kind == FS_CTX_GLFW ? create_glfw(c) : create_osmesa(c);
    if (!rc) rc = fs_gl_context_make_current(c);
    if (!rc) c->software |= fs_gl_renderer_is_software(c->renderer);
    if (!rc) rc = check_required_gpu(c);
    if (!rc) rc = fs_gl_limits_check_current(c->renderer); /* docs/DESIGN.md, "GL limits" */
    if (rc) {
        char msg[1024];
        snprintf(msg, sizeof msg, "%s", fs_error_message());
        fs_gl_context_destroy(c);
        if (prev.handle) fs_gl_context_make_current(&prev);
        return fs_fail(rc, "%s", msg);
    }
    return FS_OK;
}

void fs_gl_context_destroy(fs_gl_context *c)
{
    if (!c->handle) return;
    if (bound.handle == c->handle) release_bound();
    switch (c->kind) {
#if FS_WITH_OSMESA
    case FS_CTX_OSMESA:
        osm.DestroyContext(c->handle);
        free(c->extra);
        break;
#endif
    case FS_CTX_EGL: {
        egl_fns *e = c->extra;
        e->DestroyContext(e->dpy, c->handle);
        if (--egl_users == 0) e->Terminate(e->dpy);
        dlclose(e->lib);
        free(e);
        break;
    }
#if FS_WITH_GLFW
    case FS_CTX_GLFW:
        glfwDestroyWindow(c->handle);
        if (--glfw_users == 0) glfwTerminate();
        break;
#endif
    default: break;
    }
    memset(c, 0, sizeof *c);
}
