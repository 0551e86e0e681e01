#include "gl_stage.h"
#include "gl.h"

double fs_gl_stage_end(fs_stages *t, const char *name, double start)
{
    glFinish();
    double end = fs_now_ms();
    fs_stages_add(t, name, end - start);
    return end;
}
