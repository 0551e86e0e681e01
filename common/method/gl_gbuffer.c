/* Reading the GL render targets into the CPU G-buffer (gl_gbuffer.h). */
#include "gl_gbuffer.h"
#include "fs_error.h"
#include "gl.h"
#include "vec3.h"
#include <math.h>
#include <stdlib.h>

/* The reads of the layers g holds: depth, the normal (into t's RGBA copy,
 * unpacked by renormalize), thickness, colour when g has that layer; then the
 * caller's. Returns how many (at most 4 + nextra). */
static int layer_reads(const fs_gl_target *t, const fs_gbuffer *g, const fs_gl_read *extra, int nextra,
                       fs_gl_read *reads)
{
    int n = 0;
    reads[n++] = (fs_gl_read){t->tex[FS_TARGET_DEPTH], 1, g->depth};
    reads[n++] = (fs_gl_read){t->tex[FS_TARGET_NORMAL], 4, t->normal_rgba};
    reads[n++] = (fs_gl_read){t->tex[FS_TARGET_THICKNESS], 1, g->thickness};
    float *color = fs_gbuffer_aov(g, FS_AOV_COLOR);
    if (color) reads[n++] = (fs_gl_read){t->tex[FS_TARGET_COLOR], 4, color};
    for (int i = 0; i < nextra; i++) reads[n++] = extra[i];
    return n;
}

/* Coverage from the normal's w; the unit normal where covered, 0 and depth
 * INFINITY where not. OpenMP over pixels: each is independent, so the result
 * does not depend on the threads. */
static void renormalize(const float *nrm, fs_gbuffer *g)
{
    const long n = (long)g->w * g->h;
#pragma omp parallel for schedule(static) if (n > 65536)
    for (long i = 0; i < n; i++) {
        float cov = nrm[4 * i + 3] > 0.5f ? 1.0f : 0.0f;
        g->coverage[i] = cov;
        float *o = g->normal + 3 * i;
        const float *s = nrm + 4 * i;
        float l = fs_v3_len(s);
        for (int k = 0; k < 3; k++) o[k] = cov && l > 0 ? s[k] / l : 0.0f;
        if (!cov) g->depth[i] = INFINITY;
    }
}

int fs_gl_target_read(fs_gl_target *t, fs_gbuffer *g, const fs_gl_read *extra, int nextra, fs_stages *st)
{
    if (nextra < 0 || nextra > FS_GL_TARGET_MAX_EXTRA)
        return fs_fail(FS_ERR_INPUT, "G-buffer read: %d extra layers (at most %d)", nextra, FS_GL_TARGET_MAX_EXTRA);
    if (!t->normal_rgba && !(t->normal_rgba = malloc((size_t)t->w * t->h * 4 * sizeof(float))))
        return fs_fail(FS_ERR_RUNTIME, "out of memory reading the G-buffer");
    fs_gl_read reads[4 + FS_GL_TARGET_MAX_EXTRA];
    int n = layer_reads(t, g, extra, nextra, reads);
    double t0 = fs_now_ms();
    int rc = fs_gl_readback_run(&t->rb, reads, n, t->w, t->h);
    double t1 = fs_now_ms();
    if (st) fs_stages_add(st, "readback", t1 - t0);
    if (rc) return rc;
    renormalize(t->normal_rgba, g);
    if (st) fs_stages_add(st, "renormalize", fs_now_ms() - t1);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL: error while reading the G-buffer");
}
