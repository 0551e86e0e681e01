/* iwasaki2006 section 4: the density grid by slice splatting (density_grid.h).
 *
 * 1. Clustering: the particles are counting-sorted into N_c bands of equal
 *    height along the up axis (band k holds z_k <= z < z_{k+1}) and uploaded
 *    once, in band order, as chunked storage buffers.
 * 2. For each group of four grid planes: clear an RGBA32F framebuffer whose
 *    pixels are the grid points of a plane, draw one quad per particle of every
 *    band that can reach one of the planes (z_k - H <= plane < z_{k+1} + H),
 *    accumulate V W(d, H) for the four planes in the four channels with
 *    additive blending, and read the four channels back into the grid.
 * Shaders: shaders/common/slice_splat.{vert,frag}.glsl. */
#include "density_splat.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include "shader.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAX_CLUSTERS (1 << 16)

struct fs_slice_splat {
    unsigned prog, vao, fbo, tex;
    int tw, th;           /* size of tex */
    unsigned *bufs;       /* particle buffers of the last run */
    int nbufs;
    size_t disks;
    /* uniform locations */
    int u_first, u_axes, u_origin, u_spacing, u_size, u_zrange, u_H, u_planes, u_V, u_kernel;
};

fs_slice_splat *fs_slice_splat_create(void)
{
    fs_slice_splat *s = calloc(1, sizeof *s);
    if (!s) { fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory"); return NULL; }
    const char *st[] = {"common/slice_splat.vert.glsl", "common/slice_splat.frag.glsl", NULL};
    s->prog = fs_program_build(st, NULL);
    if (!s->prog) { free(s); return NULL; }
    glCreateVertexArrays(1, &s->vao);
    const struct { int *loc; const char *name; } u[] = {
        {&s->u_first, "u_first"},   {&s->u_axes, "u_axes"},     {&s->u_origin, "u_origin"}, {&s->u_spacing, "u_spacing"},
        {&s->u_size, "u_size"},     {&s->u_zrange, "u_zrange"}, {&s->u_H, "u_H"},           {&s->u_planes, "u_planes"},
        {&s->u_V, "u_V"},           {&s->u_kernel, "u_kernel"},
    };
    for (size_t i = 0; i < sizeof u / sizeof *u; i++) *u[i].loc = glGetUniformLocation(s->prog, u[i].name);
    return s;
}

static void free_buffers(fs_slice_splat *s)
{
    if (s->nbufs) glDeleteBuffers(s->nbufs, s->bufs);
    free(s->bufs);
    s->bufs = NULL;
    s->nbufs = 0;
}

static void free_target(fs_slice_splat *s)
{
    if (s->fbo) glDeleteFramebuffers(1, &s->fbo);
    if (s->tex) glDeleteTextures(1, &s->tex);
    s->fbo = s->tex = 0;
    s->tw = s->th = 0;
}

void fs_slice_splat_destroy(fs_slice_splat *s)
{
    if (!s) return;
    free_buffers(s);
    free_target(s);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    if (s->prog) glDeleteProgram(s->prog);
    free(s);
}

size_t fs_slice_splat_disks(const fs_slice_splat *s) { return s ? s->disks : 0; }

static int ensure_target(fs_slice_splat *s, int w, int h)
{
    if (s->tex && s->tw == w && s->th == h) return FS_OK;
    free_target(s);
    glCreateTextures(GL_TEXTURE_2D, 1, &s->tex);
    glTextureStorage2D(s->tex, 1, GL_RGBA32F, w, h);
    glCreateFramebuffers(1, &s->fbo);
    glNamedFramebufferTexture(s->fbo, GL_COLOR_ATTACHMENT0, s->tex, 0);
    if (glCheckNamedFramebufferStatus(s->fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        free_target(s);
        return fs_fail(FS_ERR_RUNTIME, "slice splat: RGBA32F framebuffer of %dx%d is incomplete", w, h);
    }
    s->tw = w;
    s->th = h;
    return FS_OK;
}

/* Band of height z: the float boundaries zb decide, so that every particle of
 * band k satisfies zb[k] <= z < zb[k+1] exactly (the last band also holds zmax). */
static int band_of(float z, const float *zb, int nc, float zmin, float inv_t)
{
    int b = (int)((z - zmin) * inv_t);
    if (b < 0) b = 0;
    if (b > nc - 1) b = nc - 1;
    while (b > 0 && z < zb[b]) b--;
    while (b < nc - 1 && z >= zb[b + 1]) b++;
    return b;
}

/* Clusters the particles into bands and uploads them in band order; start[k]
 * is the first slot of band k (nc + 1 entries). */
static int cluster_upload(fs_slice_splat *s, const fs_particles *p, int up, int nc, float *zb, size_t *start)
{
    const float *pz = up == 0 ? p->x : up == 1 ? p->y : p->z;
    float zmin = INFINITY, zmax = -INFINITY;
    for (size_t i = 0; i < p->n; i++) {
        if (!isfinite(p->x[i]) || !isfinite(p->y[i]) || !isfinite(p->z[i]))
            return fs_fail(FS_ERR_INPUT, "slice splat: particle %zu has a non-finite position", i);
        zmin = fminf(zmin, pz[i]);
        zmax = fmaxf(zmax, pz[i]);
    }
    float t = (zmax - zmin) / nc, inv_t = t > 0 ? 1.0f / t : 0.0f;
    for (int k = 0; k < nc; k++) zb[k] = zmin + t * k;
    zb[nc] = zmax;
    unsigned short *band = malloc(p->n * sizeof *band);
    float *v = malloc(p->n * 4 * sizeof(float));
    if (!band || !v) {
        free(band); free(v);
        return fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory for %zu particles", p->n);
    }
    memset(start, 0, (nc + 1) * sizeof *start);
    for (size_t i = 0; i < p->n; i++) {
        band[i] = (unsigned short)band_of(pz[i], zb, nc, zmin, inv_t);
        start[band[i] + 1]++;
    }
    for (int k = 0; k < nc; k++) start[k + 1] += start[k];
    size_t *fill = malloc(nc * sizeof *fill);
    if (!fill) {
        free(band); free(v);
        return fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory");
    }
    memcpy(fill, start, nc * sizeof *fill);
    for (size_t i = 0; i < p->n; i++) {
        float *o = v + 4 * fill[band[i]]++;
        o[0] = p->x[i];
        o[1] = p->y[i];
        o[2] = p->z[i];
        o[3] = 0.0f;
    }
    free(fill);
    free(band);
    free_buffers(s);
    size_t chunk = fs_gl_ssbo_chunk(4 * sizeof(float));
    int maxb = (int)((p->n + chunk - 1) / chunk);
    s->bufs = calloc(maxb, sizeof *s->bufs);
    if (!s->bufs) { free(v); return fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory"); }
    int nb = fs_gl_upload_chunked(v, p->n, chunk, s->bufs, maxb);
    free(v);
    if (nb < 0) { free_buffers(s); return -nb; }
    s->nbufs = nb;
    return FS_OK;
}

/* Draws particle slots [s0, s1), split over the chunked buffers. */
static void draw_range(const fs_slice_splat *s, size_t s0, size_t s1, size_t chunk)
{
    for (int b = 0; b < s->nbufs; b++) {
        size_t c0 = (size_t)b * chunk, c1 = c0 + chunk;
        size_t lo = s0 > c0 ? s0 : c0, hi = s1 < c1 ? s1 : c1;
        if (lo >= hi) continue;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, s->bufs[b]);
        glUniform1i(s->u_first, (int)(lo - c0));
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)(hi - lo));
    }
}

int fs_slice_splat_run(fs_slice_splat *s, fs_density_grid *g, const fs_particles *p, const fs_field *f, int up_axis,
                       int clusters)
{
    if (!g->data) return fs_fail(FS_ERR_INPUT, "slice splat: density grid not initialised");
    if (up_axis < 0 || up_axis > 2) return fs_fail(FS_ERR_INPUT, "slice splat: up axis %d is not 0, 1 or 2", up_axis);
    if (clusters < 1 || clusters > MAX_CLUSTERS)
        return fs_fail(FS_ERR_INPUT, "slice splat: %d clusters (1 to %d)", clusters, MAX_CLUSTERS);
    if (!(f->H > 0) || !(f->volume > 0) || !isfinite(f->H) || !isfinite(f->volume))
        return fs_fail(FS_ERR_INPUT, "slice splat: support H %g and volume V %g must be positive", f->H, f->volume);
    s->disks = 0;
    size_t npts = fs_density_grid_points(g);
    if (p->n == 0) {
        memset(g->data, 0, npts * sizeof(float));
        return FS_OK;
    }
    /* framebuffer axes: the two other axes in increasing order */
    const int up = up_axis, ax = up == 0 ? 1 : 0, bx = up == 2 ? 1 : 2;
    const int w = g->dim[ax], h = g->dim[bx], nplanes_all = g->dim[up];
    GLint maxtex = 0, maxvp[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxtex);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxvp);
    if (w > maxtex || h > maxtex || w > maxvp[0] || h > maxvp[1])
        return fs_fail(FS_ERR_INPUT, "slice splat: planes of %dx%d points exceed this context's %dx%d framebuffer limit",
                       w, h, maxvp[0] < maxtex ? maxvp[0] : maxtex, maxvp[1] < maxtex ? maxvp[1] : maxtex);
    int rc = ensure_target(s, w, h);
    if (rc) return rc;

    float *zb = malloc((clusters + 1) * sizeof *zb);
    size_t *start = malloc((clusters + 1) * sizeof *start);
    float *pix = malloc((size_t)w * h * 4 * sizeof(float));
    if (!zb || !start || !pix) {
        free(zb); free(start); free(pix);
        return fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory for a %dx%d framebuffer", w, h);
    }
    rc = cluster_upload(s, p, up, clusters, zb, start);
    if (rc) { free(zb); free(start); free(pix); return rc; }
    const size_t chunk = fs_gl_ssbo_chunk(4 * sizeof(float));
    const float H = f->H, sp = g->spacing;

    glBindFramebuffer(GL_FRAMEBUFFER, s->fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glUseProgram(s->prog);
    glBindVertexArray(s->vao);
    const int axes[3] = {ax, bx, up};
    glUniform3iv(s->u_axes, 1, axes);
    glUniform2f(s->u_origin, g->origin[ax], g->origin[bx]);
    glUniform1f(s->u_spacing, sp);
    glUniform2f(s->u_size, (float)w, (float)h);
    glUniform1f(s->u_H, H);
    glUniform1f(s->u_V, f->volume);
    glUniform1i(s->u_kernel, (int)f->kernel);
    const float zero[4] = {0, 0, 0, 0};

    for (int k0 = 0; k0 < nplanes_all; k0 += 4) {
        int np = nplanes_all - k0 < 4 ? nplanes_all - k0 : 4;
        float planes[4];
        for (int c = 0; c < 4; c++) planes[c] = g->origin[up] + sp * (k0 + c);
        glClearNamedFramebufferfv(s->fbo, GL_COLOR, 0, zero);
        glUniform4f(s->u_planes, planes[0], planes[1], planes[2], planes[3]);
        glUniform2f(s->u_zrange, planes[0], planes[np - 1]);
        /* the bands that can reach one of the planes, drawn as runs of consecutive bands */
        int drawn = 0;
        for (int k = 0; k < clusters;) {
            int run = k;
            for (; run < clusters; run++) {
                int reach = 0;
                for (int c = 0; c < np && !reach; c++) reach = zb[run] - H <= planes[c] && planes[c] < zb[run + 1] + H;
                if (!reach) break;
            }
            if (run > k && start[run] > start[k]) {
                draw_range(s, start[k], start[run], chunk);
                s->disks += start[run] - start[k];
                drawn = 1;
            }
            k = run > k ? run : k + 1;
        }
        if (drawn) glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, pix);
        /* pixel (i, j) of plane k0 + c is grid point i along ax, j along bx */
        for (int c = 0; c < np; c++) {
            int ijk[3];
            ijk[up] = k0 + c;
            for (int j = 0; j < h; j++) {
                ijk[bx] = j;
                ijk[ax] = 0;
                const float *src = pix + (size_t)j * w * 4 + c;
                if (ax == 0) { /* a row of pixels is a row of the grid */
                    float *dst = g->data + fs_density_grid_index(g, ijk[0], ijk[1], ijk[2]);
                    if (drawn) for (int i = 0; i < w; i++) dst[i] = src[4 * i];
                    else memset(dst, 0, (size_t)w * sizeof(float));
                } else {
                    for (int i = 0; i < w; i++) {
                        ijk[ax] = i;
                        g->data[fs_density_grid_index(g, ijk[0], ijk[1], ijk[2])] = drawn ? src[4 * i] : 0.0f;
                    }
                }
            }
        }
    }
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    free(zb);
    free(start);
    free(pix);
    if (glGetError() != GL_NO_ERROR) return fs_fail(FS_ERR_RUNTIME, "slice splat: OpenGL error while splatting");
    return FS_OK;
}
