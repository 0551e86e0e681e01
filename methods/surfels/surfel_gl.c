/* surfels' GL passes: see surfel_gl.h. Accumulation targets are RGBA32F with
 * additive blending; the normalisation and thickness are compute passes writing
 * the shared G-buffer textures (fs_gl_target), read back as every method does. */
#include "surfel_gl.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_gbuffer.h"
#include "density_splat.h"
#include "gl_sprites.h"
#include "gl_stage.h"
#include "shader.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void surfel_gl_destroy(surfel_gl *s)
{
    unsigned progs[] = {s->prog_vis, s->prog_blend, s->prog_norm, s->prog_thick};
    for (int i = 0; i < 4; i++)
        if (progs[i]) glDeleteProgram(progs[i]);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    if (s->buf) glDeleteBuffers(1, &s->buf);
    if (s->fbo) glDeleteFramebuffers(1, &s->fbo);
    if (s->zbuf) glDeleteTextures(1, &s->zbuf);
    for (int i = 0; i < 3; i++)
        if (s->acc[i]) glDeleteTextures(1, &s->acc[i]);
    if (s->own_tex) glDeleteTextures(1, &s->own_tex);
    if (s->grid_tex) glDeleteTextures(1, &s->grid_tex);
    fs_gl_target_destroy(&s->target);
    memset(s, 0, sizeof *s);
}

int surfel_gl_create(surfel_gl *s)
{
    memset(s, 0, sizeof *s);
    const char *spr[] = {"surfels/surfel.vert.glsl", "surfels/surfel.frag.glsl", NULL};
    const char *norm[] = {"surfels/normalize.comp.glsl", NULL};
    const char *thick[] = {"surfels/thickness.comp.glsl", NULL};
    if (!(s->prog_vis = fs_program_build(spr, "MODE_VISIBILITY 1")) ||
        !(s->prog_blend = fs_program_build(spr, "MODE_BLEND 1")) || !(s->prog_norm = fs_program_build(norm, NULL)) ||
        !(s->prog_thick = fs_program_build(thick, NULL))) {
        surfel_gl_destroy(s);
        return FS_ERR_RUNTIME;
    }
    glCreateVertexArrays(1, &s->vao);
    return FS_OK;
}

int surfel_gl_upload(surfel_gl *s, const fs_surfel_set *set)
{
    size_t bytes = set->n * sizeof(fs_surfel);
    if (set->n > fs_gl_ssbo_chunk(sizeof(fs_surfel)))
        return fs_fail(FS_ERR_INPUT, "surfels: %zu surfels exceed one storage buffer; lower grid_res", set->n);
    if (s->buf) glDeleteBuffers(1, &s->buf);
    glCreateBuffers(1, &s->buf);
    glNamedBufferStorage(s->buf, bytes ? (GLsizeiptr)bytes : 32, set->n ? set->s : NULL, 0);
    s->n = set->n;
    return FS_OK;
}

int surfel_gl_upload_grid(surfel_gl *s, const fs_density_grid *g)
{
    if (!s->grid_tex || memcmp(s->grid_dim, g->dim, sizeof g->dim)) {
        if (s->grid_tex) glDeleteTextures(1, &s->grid_tex);
        if (!(s->grid_tex = fs_density_texture_create(g))) return FS_ERR_RUNTIME;
        memcpy(s->grid_dim, g->dim, sizeof g->dim);
    }
    return fs_density_texture_upload(s->grid_tex, g);
}

static int resize(surfel_gl *s, int w, int h)
{
    if (s->target.w == w && s->target.h == h) return FS_OK;
    fs_gl_target_destroy(&s->target);
    if (s->fbo) glDeleteFramebuffers(1, &s->fbo);
    if (s->zbuf) glDeleteTextures(1, &s->zbuf);
    for (int i = 0; i < 3; i++)
        if (s->acc[i]) glDeleteTextures(1, &s->acc[i]);
    if (s->own_tex) glDeleteTextures(1, &s->own_tex);
    int rc = fs_gl_target_create(&s->target, w, h);
    if (rc) return rc;
    s->zbuf = fs_gl_texture_2d(GL_DEPTH_COMPONENT32F, w, h);
    for (int i = 0; i < 3; i++) s->acc[i] = fs_gl_texture_2d(GL_RGBA32F, w, h);
    s->own_tex = fs_gl_texture_2d(GL_RGBA32F, w, h);
    glCreateFramebuffers(1, &s->fbo);
    glNamedFramebufferTexture(s->fbo, GL_DEPTH_ATTACHMENT, s->zbuf, 0);
    GLenum bufs[3];
    for (int i = 0; i < 3; i++) {
        glNamedFramebufferTexture(s->fbo, GL_COLOR_ATTACHMENT0 + i, s->acc[i], 0);
        bufs[i] = GL_COLOR_ATTACHMENT0 + i;
    }
    glNamedFramebufferDrawBuffers(s->fbo, 3, bufs);
    if (glCheckNamedFramebufferStatus(s->fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return fs_fail(FS_ERR_RUNTIME, "surfels: incomplete accumulation framebuffer");
    return FS_OK;
}

static void inverse_view(const fs_camera *cam, float inv[16])
{
    float r[3], u[3], f[3];
    fs_camera_basis(cam, r, u, f);
    /* columns: right, up, -forward, eye */
    float m[16] = {r[0],  r[1],  r[2],  0, u[0],        u[1],        u[2],        0,
                   -f[0], -f[1], -f[2], 0, cam->eye[0], cam->eye[1], cam->eye[2], 1};
    memcpy(inv, m, sizeof m);
}

static void look_uniforms(unsigned prog, const fs_camera *cam, const surfel_look *l)
{
    float inv[16];
    inverse_view(cam, inv);
    glUseProgram(prog);
    glUniformMatrix4fv(glGetUniformLocation(prog, "u_view_inv"), 1, GL_FALSE, inv);
    glUniform3fv(glGetUniformLocation(prog, "u_light_dir"), 1, l->light_dir);
    glUniform3fv(glGetUniformLocation(prog, "u_light_color"), 1, l->light_color);
    glUniform1f(glGetUniformLocation(prog, "u_ambient"), l->ambient);
    glUniform1f(glGetUniformLocation(prog, "u_ior"), l->ior);
    glUniform3fv(glGetUniformLocation(prog, "u_extinction"), 1, l->extinction);
    glUniform3fv(glGetUniformLocation(prog, "u_tint"), 1, l->tint);
    glUniform1i(glGetUniformLocation(prog, "u_up"), l->up_axis);
    glUniform1f(glGetUniformLocation(prog, "u_floor"), l->floor_h);
    glUniform1f(glGetUniformLocation(prog, "u_check"), l->check);
    glUniform1i(glGetUniformLocation(prog, "u_checker"), l->checker);
    glUniform3fv(glGetUniformLocation(prog, "u_eye_world"), 1, cam->eye);
    glUniform1f(glGetUniformLocation(prog, "u_pixel_angle"),
                2.0f * tanf(cam->fovy_deg * (float)M_PI / 360.0f) / (float)cam->height);
    glUniform1i(glGetUniformLocation(prog, "u_has_caustics"), l->caustic_tex != 0);
    glUniform2f(glGetUniformLocation(prog, "u_rect_min"), l->rect_min[0], l->rect_min[1]);
    glUniform2f(glGetUniformLocation(prog, "u_rect_max"), l->rect_max[0], l->rect_max[1]);
    glUniform1i(glGetUniformLocation(prog, "u_caustic_maps"), 1);
    if (l->caustic_tex) glBindTextureUnit(1, l->caustic_tex);
    glUniform1i(glGetUniformLocation(prog, "u_nslices"), l->slice_tex ? l->nslices : 0);
    glUniform1fv(glGetUniformLocation(prog, "u_slice_h"), 9, l->slice_h);
    glUniform1i(glGetUniformLocation(prog, "u_object_slices"), 3);
    if (l->slice_tex) glBindTextureUnit(3, l->slice_tex);
}

static void draw_surfels(const surfel_gl *s)
{
    glBindVertexArray(s->vao);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, s->buf);
    if (s->n) glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, (GLsizei)s->n);
}

/* Pass 1: visibility, depth only, pushed back by epsilon. */
static void visibility_pass(const surfel_gl *s, const fs_camera *cam, float epsilon)
{
    glBindFramebuffer(GL_FRAMEBUFFER, s->fbo);
    glViewport(0, 0, cam->width, cam->height);
    float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    for (int i = 0; i < 3; i++) glClearNamedFramebufferfv(s->fbo, GL_COLOR, i, zero);
    glClearNamedFramebufferfv(s->fbo, GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    fs_gl_camera_uniforms(s->prog_vis, cam);
    glUniform1f(glGetUniformLocation(s->prog_vis, "u_epsilon"), epsilon);
    draw_surfels(s);
}

/* Pass 2: Gaussian-weighted blending of the surfels within epsilon of the front. */
static void blend_pass(const surfel_gl *s, const fs_camera *cam, const surfel_look *look, float gauss)
{
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    fs_gl_camera_uniforms(s->prog_blend, cam);
    glUniform1f(glGetUniformLocation(s->prog_blend, "u_gauss"), gauss);
    look_uniforms(s->prog_blend, cam, look);
    draw_surfels(s);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

/* Pass 3: per-pixel normalisation into the G-buffer and the own image. */
static void normalize_pass(const surfel_gl *s, const fs_camera *cam, const surfel_look *look)
{
    fs_gl_camera_uniforms(s->prog_norm, cam);
    look_uniforms(s->prog_norm, cam, look);
    for (int i = 0; i < 3; i++) glBindImageTexture(i, s->acc[i], 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(3, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(4, s->target.tex[FS_TARGET_NORMAL], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(5, s->own_tex, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

/* Thickness by a march through the density grid, from the surface depth on. */
static void thickness_pass(const surfel_gl *s, const fs_camera *cam, const surfel_draw_opts *o)
{
    fs_gl_camera_uniforms(s->prog_thick, cam);
    float inv[16];
    inverse_view(cam, inv);
    unsigned p = s->prog_thick;
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view_inv"), 1, GL_FALSE, inv);
    glUniform3fv(glGetUniformLocation(p, "u_grid_origin"), 1, o->grid_origin);
    glUniform3f(glGetUniformLocation(p, "u_grid_extent"), (s->grid_dim[0] - 1) * o->grid_spacing,
                (s->grid_dim[1] - 1) * o->grid_spacing, (s->grid_dim[2] - 1) * o->grid_spacing);
    glUniform3f(glGetUniformLocation(p, "u_grid_dim"), (float)s->grid_dim[0], (float)s->grid_dim[1],
                (float)s->grid_dim[2]);
    glUniform1f(glGetUniformLocation(p, "u_step"), o->step);
    glUniform1f(glGetUniformLocation(p, "u_iso"), o->iso);
    glUniform1i(glGetUniformLocation(p, "u_grid"), 2);
    glBindTextureUnit(2, s->grid_tex);
    glBindImageTexture(0, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(1, s->target.tex[FS_TARGET_THICKNESS], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

/* The G-buffer and the own image; the own image's alpha is the caustics layer,
 * split from it on the CPU (stage "own"). */
static int read_back(surfel_gl *s, fs_gbuffer *out, fs_stages *t)
{
    float *own = fs_gbuffer_aov(out, FS_AOV_OWN), *caustics = fs_gbuffer_aov(out, FS_AOV_CAUSTICS);
    const fs_gl_read own_read = {s->own_tex, 4, own};
    int rc = fs_gl_target_read(&s->target, out, &own_read, own ? 1 : 0, t);
    if (rc || !own) return rc;
    double t0 = fs_now_ms();
    for (size_t i = 0, n = (size_t)out->w * out->h; i < n; i++) {
        if (caustics) caustics[i] = own[4 * i + 3];
        own[4 * i + 3] = 1.0f;
    }
    fs_stages_add(t, "own", fs_now_ms() - t0);
    return FS_OK;
}

int surfel_gl_render(surfel_gl *s, const fs_camera *cam, const surfel_look *look, const surfel_draw_opts *o,
                     fs_gbuffer *out, fs_stages *t)
{
    int rc = resize(s, cam->width, cam->height);
    if (rc) return rc;
    double t0 = fs_gl_stage_start();
    visibility_pass(s, cam, o->epsilon);
    double t1 = fs_gl_stage_end(t, "visibility", t0);
    blend_pass(s, cam, look, o->gauss);
    double t2 = fs_gl_stage_end(t, "blend", t1);
    normalize_pass(s, cam, look);
    double t3 = fs_gl_stage_end(t, "normalize", t2);
    float zero = 0;
    glClearTexImage(s->target.tex[FS_TARGET_THICKNESS], 0, GL_RED, GL_FLOAT, &zero);
    if (o->thickness && s->grid_tex) {
        thickness_pass(s, cam, o);
        fs_gl_stage_end(t, "thickness", t3);
    }
    return read_back(s, out, t);
}
