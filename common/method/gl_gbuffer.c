/* Reading the GL render targets into the CPU G-buffer (gl_gbuffer.h). */
#include "gl_gbuffer.h"
#include "fs_error.h"
#include "gl.h"
#include "vec3.h"
#include <math.h>
#include <stdlib.h>

int fs_gl_target_read(const fs_gl_target *t, fs_gbuffer *g)
{
    size_t n = (size_t)t->w * t->h;
    float *nrm = malloc(4 * n * sizeof(float));
    if (!nrm) return fs_fail(FS_ERR_RUNTIME, "out of memory reading the G-buffer");
    int rc = fs_gl_read_texture(t->tex[FS_TARGET_DEPTH], 1, t->w, t->h, g->depth);
    if (!rc) rc = fs_gl_read_texture(t->tex[FS_TARGET_NORMAL], 4, t->w, t->h, nrm);
    if (!rc) rc = fs_gl_read_texture(t->tex[FS_TARGET_THICKNESS], 1, t->w, t->h, g->thickness);
    float *color = fs_gbuffer_aov(g, FS_AOV_COLOR);
    if (!rc && color) rc = fs_gl_read_texture(t->tex[FS_TARGET_COLOR], 4, t->w, t->h, color);
    if (rc) {
        free(nrm);
        return rc;
    }
    for (size_t i = 0; i < n; i++) {
        float cov = nrm[4 * i + 3] > 0.5f ? 1.0f : 0.0f;
        g->coverage[i] = cov;
        float *o = g->normal + 3 * i, *s = nrm + 4 * i;
        float l = fs_v3_len(s);
        for (int k = 0; k < 3; k++) o[k] = cov && l > 0 ? s[k] / l : 0.0f;
        if (!cov) g->depth[i] = INFINITY;
    }
    free(nrm);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL: error while reading the G-buffer");
}

int fs_gl_target_read_timed(const fs_gl_target *t, fs_gbuffer *g, fs_stages *st)
{
    double t0 = fs_now_ms();
    int rc = fs_gl_target_read(t, g);
    fs_stages_add(st, "readback", fs_now_ms() - t0);
    return rc;
}
