#include "gl_stage.h"
#include "gl.h"
#include <math.h>

/* The GL clock at the last wall-clock mark (a start, or an end that may start
 * the next stage), per thread as GL contexts are. Only numbers are kept, never
 * a query left running, so contexts may come and go between stages. */
static _Thread_local double mark_wall = NAN;
static _Thread_local GLint64 mark_gl;

static void mark(double wall, GLint64 gl_ns)
{
    mark_wall = wall;
    mark_gl = gl_ns;
}

double fs_gl_stage_start(void)
{
    glFinish();
    GLint64 now = 0;
    glGetInteger64v(GL_TIMESTAMP, &now); /* the GL is idle: its clock now */
    double wall = fs_now_ms();
    mark(wall, now);
    return wall;
}

double fs_gl_stage_end(fs_stages *t, const char *name, double start)
{
    GLuint q = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &q);
    glQueryCounter(q, GL_TIMESTAMP); /* when the stage's commands are done */
    glFinish();
    double end = fs_now_ms();
    GLuint64 done = 0;
    glGetQueryObjectui64v(q, GL_QUERY_RESULT, &done);
    glDeleteQueries(1, &q);
    double gpu = start == mark_wall && done >= (GLuint64)mark_gl ? (done - (GLuint64)mark_gl) * 1e-6 : NAN;
    fs_stages_add_gpu(t, name, end - start, gpu);
    mark(end, (GLint64)done);
    return end;
}
