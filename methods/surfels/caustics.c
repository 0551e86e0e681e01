/* Caustics from surfels through illumination volumes (iwasaki2006 5.1-5.2);
 * see caustics.h for the steps and the conventions. */
#include "caustics.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_target.h"
#include "shader.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define TRI_VEC4 5           /* vec4s per plane triangle (caustic_accum.vert.glsl) */
#define SQ_MIN 1e-4f         /* texel^2: smaller plane triangles go whole to one texel */
#define W_MIN 1e-4f          /* screen pixels with less summed weight are uncovered */

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
    double *vtx;        /* per screen pixel (VTX): s[3], refracted t[3], cos(theta_i) T, depth d, valid */
    float *tris;        /* plane triangles, TRI_VEC4 vec4 each */
    size_t tris_cap;    /* in triangles */
    size_t ntri;
    double flux_in, flux_plane[FS_CAUSTICS_MAX_PLANES];
    float eps_radii, max_jump_px;
};
#define VTX 9

fs_caustics *fs_caustics_create(void)
{
    fs_caustics *c = calloc(1, sizeof *c);
    if (!c) { fs_fail(FS_ERR_RUNTIME, "out of memory"); return NULL; }
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

void fs_caustics_set_epsilon(fs_caustics *c, float radii) { c->eps_radii = radii; }
void fs_caustics_set_max_jump(fs_caustics *c, float pixels) { c->max_jump_px = pixels; }

static int ensure_screen(fs_caustics *c, int res)
{
    if (c->screen_res == res) return FS_OK;
    free_screen(c);
    size_t n = (size_t)res * res;
    c->screen = malloc(n * 4 * sizeof *c->screen);
    c->vtx = malloc(n * VTX * sizeof *c->vtx);
    if (!c->screen || !c->vtx) { free_screen(c); return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory (screen %d^2)", res); }
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
    if (s->up_axis < 0 || s->up_axis > 2) return fs_fail(FS_ERR_INPUT, "caustics: up_axis %d is not 0, 1 or 2", s->up_axis);
    const float *L = s->light_dir;
    float len = sqrtf(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    if (!(len > 0.0f) || !isfinite(len)) return fs_fail(FS_ERR_INPUT, "caustics: light_dir has no direction");
    if (!(L[s->up_axis] / len > 0.01f))
        return fs_fail(FS_ERR_INPUT, "caustics: the light must come from above (light_dir along up %g)", L[s->up_axis] / len);
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
        else glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, buf, (GLintptr)(first * stride), (GLsizeiptr)(cnt * stride));
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)cnt);
    }
}

/* Step 1: splat the surfels onto the virtual screen, normalise, read back. */
static void screen_pass(fs_caustics *c, const fs_caustics_setup *s, unsigned ssbo, size_t n, const float ea[3],
                        const float eb[3], const float eu[3], float tfar)
{
    int res = s->screen_res;
    float size[2] = {s->rect_max[0] - s->rect_min[0], s->rect_max[1] - s->rect_min[1]};
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    glClearNamedFramebufferfv(c->screen_fbo, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(c->screen_fbo, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(c->screen_fbo, GL_DEPTH, 0, &one);
    glBindFramebuffer(GL_FRAMEBUFFER, c->screen_fbo);
    glViewport(0, 0, res, res);
    glBindVertexArray(c->vao);
    glEnable(GL_DEPTH_TEST);
    for (int pass = 0; pass < 2 && n; pass++) {
        unsigned p = pass ? c->prog_splat : c->prog_depth;
        glUseProgram(p);
        glUniform3fv(glGetUniformLocation(p, "u_light"), 1, s->light_dir);
        glUniform3fv(glGetUniformLocation(p, "u_ea"), 1, ea);
        glUniform3fv(glGetUniformLocation(p, "u_eb"), 1, eb);
        glUniform3fv(glGetUniformLocation(p, "u_eu"), 1, eu);
        glUniform2f(glGetUniformLocation(p, "u_rect_min"), s->rect_min[0], s->rect_min[1]);
        glUniform2f(glGetUniformLocation(p, "u_rect_size"), size[0], size[1]);
        glUniform2f(glGetUniformLocation(p, "u_pix"), size[0] / res, size[1] / res);
        glUniform1f(glGetUniformLocation(p, "u_top"), s->top);
        glUniform1f(glGetUniformLocation(p, "u_tfar"), tfar);
        glUniform1f(glGetUniformLocation(p, "u_eps"), c->eps_radii);
        if (!pass) { /* pass 1: depth only, with the epsilon offset */
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_LESS);
            glDisable(GL_BLEND);
        } else { /* pass 2: blend what passes the depth test, no depth writes */
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDepthMask(GL_FALSE);
            glDepthFunc(GL_LEQUAL);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE);
        }
        draw_chunked(ssbo, n, sizeof(fs_surfel));
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    /* per-pixel normalisation */
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

static int ensure_tris(fs_caustics *c, size_t n)
{
    if (n <= c->tris_cap) return FS_OK;
    float *t = realloc(c->tris, n * TRI_VEC4 * 4 * sizeof *t);
    if (!t) return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory (%zu triangles)", n);
    c->tris = t;
    c->tris_cap = n;
    return FS_OK;
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

int fs_caustics_run(fs_caustics *c, const fs_caustics_setup *setup, unsigned surfel_ssbo, size_t n)
{
    int rc = check_setup(setup);
    if (rc) return rc;
    fs_caustics_setup copy = *setup, *s = &copy; /* light_dir made unit */
    float len = sqrtf(s->light_dir[0] * s->light_dir[0] + s->light_dir[1] * s->light_dir[1] + s->light_dir[2] * s->light_dir[2]);
    for (int k = 0; k < 3; k++) s->light_dir[k] /= len;
    if ((rc = ensure_screen(c, s->screen_res)) || (rc = ensure_planes(c, s->plane_res, s->nplanes))) return rc;
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    while (glGetError() != GL_NO_ERROR) {}

    const int up = s->up_axis, ax = (up + 1) % 3, bx = (up + 2) % 3;
    float ea[3] = {0, 0, 0}, eb[3] = {0, 0, 0}, eu[3] = {0, 0, 0};
    ea[ax] = eb[bx] = eu[up] = 1.0f;
    const double L[3] = {s->light_dir[0], s->light_dir[1], s->light_dir[2]};
    const double Lu = L[up];
    float lowest = s->plane_height[0];
    for (int k = 1; k < s->nplanes; k++) lowest = fminf(lowest, s->plane_height[k]);
    /* depth range: down to twice the deepest plane (depths beyond clamp to 1) */
    float tfar = 2.0f * (s->top - lowest) / (float)Lu;

    /* 1. virtual screen */
    screen_pass(c, s, surfel_ssbo, n, ea, eb, eu, tfar);

    /* 2. per pixel: surface point s, refracted direction t, E = L_i cos T (mean over RGB below) */
    const int res = s->screen_res;
    const double pa = ((double)s->rect_max[0] - s->rect_min[0]) / res, pb = ((double)s->rect_max[1] - s->rect_min[1]) / res;
    const double eta = 1.0 / s->ior;
    const double lmean = (s->light_color[0] + s->light_color[1] + s->light_color[2]) / 3.0;
    for (int j = 0; j < res; j++)
        for (int i = 0; i < res; i++) {
            const float *px = c->screen + 4 * ((size_t)j * res + i);
            double *v = c->vtx + VTX * ((size_t)j * res + i);
            v[8] = 0;
            if (!(px[3] >= 0.0f) || !isfinite(px[0] + px[1] + px[2] + px[3])) continue;
            double P[3];
            P[ax] = s->rect_min[0] + (i + 0.5) * pa;
            P[bx] = s->rect_min[1] + (j + 0.5) * pb;
            P[up] = s->top;
            double nrm[3] = {px[0], px[1], px[2]}, d = px[3];
            double ci = dot3(nrm, L);
            if (ci < 0) ci = 0;
            double st2 = eta * eta * (1.0 - ci * ci), ct = sqrt(1.0 - st2);
            for (int k = 0; k < 3; k++) {
                v[k] = P[k] - d * L[k];                                    /* s */
                v[3 + k] = -eta * L[k] + (eta * ci - ct) * nrm[k];        /* refracted, unit */
            }
            double tr = fresnel_t(ci, ct, s->ior);
            v[6] = ci * tr; /* times L_i per channel */
            v[7] = d;
            v[8] = 1;
        }

    /* 3. illumination volumes: water triangles, cut by each plane */
    const double jump = c->max_jump_px * fmax(pa, pb);
    const size_t maxtri = 2 * (size_t)(res - 1) * (res - 1);
    if ((rc = ensure_tris(c, maxtri))) return rc;
    /* the water triangles that pass, as pixel index triples, and their areas S */
    uint32_t *idx = malloc(maxtri * 3 * sizeof *idx);
    double *area = malloc(maxtri * sizeof *area);
    if (!idx || !area) { free(idx); free(area); return fs_fail(FS_ERR_RUNTIME, "caustics: out of memory"); }
    size_t nt = 0;
    double flux_in = 0;
    for (int j = 0; j + 1 < res; j++)
        for (int i = 0; i + 1 < res; i++) {
            uint32_t q[4] = {(uint32_t)(j * res + i), (uint32_t)(j * res + i + 1), (uint32_t)((j + 1) * res + i),
                             (uint32_t)((j + 1) * res + i + 1)};
            const uint32_t tri[2][3] = {{q[0], q[1], q[2]}, {q[3], q[1], q[2]}};
            for (int h = 0; h < 2; h++) {
                const double *v0 = c->vtx + VTX * tri[h][0], *v1 = c->vtx + VTX * tri[h][1], *v2 = c->vtx + VTX * tri[h][2];
                if (!v0[8] || !v1[8] || !v2[8]) continue;
                double dmin = fmin(v0[7], fmin(v1[7], v2[7])), dmax = fmax(v0[7], fmax(v1[7], v2[7]));
                if (dmax - dmin > jump) continue; /* straddles a depth discontinuity */
                double e1[3], e2[3], cr[3];
                for (int k = 0; k < 3; k++) { e1[k] = v1[k] - v0[k]; e2[k] = v2[k] - v0[k]; }
                cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
                cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
                cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
                double S = 0.5 * sqrt(dot3(cr, cr));
                memcpy(idx + 3 * nt, tri[h], sizeof tri[h]);
                area[nt++] = S;
                flux_in += S * lmean * (v0[6] + v1[6] + v2[6]) / 3.0;
            }
        }
    c->ntri = nt;
    c->flux_in = flux_in;

    const int pres = s->plane_res;
    const double ta = ((double)s->rect_max[0] - s->rect_min[0]) / pres, tb = ((double)s->rect_max[1] - s->rect_min[1]) / pres;
    const double texel_area = ta * tb;
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
    for (int k = 0; k < s->nplanes; k++) {
        const double h = s->plane_height[k];
        size_t m = 0;
        for (size_t t = 0; t < nt; t++) {
            double uv[3][2], E[3][3];
            int ok = 1;
            for (int a = 0; a < 3 && ok; a++) {
                const double *v = c->vtx + VTX * idx[3 * t + a];
                double tu = v[3 + up], su = v[up] - h;
                if (!(su > 0) || !(tu < -1e-6)) { ok = 0; break; }
                double lam = su / -tu; /* path length in water (t is unit) */
                uv[a][0] = (v[ax] + lam * v[3 + ax] - s->rect_min[0]) / ta;
                uv[a][1] = (v[bx] + lam * v[3 + bx] - s->rect_min[1]) / tb;
                for (int ch = 0; ch < 3; ch++) E[a][ch] = s->light_color[ch] * v[6] * exp(-(double)s->extinction[ch] * lam);
            }
            if (!ok) continue;
            double lo0 = fmin(uv[0][0], fmin(uv[1][0], uv[2][0])), hi0 = fmax(uv[0][0], fmax(uv[1][0], uv[2][0]));
            double lo1 = fmin(uv[0][1], fmin(uv[1][1], uv[2][1])), hi1 = fmax(uv[0][1], fmax(uv[1][1], uv[2][1]));
            if (hi0 < 0 || hi1 < 0 || lo0 > pres || lo1 > pres || !isfinite(hi0 - lo0 + hi1 - lo1)) continue;
            float *o = c->tris + (size_t)TRI_VEC4 * 4 * m++;
            o[0] = (float)uv[0][0];
            o[1] = (float)uv[0][1];
            o[2] = (float)(uv[1][0] - uv[0][0]);
            o[3] = (float)(uv[1][1] - uv[0][1]);
            o[4] = (float)(uv[2][0] - uv[0][0]);
            o[5] = (float)(uv[2][1] - uv[0][1]);
            o[6] = (float)(area[t] / texel_area);
            o[7] = 0;
            for (int a = 0; a < 3; a++) {
                for (int ch = 0; ch < 3; ch++) o[8 + 4 * a + ch] = (float)E[a][ch];
                o[8 + 4 * a + 3] = 0;
            }
        }
        const float zero[4] = {0, 0, 0, 0};
        glNamedFramebufferTextureLayer(c->plane_fbo, GL_COLOR_ATTACHMENT0, c->plane_tex, 0, k);
        glClearNamedFramebufferfv(c->plane_fbo, GL_COLOR, 0, zero);
        if (!m) continue;
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
    free(idx);
    free(area);
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);

    /* read back; flux on each plane from what was deposited */
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
const float *fs_caustics_screen(const fs_caustics *c) { return c->screen; }
