/* raycast_pca: Xiao, Zhang & Yang, I3D 2017. Spheres splatted with depth
 * replacement give each pixel its ray entry (3.1); a compute pass marches the
 * SPH density iso-surface from there (3.2); a second computes the basic, PCA
 * and blended normals (3.3) and the colour average; a bilateral filter smooths
 * the normal map; thickness is additive sphere splatting (3.4). See README.md. */
#include "fs_error.h"
#include "gl.h"
#include "gl_grid.h"
#include "gl_gbuffer.h"
#include "gl_splat.h"
#include "gl_sprites.h"
#include "gl_stage.h"
#include "method.h"
#include "raycast_pca/pca_normal.h"
#include "shader.h"
#include <stdlib.h>
#include <string.h>

typedef enum { RPCA_BLEND_ADAPTIVE, RPCA_BLEND_FIXED } rpca_blend_kind;
typedef enum { RPCA_THICK_VOLUME, RPCA_THICK_CHORD } rpca_thick_weight;

typedef struct rpca_params {
    double splat_radius, step;
    int max_steps, refine;
    double step_back;
    rpca_normals normals;
    double pca_radius;
    int min_neighbors;
    rpca_blend_kind blend_weight;
    double w, blend_d, blend_k;
    bool normal_filter;
    double filter_sigma, filter_sigma_n;
    bool thickness;
    double thick_radius;
    rpca_thick_weight thick_weight;
    fs_splat_path splat;
    int splat_large_px;
} rpca_params;

#define FIELD(f) FS_PARAM_FIELD(rpca_params, f)
static const fs_param_def params[] = {
    {FIELD(splat_radius), FS_PARAM_FLOAT, 1.0, 0.1, 4.0, NULL, "radius of the entry spheres, multiples of r"},
    {FIELD(step), FS_PARAM_FLOAT, 0.5, 0.01, 4.0, NULL, "ray-march step, multiples of r"},
    {FIELD(max_steps), FS_PARAM_INT, 512, 1, 1e6, NULL, "most density samples per ray before it stops without a hit"},
    {FIELD(refine), FS_PARAM_INT, 12, 0, 40, NULL, "bisection iterations refining a crossing"},
    {FIELD(step_back), FS_PARAM_FLOAT, 8.0, 0.0, 1000.0, NULL,
     "how far an entry inside the fluid steps back, multiples of r"},
    {FIELD(normals), FS_PARAM_ENUM, RPCA_NORMALS_BLEND, 0, 2, "basic|pca|blend", "normal estimate (3.3)"},
    {FIELD(pca_radius), FS_PARAM_FLOAT, 4.0, 0.5, 40.0, NULL, "R of eqs. 2-4 (spiky gradient and PCA), multiples of r"},
    {FIELD(min_neighbors), FS_PARAM_INT, 10, 3, 1e6, NULL, "fewer particles within R: use the basic normal"},
    {FIELD(blend_weight), FS_PARAM_ENUM, 0, 0, 1, "adaptive|fixed", "w of eq. 5: eq. 6 (adaptive) or the constant w"},
    {FIELD(w), FS_PARAM_FLOAT, 0.5, 0.0, 1.0, NULL, "blend weight when blend_weight=fixed"},
    {FIELD(blend_d), FS_PARAM_FLOAT, 10.0, 0.0, 1000.0, NULL, "d of eq. 6"},
    {FIELD(blend_k), FS_PARAM_FLOAT, 0.998, -1.0, 1.0, NULL, "k of eq. 6"},
    {FIELD(normal_filter), FS_PARAM_BOOL, 1, 0, 1, NULL, "bilateral Gaussian filter of the normal map (on/off)"},
    {FIELD(filter_sigma), FS_PARAM_FLOAT, 1.0, 0.01, 20.0, NULL,
     "spatial sigma of the filter, multiples of r at the pixel's depth"},
    {FIELD(filter_sigma_n), FS_PARAM_FLOAT, 0.3, 0.01, 4.0, NULL, "range sigma of the filter on |n_p - n_q|"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL, "additive sphere-splatting thickness pass (on/off)"},
    {FIELD(thick_radius), FS_PARAM_FLOAT, 2.5, 0.1, 8.0, NULL,
     "radius of the thickness spheres, multiples of r (the paper: the entry spheres' 1 r)"},
    {FIELD(thick_weight), FS_PARAM_ENUM, RPCA_THICK_VOLUME, 0, 1, "volume|chord",
     "what a thickness sphere adds: its chord times V / sphere volume (volume) or the bare chord"},
    FS_SPLAT_PARAM_DEFS(rpca_params),
};
#undef FIELD

#define FILTER_MAX_RADIUS 12   /* pixels: bounds the filter's cost at close range */
#define FILTER_DEPTH_GATE 2.0f /* multiples of r */

typedef struct rpca {
    fs_field f;
    rpca_params params;
    unsigned prog_splat, prog_thick, prog_march, prog_normals, prog_filter, vao;
    fs_gl_splat cs;            /* the compute splatter, with splat=compute */
    unsigned tex_hit, tex_raw; /* world hit point; unfiltered view normal */
    int tex_w, tex_h;
    fs_grid own; /* built when the caller's grid is missing or too fine; upload only */
    int has_own, use_color;
    size_t n;
    fs_gl_grid gg;
    fs_gl_target target;
} rpca;

static void free_textures(rpca *s)
{
    if (s->tex_hit) glDeleteTextures(1, &s->tex_hit);
    if (s->tex_raw) glDeleteTextures(1, &s->tex_raw);
    s->tex_hit = s->tex_raw = 0;
    fs_gl_target_destroy(&s->target);
}

static void destroy(void *self)
{
    rpca *s = self;
    if (!s) return;
    unsigned progs[] = {s->prog_splat, s->prog_thick, s->prog_march, s->prog_normals, s->prog_filter};
    for (int i = 0; i < 5; i++)
        if (progs[i]) glDeleteProgram(progs[i]);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    fs_gl_splat_free(&s->cs);
    free_textures(s);
    fs_gl_grid_free(&s->gg);
    if (s->has_own) fs_grid_free(&s->own);
    free(s);
}

/* The sprite passes' programs: the raster's, or the compute splatter's (splat=compute). */
static int build_sprites(rpca *s)
{
    if (s->params.splat != FS_SPLAT_RASTER)
        return fs_gl_splat_init(&s->cs, s->params.splat, FS_SPRITE_XYZW, s->params.splat_large_px);
    const char *spr[] = {"common/sphere_sprite.vert.glsl", "common/sphere_sprite.frag.glsl", NULL};
    if (!(s->prog_splat = fs_program_build(spr, NULL)) || !(s->prog_thick = fs_program_build(spr, "MODE_THICKNESS 1")))
        return FS_ERR_RUNTIME;
    return FS_OK;
}

static void *create(const fs_method_setup *setup)
{
    const fs_field *f = &setup->field;
    if (fs_method_check_field("raycast_pca", f)) return NULL;
    rpca *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "raycast_pca: out of memory");
        return NULL;
    }
    s->f = *f;
    if (fs_method_params_copy("raycast_pca", setup, &s->params, sizeof s->params)) {
        free(s);
        return NULL;
    }
    const char *march[] = {"raycast_pca/march.comp.glsl", NULL};
    const char *normals[] = {"raycast_pca/normals.comp.glsl", NULL};
    const char *filter[] = {"raycast_pca/filter.comp.glsl", NULL};
    if (build_sprites(s) != FS_OK || !(s->prog_march = fs_program_build(march, NULL)) ||
        !(s->prog_normals = fs_program_build(normals, NULL)) || !(s->prog_filter = fs_program_build(filter, NULL))) {
        destroy(s);
        return NULL;
    }
    glCreateVertexArrays(1, &s->vao);
    return s;
}

/* The grid and, when the particles carry colour, the colours as GL buffers. */
static int upload_gl(rpca *s, const fs_particles *p, const fs_grid *g)
{
    int rc = fs_gl_grid_upload(&s->gg, g);
    if (rc || !s->use_color) return rc;
    float *c = malloc((p->n ? p->n : 1) * 4 * sizeof *c);
    if (!c) return fs_fail(FS_ERR_RUNTIME, "raycast_pca: out of memory for %zu colours", p->n);
    for (size_t i = 0; i < p->n; i++) {
        memcpy(c + 4 * i, p->color + 3 * i, 3 * sizeof *c);
        c[4 * i + 3] = 1;
    }
    rc = fs_gl_grid_upload_attr(&s->gg, g, c);
    free(c);
    return rc;
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    rpca *s = self;
    /* The march needs cells of at least H (one ring of cells holds every
     * particle that reaches a point); build one when not given. */
    int rc = fs_grid_fit(g, p, s->f.H, &s->own, &s->has_own, &g);
    if (rc) return rc;
    s->n = p->n;
    s->use_color = p->color != NULL;
    rc = upload_gl(s, p, g);
    /* every pass reads the GL copy: the host grid is not kept (FS_GRID_AT_UPLOAD) */
    if (s->has_own) fs_grid_free(&s->own);
    s->has_own = 0;
    return rc;
}

static void draw_spheres(const rpca *s)
{
    fs_gl_draw_sprites(s->vao, s->gg.pos, s->gg.nchunks, s->gg.chunk, s->n, 4 * sizeof(float));
}

static int ensure_targets(rpca *s, int w, int h)
{
    if (s->target.w == w && s->target.h == h && s->tex_hit) return FS_OK;
    free_textures(s);
    int rc = fs_gl_target_create(&s->target, w, h);
    if (rc) return rc;
    glCreateTextures(GL_TEXTURE_2D, 1, &s->tex_hit);
    glTextureStorage2D(s->tex_hit, 1, GL_RGBA32F, w, h);
    glCreateTextures(GL_TEXTURE_2D, 1, &s->tex_raw);
    glTextureStorage2D(s->tex_raw, 1, GL_RGBA32F, w, h);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate %dx%d images", w, h);
}

static void dispatch(const fs_camera *cam)
{
    glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

/* xiao2017's passes, in the order render() runs them (defined below it). */
static int entry_pass(rpca *s, const fs_camera *cam, float splat_r);
static void march_pass(rpca *s, const fs_camera *cam);
static void normals_pass(rpca *s, const fs_camera *cam);
static void filter_pass(rpca *s, const fs_camera *cam, const float proj[16]);
static int thickness_pass(rpca *s, const fs_camera *cam, fs_stages *t, double start);

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *t)
{
    rpca *s = self;
    if (!s->gg.start) return fs_fail(FS_ERR_RUNTIME, "raycast_pca: render before upload");
    int rc = ensure_targets(s, cam->width, cam->height);
    if (rc) return rc;
    const fs_field *f = &s->f;
    float r = f->r, splat_r = (float)s->params.splat_radius * r;
    float proj[16];
    fs_camera_proj_matrix(cam, proj);

    double t0 = fs_gl_stage_start();
    rc = entry_pass(s, cam, splat_r);
    if (rc) return rc;
    double t1 = fs_gl_stage_end(t, fs_gl_splat_stage(&s->cs, 0), t0);
    march_pass(s, cam);
    double t2 = fs_gl_stage_end(t, "march", t1);
    normals_pass(s, cam);
    double t3 = fs_gl_stage_end(t, "normals", t2);
    filter_pass(s, cam, proj);
    double t4 = fs_gl_stage_end(t, "filter", t3);
    rc = thickness_pass(s, cam, t, t4);
    return rc ? rc : fs_gl_target_read(&s->target, out, NULL, 0, t);
}

/* The particles as the compute splatter reads them: the grid's sorted vec4 positions. */
static fs_sprite_bufs sprites(const rpca *s) { return (fs_sprite_bufs){s->gg.pos, s->gg.nchunks, s->gg.chunk, s->n}; }

static int entry_pass(rpca *s, const fs_camera *cam, float splat_r)
{
    /* 3.1 ray entry: nearest sphere per pixel, hardware depth test (or the
     * compute splatter's atomic minimum: the same depth and normal). */
    fs_gl_target_clear(&s->target);
    if (s->params.splat != FS_SPLAT_RASTER) {
        fs_sprite_bufs sp = sprites(s);
        return fs_gl_splat_depth(&s->cs, &s->target, cam, &sp, splat_r);
    }
    fs_gl_target_begin_surface(&s->target);
    fs_gl_camera_uniforms(s->prog_splat, cam);
    glUniform1f(glGetUniformLocation(s->prog_splat, "u_radius"), splat_r);
    draw_spheres(s);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    return FS_OK;
}

static void march_pass(rpca *s, const fs_camera *cam)
{
    /* 3.2 iso-surface by narrow-band ray casting. */
    const fs_field *f = &s->f;
    const float r = f->r;
    unsigned P = s->prog_march;
    fs_gl_grid_bind(&s->gg, P);
    fs_gl_camera_uniforms(P, cam);
    glUniform1i(glGetUniformLocation(P, "u_kernel"), (int)f->kernel);
    glUniform1f(glGetUniformLocation(P, "u_H"), f->H);
    glUniform1f(glGetUniformLocation(P, "u_V"), f->volume);
    glUniform1f(glGetUniformLocation(P, "u_iso"), f->iso);
    glUniform1f(glGetUniformLocation(P, "u_step"), (float)s->params.step * r);
    glUniform1f(glGetUniformLocation(P, "u_step_back"), (float)s->params.step_back * r);
    glUniform1i(glGetUniformLocation(P, "u_max_steps"), s->params.max_steps);
    glUniform1i(glGetUniformLocation(P, "u_refine"), s->params.refine);
    glBindImageTexture(0, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(1, s->target.tex[FS_TARGET_NORMAL], 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(2, s->tex_hit, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch(cam);
}

static void normals_pass(rpca *s, const fs_camera *cam)
{
    /* 3.3 normals (and colour, eye depth). */
    const fs_field *f = &s->f;
    const float r = f->r;
    unsigned P = s->prog_normals;
    fs_gl_grid_bind(&s->gg, P);
    fs_gl_camera_uniforms(P, cam);
    glUniform1i(glGetUniformLocation(P, "u_kernel"), (int)f->kernel);
    glUniform1f(glGetUniformLocation(P, "u_H"), f->H);
    glUniform1f(glGetUniformLocation(P, "u_R"), (float)s->params.pca_radius * r);
    glUniform1i(glGetUniformLocation(P, "u_mode"), s->params.normals);
    glUniform1i(glGetUniformLocation(P, "u_min_neighbors"), s->params.min_neighbors);
    glUniform1i(glGetUniformLocation(P, "u_fixed_weight"), s->params.blend_weight == RPCA_BLEND_FIXED);
    glUniform1f(glGetUniformLocation(P, "u_w"), (float)s->params.w);
    glUniform1f(glGetUniformLocation(P, "u_blend_d"), (float)s->params.blend_d);
    glUniform1f(glGetUniformLocation(P, "u_blend_k"), (float)s->params.blend_k);
    glUniform1i(glGetUniformLocation(P, "u_use_color"), s->use_color);
    glBindImageTexture(0, s->tex_hit, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(2, s->tex_raw, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(3, s->target.tex[FS_TARGET_COLOR], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch(cam);
}

static void filter_pass(rpca *s, const fs_camera *cam, const float proj[16])
{
    /* Bilateral Gaussian filter of the normal map (a copy when off). */
    const float r = s->f.r;
    unsigned P = s->prog_filter;
    glUseProgram(P);
    glUniform1i(glGetUniformLocation(P, "u_enable"), s->params.normal_filter);
    glUniform1f(glGetUniformLocation(P, "u_focal_px"), proj[5] * 0.5f * (float)cam->height);
    glUniform1f(glGetUniformLocation(P, "u_sigma"), (float)s->params.filter_sigma * r);
    glUniform1f(glGetUniformLocation(P, "u_sigma_n"), (float)s->params.filter_sigma_n);
    glUniform1f(glGetUniformLocation(P, "u_depth_gate"), FILTER_DEPTH_GATE * r);
    glUniform1i(glGetUniformLocation(P, "u_max_radius"), FILTER_MAX_RADIUS);
    glBindImageTexture(0, s->tex_raw, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(2, s->target.tex[FS_TARGET_NORMAL], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch(cam);
}

/* The factor on each thickness sphere's chord: with `volume`, V over the sphere's
 * volume, so that the map integrates to the particles' volume (spheres of r on a
 * 2r lattice fill only pi/6 of it); 1 with `chord`. */
static float rpca_thickness_weight(rpca_thick_weight weight, float V, float radius)
{
    if (weight == RPCA_THICK_CHORD) return 1.0f;
    return V / (4.18879020f * radius * radius * radius);
}

static int thickness_pass(rpca *s, const fs_camera *cam, fs_stages *t, double start)
{
    /* 3.4 thickness: additive sphere splatting (weighted chord lengths). */
    if (!s->params.thickness) return FS_OK;
    float radius = (float)s->params.thick_radius * s->f.r;
    float weight = rpca_thickness_weight(s->params.thick_weight, s->f.volume, radius);
    int rc = FS_OK;
    if (s->params.splat != FS_SPLAT_RASTER) {
        fs_sprite_bufs sp = sprites(s);
        rc = fs_gl_splat_thickness(&s->cs, &s->target, cam, &sp, radius, weight);
    } else {
        fs_gl_target_begin_thickness(&s->target);
        fs_gl_camera_uniforms(s->prog_thick, cam);
        glUniform1f(glGetUniformLocation(s->prog_thick, "u_radius"), radius);
        glUniform1f(glGetUniformLocation(s->prog_thick, "u_thickness_weight"), weight);
        draw_spheres(s);
        fs_gl_target_end_pass();
    }
    fs_gl_stage_end(t, fs_gl_splat_stage(&s->cs, 1), start);
    return rc;
}

/* the particles' colours, interpolated like the normals */
static const fs_aov_def aovs[] = {{FS_AOV_COLOR, 4, 1}};

const fs_method fs_method_raycast_pca = {
    .name = "raycast_pca",
    .cost = 40, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "splatted entry, narrow-band ray casting of the SPH iso-surface, PCA/SPH-gradient blended normals",
    .paper = "xiao2017",
    .needs_gl = 1,
    .grid_use = FS_GRID_AT_UPLOAD,
    .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS) | FS_CNT_BIT(FS_CNT_NEIGHBOURS) | FS_CNT_BIT(FS_CNT_MARCH_SAMPLES) |
        FS_CNT_BIT(FS_CNT_FRAGMENTS) | FS_CNT_BIT(FS_CNT_FILTER_TAPS) | FS_CNT_BIT(FS_CNT_TEXELS) |
        FS_CNT_BIT(FS_CNT_SPLAT_PIXELS) | FS_CNT_BIT(FS_CNT_SPLAT_ATOMICS),
    .aovs = aovs,
    .naovs = sizeof aovs / sizeof *aovs,
    .params = params,
    .nparams = (int)(sizeof params / sizeof *params),
    .params_size = sizeof(rpca_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
};
