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
    int tw, th;         /* size of tex */
    fs_gl_chunks parts; /* the particles of the last run, in band order */
    size_t disks;
    /* uniform locations */
    int u_first, u_axes, u_origin, u_spacing, u_size, u_zrange, u_H, u_planes, u_V, u_kernel;
};

fs_slice_splat *fs_slice_splat_create(void)
{
    fs_slice_splat *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory");
        return NULL;
    }
    const char *st[] = {"common/slice_splat.vert.glsl", "common/slice_splat.frag.glsl", NULL};
    s->prog = fs_program_build(st, NULL);
    if (!s->prog) {
        free(s);
        return NULL;
    }
    glCreateVertexArrays(1, &s->vao);
    const struct {
        int *loc;
        const char *name;
    } u[] = {
        {&s->u_first, "u_first"}, {&s->u_axes, "u_axes"},     {&s->u_origin, "u_origin"}, {&s->u_spacing, "u_spacing"},
        {&s->u_size, "u_size"},   {&s->u_zrange, "u_zrange"}, {&s->u_H, "u_H"},           {&s->u_planes, "u_planes"},
        {&s->u_V, "u_V"},         {&s->u_kernel, "u_kernel"},
    };
    for (size_t i = 0; i < sizeof u / sizeof *u; i++) *u[i].loc = glGetUniformLocation(s->prog, u[i].name);
    return s;
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
    fs_gl_chunks_free(&s->parts);
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
        free(band);
        free(v);
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
        free(band);
        free(v);
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
    int rc = fs_gl_chunks_upload(&s->parts, v, p->n, "slice splat");
    free(v);
    return rc;
}

/* Draws particle slots [s0, s1), split over the chunked buffers. */
static void draw_range(const fs_slice_splat *s, size_t s0, size_t s1)
{
    const size_t chunk = s->parts.chunk;
    for (int b = 0; b < s->parts.n; b++) {
        size_t c0 = (size_t)b * chunk, c1 = c0 + chunk;
        size_t lo = s0 > c0 ? s0 : c0, hi = s1 < c1 ? s1 : c1;
        if (lo >= hi) continue;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, s->parts.bufs[b]);
        glUniform1i(s->u_first, (int)(lo - c0));
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)(hi - lo));
    }
}

static int check_run(const fs_density_grid *g, const fs_field *f, int up_axis, int clusters)
{
    if (!g->data) return fs_fail(FS_ERR_INPUT, "slice splat: density grid not initialised");
    if (up_axis < 0 || up_axis > 2) return fs_fail(FS_ERR_INPUT, "slice splat: up axis %d is not 0, 1 or 2", up_axis);
    if (clusters < 1 || clusters > MAX_CLUSTERS)
        return fs_fail(FS_ERR_INPUT, "slice splat: %d clusters (1 to %d)", clusters, MAX_CLUSTERS);
    if (!(f->H > 0) || !(f->volume > 0) || !isfinite(f->H) || !isfinite(f->volume))
        return fs_fail(FS_ERR_INPUT, "slice splat: support H %g and volume V %g must be positive", f->H, f->volume);
    return FS_OK;
}

/* A grid plane as a framebuffer: pixel (i, j) is grid point i along ax, j along
 * bx (the two axes other than up, in increasing order), w x h pixels. */
typedef struct plane_axes {
    int up, ax, bx, w, h;
} plane_axes;

static int plane_axes_of(const fs_density_grid *g, int up, plane_axes *a)
{
    a->up = up;
    a->ax = up == 0 ? 1 : 0;
    a->bx = up == 2 ? 1 : 2;
    a->w = g->dim[a->ax];
    a->h = g->dim[a->bx];
    GLint maxtex = 0, maxvp[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxtex);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxvp);
    if (a->w > maxtex || a->h > maxtex || a->w > maxvp[0] || a->h > maxvp[1])
        return fs_fail(FS_ERR_INPUT,
                       "slice splat: planes of %dx%d points exceed this context's %dx%d framebuffer limit", a->w, a->h,
                       maxvp[0] < maxtex ? maxvp[0] : maxtex, maxvp[1] < maxtex ? maxvp[1] : maxtex);
    return FS_OK;
}

/* The clusters of a run: nc bands with boundaries zb and first slots start
 * (nc + 1 each), and the read-back pixels of one group of planes. */
typedef struct bands {
    int nc;
    float *zb;
    size_t *start;
    float *pix;
} bands;

static void free_bands(bands *b)
{
    free(b->zb);
    free(b->start);
    free(b->pix);
}

static int alloc_bands(bands *b, int nc, const plane_axes *a)
{
    b->nc = nc;
    b->zb = malloc((nc + 1) * sizeof *b->zb);
    b->start = malloc((nc + 1) * sizeof *b->start);
    b->pix = malloc((size_t)a->w * a->h * 4 * sizeof(float));
    if (!b->zb || !b->start || !b->pix)
        return fs_fail(FS_ERR_RUNTIME, "slice splat: out of memory for a %dx%d framebuffer", a->w, a->h);
    return FS_OK;
}

/* Additive blending into the planes' framebuffer, the grid's uniforms. */
static void begin_splat(const fs_slice_splat *s, const fs_density_grid *g, const fs_field *f, const plane_axes *a)
{
    glBindFramebuffer(GL_FRAMEBUFFER, s->fbo);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, a->w, a->h);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glUseProgram(s->prog);
    glBindVertexArray(s->vao);
    const int axes[3] = {a->ax, a->bx, a->up};
    glUniform3iv(s->u_axes, 1, axes);
    glUniform2f(s->u_origin, g->origin[a->ax], g->origin[a->bx]);
    glUniform1f(s->u_spacing, g->spacing);
    glUniform2f(s->u_size, (float)a->w, (float)a->h);
    glUniform1f(s->u_H, f->H);
    glUniform1f(s->u_V, f->volume);
    glUniform1i(s->u_kernel, (int)f->kernel);
}

static void end_splat(void)
{
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* Whether band k can reach one of the np planes at heights planes[]. */
static int band_reaches(const bands *b, int k, float H, const float *planes, int np)
{
    int reach = 0;
    for (int c = 0; c < np && !reach; c++) reach = b->zb[k] - H <= planes[c] && planes[c] < b->zb[k + 1] + H;
    return reach;
}

/* Draws the bands that can reach one of the planes, as runs of consecutive
 * bands; returns whether any particle was drawn. */
static int draw_reaching_bands(fs_slice_splat *s, const bands *b, float H, const float *planes, int np)
{
    int drawn = 0;
    for (int k = 0; k < b->nc;) {
        int run = k;
        while (run < b->nc && band_reaches(b, run, H, planes, np)) run++;
        if (run > k && b->start[run] > b->start[k]) {
            draw_range(s, b->start[k], b->start[run]);
            s->disks += b->start[run] - b->start[k];
            drawn = 1;
        }
        k = run > k ? run : k + 1;
    }
    return drawn;
}

/* Channel c of the read-back pixels (zeros when nothing was drawn) into grid plane k. */
static void store_plane(fs_density_grid *g, const plane_axes *a, const float *pix, int c, int k, int drawn)
{
    const int w = a->w;
    int ijk[3];
    ijk[a->up] = k;
    for (int j = 0; j < a->h; j++) {
        ijk[a->bx] = j;
        ijk[a->ax] = 0;
        const float *src = pix + (size_t)j * w * 4 + c;
        if (a->ax == 0) { /* a row of pixels is a row of the grid */
            float *dst = g->data + fs_density_grid_index(g, ijk[0], ijk[1], ijk[2]);
            if (drawn)
                for (int i = 0; i < w; i++) dst[i] = src[4 * i];
            else memset(dst, 0, (size_t)w * sizeof(float));
        } else {
            for (int i = 0; i < w; i++) {
                ijk[a->ax] = i;
                g->data[fs_density_grid_index(g, ijk[0], ijk[1], ijk[2])] = drawn ? src[4 * i] : 0.0f;
            }
        }
    }
}

/* Step 2 for the grid planes k0 .. k0 + np - 1 (np <= 4, one per channel). */
static void splat_planes(fs_slice_splat *s, fs_density_grid *g, const plane_axes *a, const bands *b, float H, int k0,
                         int np)
{
    const float zero[4] = {0, 0, 0, 0};
    float planes[4];
    for (int c = 0; c < 4; c++) planes[c] = g->origin[a->up] + g->spacing * (k0 + c);
    glClearNamedFramebufferfv(s->fbo, GL_COLOR, 0, zero);
    glUniform4f(s->u_planes, planes[0], planes[1], planes[2], planes[3]);
    glUniform2f(s->u_zrange, planes[0], planes[np - 1]);
    int drawn = draw_reaching_bands(s, b, H, planes, np);
    if (drawn) glReadPixels(0, 0, a->w, a->h, GL_RGBA, GL_FLOAT, b->pix);
    for (int c = 0; c < np; c++) store_plane(g, a, b->pix, c, k0 + c, drawn);
}

int fs_slice_splat_run(fs_slice_splat *s, fs_density_grid *g, const fs_particles *p, const fs_field *f, int up_axis,
                       int clusters)
{
    int rc = check_run(g, f, up_axis, clusters);
    if (rc) return rc;
    s->disks = 0;
    if (p->n == 0) {
        memset(g->data, 0, fs_density_grid_points(g) * sizeof(float));
        return FS_OK;
    }
    plane_axes a;
    if ((rc = plane_axes_of(g, up_axis, &a)) || (rc = ensure_target(s, a.w, a.h))) return rc;
    bands b = {0};
    if ((rc = alloc_bands(&b, clusters, &a)) || (rc = cluster_upload(s, p, a.up, clusters, b.zb, b.start))) {
        free_bands(&b);
        return rc;
    }
    begin_splat(s, g, f, &a);
    const int nplanes = g->dim[a.up];
    for (int k0 = 0; k0 < nplanes; k0 += 4) splat_planes(s, g, &a, &b, f->H, k0, nplanes - k0 < 4 ? nplanes - k0 : 4);
    end_splat();
    free_bands(&b);
    if (glGetError() != GL_NO_ERROR) return fs_fail(FS_ERR_RUNTIME, "slice splat: OpenGL error while splatting");
    return FS_OK;
}
