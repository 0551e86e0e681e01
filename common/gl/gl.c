#define FS_GL_NO_MACROS
#include "gl.h"
#include "fs_error.h"
#include <stdio.h>

fs_gl_table fs_gl;

int fs_gl_load(fs_gl_getproc getproc)
{
#define FS_GL(name, type)                                                                                              \
    if (!(fs_gl.name = (type)getproc(#name))) return fs_fail(FS_ERR_RUNTIME, "OpenGL: the context has no %s", #name);
#include "gl_funcs.h"
#undef FS_GL
    return FS_OK;
}

int fs_gl_check_core45(char *renderer, int rsize, char *version, int vsize)
{
    GLint major = 0, minor = 0, mask = 0;
    if (!fs_gl.glGetIntegerv || !fs_gl.glGetString)
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: no context has been made current");
    fs_gl.glGetIntegerv(GL_MAJOR_VERSION, &major);
    fs_gl.glGetIntegerv(GL_MINOR_VERSION, &minor);
    fs_gl.glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
    if (major * 10 + minor < 45 || !(mask & GL_CONTEXT_CORE_PROFILE_BIT))
        return fs_fail(FS_ERR_RUNTIME, "OpenGL: got %d.%d %s, need 4.5 core", major, minor,
                       mask & GL_CONTEXT_CORE_PROFILE_BIT ? "core" : "compatibility");
    snprintf(renderer, rsize, "%s", (const char *)fs_gl.glGetString(GL_RENDERER));
    snprintf(version, vsize, "%s", (const char *)fs_gl.glGetString(GL_VERSION));
    return FS_OK;
}
