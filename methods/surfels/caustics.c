/* Caustics from surfels through illumination volumes (iwasaki2006 5.1-5.2);
 * see caustics.h for the steps and the conventions. */
#include "caustics.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include "shader.h"
#include "vec3.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define TRI_VEC4 5   /* vec4s per plane triangle (caustic_accum.vert.glsl) */
#define SQ_MIN 1e-4f /* texel^2: smaller plane triangles go whole to one texel */
#define W_MIN 1e-4f  /* screen pixels with less summed weight are uncovered */

struct fs_caustics {
    unsigned prog_depth, prog_splat, prog_norm, prog_accum;
    unsigned vao;
    /* virtual screen */
    int screen_res;
    unsigned screen_fbo, screen_acc, screen_dacc, screen_zbuf, screen_out;
    float *screen; /* screen_res^2 x (n, d), d < 0: uncovered */
    /* sample planes */
    int plane_res, nplanes;
    unsigned plane_tex, plane_fbo;
    float *maps;
    unsigned tri_buf;
    size_t tri_buf_bytes;
    /* CPU work arrays */
    double *vtx;     /* per screen pixel (VTX): s[3], refracted t[3], cos(theta_i) T, depth d, valid */
    float *tris;     /* plane triangles, TRI_VEC4 vec4 each */
    size_t tris_cap; /* in triangles */
    size_t ntri;
    double flux_in, flux_plane[FS_CAUSTICS_MAX_PLANES];
    float eps_radii, max_jump_px;
};
#define VTX 9

fs_caustics *fs_caustics_create(void)
{
    fs_caustics *c = calloc(1, sizeof *c);
    if (!c) {
        fs_fail(FS_ERR_RUNTIME, "out of memory");
        return NULL;
    }
    c->eps_radii = 1.0f;
    c->max_jump_px = 4.0f;
    const char *scr[] = {"surfels/caustic_screen.vert.glsl", "surfels/caustic_screen.frag.glsl", NULL};
    const char *norm[] = {"surfels/caustic_normalize.comp.glsl", NULL};
    const char *acc[] = {"surfels/caustic_accum.vert.glsl", "surfels/caustic_accum.frag.glsl", NULL};
    if (!(c->prog_depth = fs_program_build(scr, "MODE_DEPTH 1")) || !(c->prog_splat = fs_program_build(scr, NULL)) ||
        !(c->prog_norm = fs_program_build(norm, NULL)) || !(c->prog_accum = fs_program_build(acc, NULL))) {
        fs_caustics_destroy(c);
        return NULL;
    }
    glCreateVertexArrays(1, &c->vao);
    return c;
}

static void free_screen(fs_caustics *c)
{
    if (c->screen_fbo) glDeleteFramebuffers(1, &c->screen_fbo);
    unsigned tex[4] = {c->screen_acc, c->screen_dacc, c->screen_zbuf, c->screen_out};
    for (int i = 0; i < 4; i++)
        if (tex[i]) glDeleteTextures(1, &tex[i]);
    c->screen_fbo = c->screen_acc = c->screen_dacc = c->screen_zbuf = c->screen_out = 0;
    free(c->screen);
    free(c->vtx);
    c->screen = NULL;
    c->vtx = NULL;
    c->screen_res = 0;
}

static void free_planes(fs_caustics *c)
{
    if (c->plane_fbo) glDeleteFramebuffers(1, &c->plane_fbo);
    if (c->plane_tex) glDeleteTextures(1, &c->plane_tex);
    c->plane_fbo = c->plane_tex = 0;
    free(c->maps);
    c->maps = NULL;
    c->plane_res = c->nplanes = 0;
}

void fs_caustics_destroy(fs_caustics *c)
{
    if (!c) return;
    free_screen(c);
    free_planes(c);
    unsigned progs[4] = {c->prog_depth, c->prog_splat, c->prog_norm, c->prog_accum};
    for (int i = 0; i < 4; i++)
        if (progs[i]) glDeleteProgram(progs[i]);
    if (c->vao) glDeleteVertexArrays(1, &c->vao);
    if (c->tri_buf) glDeleteBuffers(1, &c->tri_buf);
    free(c->tris);
    free(c);
}

void fs_caustics_set_max_jump(fs_caustics *c, float pixels) { c->max_jump_px = pixels; }

static int ensure_screen(fs_caustics *c, int res)
{
    if (c->screen_res == res) return FS_OK;
    free_screen(c);
    size_t n = (size_t)res * res;
    c->screen = malloc(n * 4 * sizeof *c->screen);
    c->vtx = malloc(n * VTX * sizeof *c->vtx);
    if (!c->screen || !c->vtx) {
        free_screen(c);
        return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory (screen %d^2)", res);
    }
    c->screen_acc = fs_gl_texture_2d(GL_RGBA32F, res, res);
    c->screen_dacc = fs_gl_texture_2d(GL_R32F, res, res);
    c->screen_zbuf = fs_gl_texture_2d(GL_DEPTH_COMPONENT32F, res, res);
    c->screen_out = fs_gl_texture_2d(GL_RGBA32F, res, res);
    glCreateFramebuffers(1, &c->screen_fbo);
    glNamedFramebufferTexture(c->screen_fbo, GL_COLOR_ATTACHMENT0, c->screen_acc, 0);
    glNamedFramebufferTexture(c->screen_fbo, GL_COLOR_ATTACHMENT1, c->screen_dacc, 0);
    glNamedFramebufferTexture(c->screen_fbo, GL_DEPTH_ATTACHMENT, c->screen_zbuf, 0);
    const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(c->screen_fbo, 2, bufs);
    c->screen_res = res;
    if (glCheckNamedFramebufferStatus(c->screen_fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        free_screen(c);
        return fs_fail(FS_ERR_RUNTIME, "caustics: OpenGL: the virtual screen (%d^2, float) is incomplete", res);
    }
    return FS_OK;
}

static int ensure_planes(fs_caustics *c, int res, int np)
{
    if (c->plane_res == res && c->nplanes == np) return FS_OK;
    free_planes(c);
    c->maps = malloc((size_t)res * res * np * 4 * sizeof *c->maps);
    if (!c->maps) return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory (%d planes of %d^2)", np, res);
    c->plane_tex = fs_gl_texture_2d_array(GL_RGBA32F, res, res, np);
    glCreateFramebuffers(1, &c->plane_fbo);
    glNamedFramebufferTextureLayer(c->plane_fbo, GL_COLOR_ATTACHMENT0, c->plane_tex, 0, 0);
    c->plane_res = res;
    c->nplanes = np;
    if (glCheckNamedFramebufferStatus(c->plane_fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        free_planes(c);
        return fs_fail(FS_ERR_RUNTIME, "caustics: OpenGL: the sample planes (%d^2, float) are incomplete", res);
    }
    return FS_OK;
}

static int check_setup(const fs_caustics_setup *s)
{
    if (s->up_axis < 0 || s->up_axis > 2)
        return fs_fail(FS_ERR_INPUT, "caustics: up_axis %d is not 0, 1 or 2", s->up_axis);
    const float *L = s->light_dir;
    float len = fs_v3_len(L);
    if (!(len > 0.0f) || !isfinite(len)) return fs_fail(FS_ERR_INPUT, "caustics: light_dir has no direction");
    if (!(L[s->up_axis] / len > 0.01f))
        return fs_fail(FS_ERR_INPUT, "caustics: the light must come from above (light_dir along up %g)",
                       L[s->up_axis] / len);
    if (!(s->ior >= 1.0f && s->ior < 10.0f)) return fs_fail(FS_ERR_INPUT, "caustics: ior %g out of range", s->ior);
    for (int k = 0; k < 3; k++)
        if (!(s->extinction[k] >= 0.0f) || !(s->light_color[k] >= 0.0f) || !isfinite(s->light_color[k]) ||
            !isfinite(s->extinction[k]))
            return fs_fail(FS_ERR_INPUT, "caustics: light colour and extinction must be finite and >= 0");
    for (int k = 0; k < 2; k++)
        if (!(s->rect_max[k] > s->rect_min[k]) || !isfinite(s->rect_min[k]) || !isfinite(s->rect_max[k]))
            return fs_fail(FS_ERR_INPUT, "caustics: empty rectangle along horizontal axis %d", k);
    if (s->screen_res < 2 || s->screen_res > 4096)
        return fs_fail(FS_ERR_INPUT, "caustics: screen_res %d out of range 2..4096", s->screen_res);
    if (s->plane_res < 1 || s->plane_res > 8192)
        return fs_fail(FS_ERR_INPUT, "caustics: plane_res %d out of range 1..8192", s->plane_res);
    if (s->nplanes < 1 || s->nplanes > FS_CAUSTICS_MAX_PLANES)
        return fs_fail(FS_ERR_INPUT, "caustics: nplanes %d out of range 1..%d", s->nplanes, FS_CAUSTICS_MAX_PLANES);
    for (int k = 0; k < s->nplanes; k++)
        if (!(s->plane_height[k] < s->top))
            return fs_fail(FS_ERR_INPUT, "caustics: sample plane %d (height %g) is not below the screen (%g)", k,
                           s->plane_height[k], s->top);
    return FS_OK;
}

/* Unpolarised Fresnel transmittance from air into a medium of index ior, for
 * incidence cosine ci and refraction cosine ct: 1 - (rs^2 + rp^2) / 2. */
static double fresnel_t(double ci, double ct, double ior)
{
    double rs = (ci - ior * ct) / (ci + ior * ct);
    double rp = (ior * ci - ct) / (ior * ci + ct);
    return 1.0 - 0.5 * (rs * rs + rp * rp);
}

double fs_caustics_transmittance(double cos_i, double ior)
{
    if (cos_i <= 0.0) return 0.0;
    if (cos_i > 1.0) cos_i = 1.0;
    double st2 = (1.0 - cos_i * cos_i) / (ior * ior);
    return fresnel_t(cos_i, sqrt(1.0 - st2), ior);
}

/* Draws n instances of a 4-vertex strip whose data (stride bytes each) sit in
 * buffer buf, in pieces that fit one SSBO binding. */
static void draw_chunked(unsigned buf, size_t n, size_t stride)
{
    size_t chunk = fs_gl_ssbo_chunk(stride);
    GLint align = 256;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
    if (align < 1) align = 256;
    /* pieces start at offsets that are multiples of the alignment */
    size_t unit = 1;
    while ((unit * stride) % (size_t)align) unit++;
    chunk -= chunk % unit;
    for (size_t first = 0; first < n; first += chunk) {
        size_t cnt = n - first < chunk ? n - first : chunk;
        if (first == 0 && cnt == n) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf);
        else
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, buf, (GLintptr)(first * stride), (GLsizeiptr)(cnt * stride));
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)cnt);
    }
}

static int ensure_tris(fs_caustics *c, size_t n)
{
    if (n <= c->tris_cap) return FS_OK;
    float *t = realloc(c->tris, n * TRI_VEC4 * 4 * sizeof *t);
    if (!t) return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory (%zu triangles)", n);
    c->tris = t;
    c->tris_cap = n;
    return FS_OK;
}

/* The light's frame: up the vertical axis, ax and bx the horizontal axes a and b
 * (u and v of the screen and the planes; unit vectors ea, eb, eu), L the unit
 * direction towards the light, tfar the depth range of the virtual screen. */
typedef struct light_frame {
    int up, ax, bx;
    float ea[3], eb[3], eu[3];
    double L[3];
    float tfar;
} light_frame;

/* The water-surface triangles whose refracted sweeps are the illumination
 * volumes: pixel index triples of the virtual screen, and their areas S. */
typedef struct water_tris {
    uint32_t *idx;
    double *area;
    size_t n;
} water_tris;

/* The size along horizontal axis 0 (a) or 1 (b) of one of res cells across the rectangle. */
static double cell_size(const fs_caustics_setup *s, int axis, int res)
{
    return ((double)s->rect_max[axis] - s->rect_min[axis]) / res;
}

/* Checks the setup and copies it to s with light_dir made unit; sizes the
 * virtual screen and the sample planes. */
static int begin_run(fs_caustics *c, const fs_caustics_setup *setup, fs_caustics_setup *s)
{
    int rc = check_setup(setup);
    if (rc) return rc;
    *s = *setup;
    float len = fs_v3_len(s->light_dir);
    for (int k = 0; k < 3; k++) s->light_dir[k] /= len;
    if ((rc = ensure_screen(c, s->screen_res)) || (rc = ensure_planes(c, s->plane_res, s->nplanes))) return rc;
    return FS_OK;
}

static void light_frame_of(const fs_caustics_setup *s, light_frame *f)
{
    f->up = s->up_axis;
    f->ax = (f->up + 1) % 3;
    f->bx = (f->up + 2) % 3;
    for (int k = 0; k < 3; k++) {
        f->ea[k] = f->eb[k] = f->eu[k] = 0.0f;
        f->L[k] = s->light_dir[k];
    }
    f->ea[f->ax] = f->eb[f->bx] = f->eu[f->up] = 1.0f;
    float lowest = s->plane_height[0];
    for (int k = 1; k < s->nplanes; k++) lowest = fminf(lowest, s->plane_height[k]);
    /* depth range: down to twice the deepest plane (depths beyond clamp to 1) */
    f->tfar = 2.0f * (s->top - lowest) / (float)f->L[f->up];
}

static void set_screen_uniforms(unsigned p, const fs_caustics_setup *s, const light_frame *f, float eps)
{
    int res = s->screen_res;
    float size[2] = {s->rect_max[0] - s->rect_min[0], s->rect_max[1] - s->rect_min[1]};
    glUseProgram(p);
    glUniform3fv(glGetUniformLocation(p, "u_light"), 1, s->light_dir);
    glUniform3fv(glGetUniformLocation(p, "u_ea"), 1, f->ea);
    glUniform3fv(glGetUniformLocation(p, "u_eb"), 1, f->eb);
    glUniform3fv(glGetUniformLocation(p, "u_eu"), 1, f->eu);
    glUniform2f(glGetUniformLocation(p, "u_rect_min"), s->rect_min[0], s->rect_min[1]);
    glUniform2f(glGetUniformLocation(p, "u_rect_size"), size[0], size[1]);
    glUniform2f(glGetUniformLocation(p, "u_pix"), size[0] / res, size[1] / res);
    glUniform1f(glGetUniformLocation(p, "u_top"), s->top);
    glUniform1f(glGetUniformLocation(p, "u_tfar"), f->tfar);
    glUniform1f(glGetUniformLocation(p, "u_eps"), eps);
}

/* Pass 0: depth only, with the epsilon offset; pass 1: blend what passes the
 * depth test, no depth writes. */
static void set_screen_pass_state(int pass)
{
    if (!pass) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_BLEND);
    } else {
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    }
}

/* Step 1 (5.2): the surfels splatted onto the virtual screen along the light
 * with Gaussian weights, summing g n and g d (eq. 3) where visible. */
static void splat_screen(fs_caustics *c, const fs_caustics_setup *s, const light_frame *f, unsigned ssbo, size_t n)
{
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    glClearNamedFramebufferfv(c->screen_fbo, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(c->screen_fbo, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(c->screen_fbo, GL_DEPTH, 0, &one);
    glBindFramebuffer(GL_FRAMEBUFFER, c->screen_fbo);
    glViewport(0, 0, s->screen_res, s->screen_res);
    glBindVertexArray(c->vao);
    glEnable(GL_DEPTH_TEST);
    for (int pass = 0; pass < 2 && n; pass++) {
        set_screen_uniforms(pass ? c->prog_splat : c->prog_depth, s, f, c->eps_radii);
        set_screen_pass_state(pass);
        draw_chunked(ssbo, n, sizeof(fs_surfel));
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* Step 1 (5.2): eq. 3's per-pixel normalisation, n(x,y) and d(x,y), read back
 * to c->screen. */
static void normalise_screen(fs_caustics *c, int res)
{
    glUseProgram(c->prog_norm);
    glUniform1i(glGetUniformLocation(c->prog_norm, "u_res"), res);
    glUniform1f(glGetUniformLocation(c->prog_norm, "u_wmin"), W_MIN);
    glBindImageTexture(0, c->screen_acc, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, c->screen_dacc, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(2, c->screen_out, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute((GLuint)(res + 7) / 8, (GLuint)(res + 7) / 8, 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(c->screen_out, 0, GL_RGBA, GL_FLOAT, (GLsizei)((size_t)res * res * 4 * sizeof(float)), c->screen);
}

/* One pixel of the virtual screen, px = (n, d), at screen point P: v gets the
 * surface point s = P - d L, the refracted direction t (unit), cos(theta_i) T
 * (times L_i per channel later), d, and 1; v[8] = 0 where the pixel is uncovered. */
static void surface_point(const float px[4], const double P[3], const double L[3], double ior, double *v)
{
    v[8] = 0;
    if (!(px[3] >= 0.0f) || !isfinite(px[0] + px[1] + px[2] + px[3])) return;
    const double eta = 1.0 / ior;
    double nrm[3] = {px[0], px[1], px[2]}, d = px[3];
    double ci = fs_v3d_dot(nrm, L);
    if (ci < 0) ci = 0;
    double st2 = eta * eta * (1.0 - ci * ci), ct = sqrt(1.0 - st2);
    for (int k = 0; k < 3; k++) {
        v[k] = P[k] - d * L[k];                            /* s */
        v[3 + k] = -eta * L[k] + (eta * ci - ct) * nrm[k]; /* refracted, unit */
    }
    v[6] = ci * fresnel_t(ci, ct, ior);
    v[7] = d;
    v[8] = 1;
}

/* Step 2 (5.2): per screen pixel P(x,y), the surface point s(x,y) and the
 * refracted direction of the incident light there, into c->vtx. */
static void surface_points(fs_caustics *c, const fs_caustics_setup *s, const light_frame *f)
{
    const int res = s->screen_res;
    const double pa = cell_size(s, 0, res), pb = cell_size(s, 1, res);
    for (int j = 0; j < res; j++)
        for (int i = 0; i < res; i++) {
            double P[3];
            P[f->ax] = s->rect_min[0] + (i + 0.5) * pa;
            P[f->bx] = s->rect_min[1] + (j + 0.5) * pb;
            P[f->up] = s->top;
            size_t q = (size_t)j * res + i;
            surface_point(c->screen + 4 * q, P, f->L, s->ior, c->vtx + VTX * q);
        }
}

/* Whether three pixels make a water triangle: all covered, and their depths
 * along the light within jump (else it straddles a depth discontinuity). */
static int is_water_triangle(const double *v0, const double *v1, const double *v2, double jump)
{
    if (!v0[8] || !v1[8] || !v2[8]) return 0;
    double dmin = fmin(v0[7], fmin(v1[7], v2[7])), dmax = fmax(v0[7], fmax(v1[7], v2[7]));
    return !(dmax - dmin > jump);
}

/* The area S of the triangle of surface points v0, v1, v2. */
static double triangle_area(const double *v0, const double *v1, const double *v2)
{
    double e1[3], e2[3], cr[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = v1[k] - v0[k];
        e2[k] = v2[k] - v0[k];
    }
    fs_v3d_cross(e1, e2, cr);
    return 0.5 * sqrt(fs_v3d_dot(cr, cr));
}

/* Step 2 (5.2): the illumination volumes, swept from the water triangles
 * (x,y),(x+1,y),(x,y+1) and (x+1,y+1),(x+1,y),(x,y+1) of covered pixels; sets
 * c->ntri and c->flux_in. On failure w holds nothing. */
static int illumination_volumes(fs_caustics *c, const fs_caustics_setup *s, water_tris *w)
{
    const int res = s->screen_res;
    const double jump = c->max_jump_px * fmax(cell_size(s, 0, res), cell_size(s, 1, res));
    const double lmean = (s->light_color[0] + s->light_color[1] + s->light_color[2]) / 3.0;
    const size_t maxtri = 2 * (size_t)(res - 1) * (res - 1);
    int rc = ensure_tris(c, maxtri);
    if (rc) return rc;
    w->idx = malloc(maxtri * 3 * sizeof *w->idx);
    w->area = malloc(maxtri * sizeof *w->area);
    if (!w->idx || !w->area) {
        free(w->idx);
        free(w->area);
        return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory");
    }
    w->n = 0;
    double flux_in = 0;
    for (int j = 0; j + 1 < res; j++)
        for (int i = 0; i + 1 < res; i++) {
            uint32_t q[4] = {(uint32_t)(j * res + i), (uint32_t)(j * res + i + 1), (uint32_t)((j + 1) * res + i),
                             (uint32_t)((j + 1) * res + i + 1)};
            const uint32_t tri[2][3] = {{q[0], q[1], q[2]}, {q[3], q[1], q[2]}};
            for (int h = 0; h < 2; h++) {
                const double *v0 = c->vtx + VTX * tri[h][0], *v1 = c->vtx + VTX * tri[h][1],
                             *v2 = c->vtx + VTX * tri[h][2];
                if (!is_water_triangle(v0, v1, v2, jump)) continue;
                memcpy(w->idx + 3 * w->n, tri[h], sizeof tri[h]);
                w->area[w->n] = triangle_area(v0, v1, v2);
                flux_in += w->area[w->n++] * lmean * (v0[6] + v1[6] + v2[6]) / 3.0;
            }
        }
    c->ntri = w->n;
    c->flux_in = flux_in;
    return FS_OK;
}

/* Where the illumination volume of water triangle tri meets the sample plane at
 * height h: per vertex the plane point in texels (texel = texel sizes) and eq.
 * 2's L_i cos T exp(-c l_q); 0 where a vertex is not above the plane or its
 * refracted ray does not go down. */
static int plane_triangle(const fs_caustics *c, const fs_caustics_setup *s, const light_frame *f, const uint32_t tri[3],
                          double h, const double texel[2], double uv[3][2], double E[3][3])
{
    for (int a = 0; a < 3; a++) {
        const double *v = c->vtx + VTX * tri[a];
        double tu = v[3 + f->up], su = v[f->up] - h;
        if (!(su > 0) || !(tu < -1e-6)) return 0;
        double lam = su / -tu; /* path length in water (t is unit) */
        uv[a][0] = (v[f->ax] + lam * v[3 + f->ax] - s->rect_min[0]) / texel[0];
        uv[a][1] = (v[f->bx] + lam * v[3 + f->bx] - s->rect_min[1]) / texel[1];
        for (int ch = 0; ch < 3; ch++) E[a][ch] = s->light_color[ch] * v[6] * exp(-(double)s->extinction[ch] * lam);
    }
    return 1;
}

/* Whether a plane triangle (in texels) can touch a plane of res^2 texels. */
static int on_plane(const double uv[3][2], int res)
{
    double lo0 = fmin(uv[0][0], fmin(uv[1][0], uv[2][0])), hi0 = fmax(uv[0][0], fmax(uv[1][0], uv[2][0]));
    double lo1 = fmin(uv[0][1], fmin(uv[1][1], uv[2][1])), hi1 = fmax(uv[0][1], fmax(uv[1][1], uv[2][1]));
    return !(hi0 < 0 || hi1 < 0 || lo0 > res || lo1 > res || !isfinite(hi0 - lo0 + hi1 - lo1));
}

/* One plane triangle as caustic_accum.vert.glsl reads it: a corner, two edges,
 * S in texel areas, and the three vertices' intensities. */
static void pack_triangle(float *o, const double uv[3][2], const double E[3][3], double area_texels)
{
    o[0] = (float)uv[0][0];
    o[1] = (float)uv[0][1];
    o[2] = (float)(uv[1][0] - uv[0][0]);
    o[3] = (float)(uv[1][1] - uv[0][1]);
    o[4] = (float)(uv[2][0] - uv[0][0]);
    o[5] = (float)(uv[2][1] - uv[0][1]);
    o[6] = (float)area_texels;
    o[7] = 0;
    for (int a = 0; a < 3; a++) {
        for (int ch = 0; ch < 3; ch++) o[8 + 4 * a + ch] = (float)E[a][ch];
        o[8 + 4 * a + 3] = 0;
    }
}

/* The intersection triangles of the illumination volumes with the sample plane
 * at height h, packed into c->tris; returns how many. */
static size_t cut_plane(fs_caustics *c, const fs_caustics_setup *s, const light_frame *f, const water_tris *w, double h)
{
    const int pres = s->plane_res;
    const double texel[2] = {cell_size(s, 0, pres), cell_size(s, 1, pres)};
    const double texel_area = texel[0] * texel[1];
    size_t m = 0;
    for (size_t t = 0; t < w->n; t++) {
        double uv[3][2], E[3][3];
        if (!plane_triangle(c, s, f, w->idx + 3 * t, h, texel, uv, E) || !on_plane(uv, pres)) continue;
        pack_triangle(c->tris + (size_t)TRI_VEC4 * 4 * m++, uv, E, w->area[t] / texel_area);
    }
    return m;
}

/* Clears sample plane k and accumulates the m triangles in c->tris into it. */
static void accumulate_plane(fs_caustics *c, int k, size_t m)
{
    const float zero[4] = {0, 0, 0, 0};
    glNamedFramebufferTextureLayer(c->plane_fbo, GL_COLOR_ATTACHMENT0, c->plane_tex, 0, k);
    glClearNamedFramebufferfv(c->plane_fbo, GL_COLOR, 0, zero);
    if (!m) return;
    size_t bytes = m * TRI_VEC4 * 4 * sizeof(float);
    if (bytes > c->tri_buf_bytes) {
        if (c->tri_buf) glDeleteBuffers(1, &c->tri_buf);
        glCreateBuffers(1, &c->tri_buf);
        glNamedBufferData(c->tri_buf, (GLsizeiptr)bytes, NULL, GL_STREAM_DRAW);
        c->tri_buf_bytes = bytes;
    }
    glNamedBufferSubData(c->tri_buf, 0, (GLsizeiptr)bytes, c->tris);
    draw_chunked(c->tri_buf, m, TRI_VEC4 * 4 * sizeof(float));
}

/* Step 3 (5.1): each sample plane accumulates, additively, its intersection
 * triangles with the illumination volumes (eq. 2). */
static void sample_planes(fs_caustics *c, const fs_caustics_setup *s, const light_frame *f, const water_tris *w)
{
    const int pres = s->plane_res;
    glBindFramebuffer(GL_FRAMEBUFFER, c->plane_fbo);
    glViewport(0, 0, pres, pres);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(c->prog_accum);
    glUniform1f(glGetUniformLocation(c->prog_accum, "u_res"), (float)pres);
    glUniform1f(glGetUniformLocation(c->prog_accum, "u_sq_min"), SQ_MIN);
    glBindVertexArray(c->vao);
    for (int k = 0; k < s->nplanes; k++) accumulate_plane(c, k, cut_plane(c, s, f, w, s->plane_height[k]));
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* Reads the sample planes back to c->maps; the flux on each from what was deposited. */
static void read_planes(fs_caustics *c, const fs_caustics_setup *s)
{
    const int pres = s->plane_res;
    const double texel_area = cell_size(s, 0, pres) * cell_size(s, 1, pres);
    size_t layer = (size_t)pres * pres;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(c->plane_tex, 0, GL_RGBA, GL_FLOAT, (GLsizei)(layer * s->nplanes * 4 * sizeof(float)), c->maps);
    for (int k = 0; k < FS_CAUSTICS_MAX_PLANES; k++) c->flux_plane[k] = 0;
    for (int k = 0; k < s->nplanes; k++) {
        double sum = 0;
        const float *m = c->maps + 4 * layer * k;
        for (size_t i = 0; i < layer; i++) sum += (double)m[4 * i] + m[4 * i + 1] + m[4 * i + 2];
        c->flux_plane[k] = sum / 3.0 * texel_area;
    }
}

int fs_caustics_run(fs_caustics *c, const fs_caustics_setup *setup, unsigned surfel_ssbo, size_t n)
{
    fs_caustics_setup s;
    int rc = begin_run(c, setup, &s);
    if (rc) return rc;
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    while (glGetError() != GL_NO_ERROR) {}
    light_frame f;
    light_frame_of(&s, &f);

    /* 1. the virtual screen: the water surface's normal and depth maps (eq. 3) */
    splat_screen(c, &s, &f, surfel_ssbo, n);
    normalise_screen(c, s.screen_res);
    /* 2. read back: surface points, refracted light, illumination volumes */
    surface_points(c, &s, &f);
    water_tris w = {0};
    if ((rc = illumination_volumes(c, &s, &w))) return rc;
    /* 3. the sample planes accumulate the volumes' intersection triangles (eq. 2) */
    sample_planes(c, &s, &f, &w);
    free(w.idx);
    free(w.area);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    read_planes(c, &s);
    if (glGetError() != GL_NO_ERROR) return fs_fail(FS_ERR_RUNTIME, "caustics: OpenGL error");
    return FS_OK;
}

unsigned fs_caustics_texture(const fs_caustics *c) { return c->plane_tex; }
const float *fs_caustics_maps(const fs_caustics *c) { return c->maps; }
size_t fs_caustics_triangles(const fs_caustics *c) { return c->ntri; }
double fs_caustics_flux_in(const fs_caustics *c) { return c->flux_in; }
double fs_caustics_flux_plane(const fs_caustics *c, int plane)
{
    return plane >= 0 && plane < c->nplanes ? c->flux_plane[plane] : 0.0;
}
