/* aniso_ssf: Xu et al. 2022. Screen-space fluid rendering with WPCA-anisotropic
 * ellipsoid point sprites (4.2-4.3; plain spheres when anisotropy is off), one
 * of four depth filters (Gaussian, bilateral, curvature flow, narrow-range),
 * normals from the filtered depth, thickness by additive splatting. README.md
 * maps the paper's parameters onto fluidsurf's units. */
#include "aniso_ssf/aniso_gl.h"
#include "aniso_params.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_gbuffer.h"
#include "gl_grid.h"
#include "gl_splat.h"
#include "gl_sprites.h"
#include "gl_stage.h"
#include "method.h"
#include "shader.h"
#include <stdlib.h>
#include <string.h>

typedef enum { F_NONE, F_GAUSSIAN, F_BILATERAL, F_CURVATURE, F_NARROW } ssf_filter;

typedef struct aniso_ssf_params {
    bool anisotropy;
    ssf_filter filter;
    int iterations;
    double sigma, sigma_depth, range, narrow_threshold, narrow_clamp;
    int max_radius_px;
    fs_aniso_param_values aniso;
    bool thickness;
    fs_splat_path splat;
    int splat_large_px;
} aniso_ssf_params;

#define FIELD(f) FS_PARAM_FIELD(aniso_ssf_params, f)
static const fs_param_def params[] = {
    {FIELD(anisotropy), FS_PARAM_BOOL, 1, 0, 1, NULL, "WPCA ellipsoid sprites (on) or spheres of radius r (off)"},
    {FIELD(filter), FS_PARAM_ENUM, F_NARROW, 0, 4, "none|gaussian|bilateral|curvature|narrow", "depth filter"},
    {FIELD(iterations), FS_PARAM_INT, 0, 0, 1000, NULL, "filter iterations; 0: the paper's (2, curvature flow 80)"},
    {FIELD(sigma), FS_PARAM_FLOAT, 1.5, 0.05, 20.0, NULL,
     "spatial Gaussian sigma of every filter kernel, multiples of r"},
    {FIELD(sigma_depth), FS_PARAM_FLOAT, 1.0, 0.01, 100.0, NULL, "bilateral range sigma on depth, multiples of r"},
    {FIELD(range), FS_PARAM_FLOAT, 2.0, 0.01, 100.0, NULL,
     "curvature flow: depth jump treated as a discontinuity, multiples of r"},
    {FIELD(narrow_threshold), FS_PARAM_FLOAT, 10.0, 0.01, 1000.0, NULL,
     "narrow-range filter: depth range delta around the pixel (grows with kept samples), multiples of r"},
    {FIELD(narrow_clamp), FS_PARAM_FLOAT, 1.0, 0.0, 100.0, NULL,
     "narrow-range filter: samples behind the range (or empty) count as z + mu, mu in multiples of r"},
    {FIELD(max_radius_px), FS_PARAM_INT, 32, 1, 256, NULL, "largest filter radius in pixels"},
    FS_ANISO_PARAM_DEFS(aniso_ssf_params),
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL, "additive splatting thickness pass (on/off)"},
    FS_SPLAT_PARAM_DEFS(aniso_ssf_params),
};
#undef FIELD

typedef struct assf {
    fs_field f;
    aniso_ssf_params params;
    fs_aniso_params ap;
    unsigned prog_sph, prog_sph_thick, prog_ell, prog_ell_thick, vao;
    unsigned prog_gauss, prog_bilat, prog_curv, prog_narrow, prog_normals;
    fs_gl_splat cs;  /* the compute splatter, with splat=compute */
    unsigned tex[2]; /* ping-pong depth */
    fs_grid own;
    int has_own;
    size_t n;
    fs_gl_grid gg;
    aniso_gl an;
    fs_gl_target target;
} assf;

static void free_textures(assf *s)
{
    if (s->tex[0]) glDeleteTextures(2, s->tex);
    s->tex[0] = s->tex[1] = 0;
    fs_gl_target_destroy(&s->target);
}

static void destroy(void *self)
{
    assf *s = self;
    if (!s) return;
    unsigned progs[] = {s->prog_sph,   s->prog_sph_thick, s->prog_ell,    s->prog_ell_thick, s->prog_gauss,
                        s->prog_bilat, s->prog_curv,      s->prog_narrow, s->prog_normals};
    for (size_t i = 0; i < sizeof progs / sizeof *progs; i++)
        if (progs[i]) glDeleteProgram(progs[i]);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    fs_gl_splat_free(&s->cs);
    free_textures(s);
    aniso_gl_free(&s->an);
    fs_gl_grid_free(&s->gg);
    if (s->has_own) fs_grid_free(&s->own);
    free(s);
}

static unsigned comp(const char *name)
{
    const char *st[] = {name, NULL};
    return fs_program_build(st, NULL);
}

/* The sprite passes' programs: the raster's spheres and ellipsoids, or the
 * compute splatter's for the one shape the parameters pick (splat=compute). */
static int build_sprites(assf *s)
{
    if (s->params.splat != FS_SPLAT_RASTER)
        return fs_gl_splat_init(&s->cs, s->params.splat, s->params.anisotropy ? FS_SPRITE_ELLIPSOID : FS_SPRITE_XYZW,
                                s->params.splat_large_px);
    const char *sph[] = {"common/sphere_sprite.vert.glsl", "common/sphere_sprite.frag.glsl", NULL};
    const char *ell[] = {"aniso_ssf/ellipsoid.vert.glsl", "aniso_ssf/ellipsoid.frag.glsl", NULL};
    if (!(s->prog_sph = fs_program_build(sph, NULL)) ||
        !(s->prog_sph_thick = fs_program_build(sph, "MODE_THICKNESS 1")) ||
        !(s->prog_ell = fs_program_build(ell, NULL)) ||
        !(s->prog_ell_thick = fs_program_build(ell, "MODE_THICKNESS 1")))
        return FS_ERR_RUNTIME;
    return FS_OK;
}

static void *create(const fs_method_setup *setup)
{
    const fs_field *f = &setup->field;
    if (!(f->r > 0) || !(f->H > 0)) {
        fs_fail(FS_ERR_INPUT, "aniso_ssf: r %g and H %g must be positive", f->r, f->H);
        return NULL;
    }
    assf *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "aniso_ssf: out of memory");
        return NULL;
    }
    s->f = *f;
    if (fs_method_params_copy("aniso_ssf", setup, &s->params, sizeof s->params)) {
        free(s);
        return NULL;
    }
    fs_aniso_params_set(&s->ap, &s->params.aniso, f->kernel, f->r);
    if (build_sprites(s) != FS_OK || !(s->prog_gauss = comp("aniso_ssf/gaussian.comp.glsl")) ||
        !(s->prog_bilat = comp("aniso_ssf/bilateral.comp.glsl")) ||
        !(s->prog_curv = comp("aniso_ssf/curvature.comp.glsl")) ||
        !(s->prog_narrow = comp("aniso_ssf/narrow.comp.glsl")) ||
        !(s->prog_normals = comp("aniso_ssf/normals.comp.glsl")) || aniso_gl_init(&s->an) != FS_OK) {
        destroy(s);
        return NULL;
    }
    glCreateVertexArrays(1, &s->vao);
    return s;
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    assf *s = self;
    if (s->has_own) {
        fs_grid_free(&s->own);
        s->has_own = 0;
    }
    if (!g || g->n != p->n || !(g->cell >= s->f.H)) {
        int rc = fs_grid_build(&s->own, p, s->f.H);
        if (rc) return rc;
        s->has_own = 1;
        g = &s->own;
    }
    s->n = p->n;
    int rc = fs_gl_grid_upload(&s->gg, g);
    /* every pass reads the GL copy: the host grid is not kept (FS_GRID_AT_UPLOAD) */
    if (s->has_own) fs_grid_free(&s->own);
    s->has_own = 0;
    return rc;
}

/* Camera uniforms plus the splat radius. */
static void camera_uniforms(unsigned prog, const fs_camera *cam, float radius)
{
    fs_gl_camera_uniforms(prog, cam);
    glUniform1f(glGetUniformLocation(prog, "u_radius"), radius);
}

static void draw_sprites(const assf *s, int aniso)
{
    if (aniso) fs_gl_draw_sprites(s->vao, s->an.bufs, s->an.nbufs, s->an.chunk, s->n, 12 * sizeof(float));
    else fs_gl_draw_sprites(s->vao, s->gg.pos, s->gg.nchunks, s->gg.chunk, s->n, 4 * sizeof(float));
}

/* The sprites as the compute splatter reads them: ellipsoids (3 vec4 each) or
 * the grid's sorted vec4 positions. */
static fs_sprite_bufs sprites(const assf *s)
{
    if (s->params.anisotropy) return (fs_sprite_bufs){s->an.bufs, s->an.nbufs, s->an.chunk, s->n};
    return (fs_sprite_bufs){s->gg.pos, s->gg.nchunks, s->gg.chunk, s->n};
}

/* The depth splat (4.3) into the cleared target: eye depth and normal of the
 * nearest sprite, on the raster or the compute splatter. */
static int splat_pass(assf *s, const fs_camera *cam)
{
    int aniso = s->params.anisotropy;
    fs_gl_target_clear(&s->target);
    if (s->params.splat != FS_SPLAT_RASTER) {
        fs_sprite_bufs sp = sprites(s);
        return fs_gl_splat_depth(&s->cs, &s->target, cam, &sp, s->f.r);
    }
    fs_gl_target_begin_surface(&s->target);
    camera_uniforms(aniso ? s->prog_ell : s->prog_sph, cam, s->f.r);
    draw_sprites(s, aniso);
    fs_gl_target_end_pass();
    glDisable(GL_DEPTH_TEST);
    return FS_OK;
}

/* The additive thickness splat: the sum of the sprites' chords per pixel. */
static int thickness_pass(assf *s, const fs_camera *cam)
{
    int aniso = s->params.anisotropy;
    if (s->params.splat != FS_SPLAT_RASTER) {
        fs_sprite_bufs sp = sprites(s);
        return fs_gl_splat_thickness(&s->cs, &s->target, cam, &sp, s->f.r, 1.0f);
    }
    fs_gl_target_begin_thickness(&s->target);
    camera_uniforms(aniso ? s->prog_ell_thick : s->prog_sph_thick, cam, s->f.r);
    draw_sprites(s, aniso);
    fs_gl_target_end_pass();
    return FS_OK;
}

static int ensure_targets(assf *s, int w, int h)
{
    if (s->target.w == w && s->target.h == h && s->tex[0]) return FS_OK;
    free_textures(s);
    int rc = fs_gl_target_create(&s->target, w, h);
    if (rc) return rc;
    glCreateTextures(GL_TEXTURE_2D, 2, s->tex);
    for (int i = 0; i < 2; i++) glTextureStorage2D(s->tex[i], 1, GL_R32F, w, h);
    return glGetError() == GL_NO_ERROR ? FS_OK : fs_fail(FS_ERR_RUNTIME, "OpenGL: cannot allocate %dx%d images", w, h);
}

/* One filter pass src -> dst with the shared kernel-size uniforms. */
static void pass(const assf *s, unsigned prog, unsigned src, unsigned dst, const fs_camera *cam, float focal_px)
{
    glUseProgram(prog);
    glUniform1f(glGetUniformLocation(prog, "u_focal_px"), focal_px);
    glUniform1f(glGetUniformLocation(prog, "u_sigma"), (float)s->params.sigma * s->f.r);
    glUniform1i(glGetUniformLocation(prog, "u_max_radius"), s->params.max_radius_px);
    glBindImageTexture(0, src, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(1, dst, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

/* Runs the chosen filter; returns the texture holding the filtered depth. */
static unsigned run_filter(assf *s, const fs_camera *cam, float focal_px)
{
    int filter = s->params.filter, iters = s->params.iterations;
    if (iters == 0) iters = filter == F_CURVATURE ? 80 : 2;
    unsigned cur = s->target.tex[FS_TARGET_DEPTH];
    if (filter == F_NONE) return cur;
    int k = 0; /* next ping-pong texture */
#define STEP(prog)                                                                                                     \
    do {                                                                                                               \
        pass(s, prog, cur, s->tex[k], cam, focal_px);                                                                  \
        cur = s->tex[k];                                                                                               \
        k ^= 1;                                                                                                        \
    } while (0)
    float range = (float)s->params.range * s->f.r;
    for (int it = 0; it < iters; it++) {
        switch (filter) {
        case F_GAUSSIAN:
            glUseProgram(s->prog_gauss);
            glUniform1i(glGetUniformLocation(s->prog_gauss, "u_axis"), 0);
            STEP(s->prog_gauss);
            glUseProgram(s->prog_gauss);
            glUniform1i(glGetUniformLocation(s->prog_gauss, "u_axis"), 1);
            STEP(s->prog_gauss);
            break;
        case F_BILATERAL:
            glUseProgram(s->prog_bilat);
            glUniform1f(glGetUniformLocation(s->prog_bilat, "u_sigma_z"), (float)s->params.sigma_depth * s->f.r);
            STEP(s->prog_bilat);
            break;
        case F_CURVATURE:
            glUseProgram(s->prog_curv);
            glUniform1f(glGetUniformLocation(s->prog_curv, "u_range"), range);
            glUniform1f(glGetUniformLocation(s->prog_curv, "u_dt_scale"), 1.0f);
            STEP(s->prog_curv);
            break;
        default: /* narrow-range: 1D passes each iteration */
            glUseProgram(s->prog_narrow);
            glUniform1f(glGetUniformLocation(s->prog_narrow, "u_threshold"),
                        (float)s->params.narrow_threshold * s->f.r);
            glUniform1f(glGetUniformLocation(s->prog_narrow, "u_clamp"), (float)s->params.narrow_clamp * s->f.r);
            glUniform1i(glGetUniformLocation(s->prog_narrow, "u_axis"), 0);
            STEP(s->prog_narrow);
            glUseProgram(s->prog_narrow);
            glUniform1i(glGetUniformLocation(s->prog_narrow, "u_axis"), 1);
            STEP(s->prog_narrow);
        }
    }
    if (filter == F_NARROW) { /* then one 2D pass */
        glUseProgram(s->prog_narrow);
        glUniform1i(glGetUniformLocation(s->prog_narrow, "u_axis"), 2);
        STEP(s->prog_narrow);
    }
#undef STEP
    return cur;
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *t)
{
    assf *s = self;
    if (!s->gg.start) return fs_fail(FS_ERR_RUNTIME, "aniso_ssf: render before upload");
    int rc = ensure_targets(s, cam->width, cam->height);
    if (rc) return rc;
    int aniso = s->params.anisotropy;
    float proj[16];
    fs_camera_proj_matrix(cam, proj);
    float focal_px = proj[5] * 0.5f * (float)cam->height;

    double t0 = fs_gl_stage_start(), t1 = t0;
    if (aniso) {
        rc = aniso_gl_run(&s->an, &s->gg, s->n, &s->ap);
        if (rc) return rc;
        t1 = fs_gl_stage_end(t, "anisotropy", t0);
    }

    rc = splat_pass(s, cam);
    if (rc) return rc;
    double t2 = fs_gl_stage_end(t, fs_gl_splat_stage(&s->cs, 0), t1);

    unsigned depth = run_filter(s, cam, focal_px);
    double t3 = fs_gl_stage_end(t, "filter", t2);

    unsigned P = s->prog_normals;
    glUseProgram(P);
    glUniformMatrix4fv(glGetUniformLocation(P, "u_proj"), 1, GL_FALSE, proj);
    glUniform1i(glGetUniformLocation(P, "u_write_depth"), depth != s->target.tex[FS_TARGET_DEPTH]);
    glBindImageTexture(0, depth, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(1, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(2, s->target.tex[FS_TARGET_NORMAL], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    double t4 = fs_gl_stage_end(t, "normals", t3);

    if (s->params.thickness) {
        rc = thickness_pass(s, cam);
        fs_gl_stage_end(t, fs_gl_splat_stage(&s->cs, 1), t4);
    }
    return rc ? rc : fs_gl_target_read(&s->target, out, NULL, 0, t);
}

const fs_method fs_method_aniso_ssf = {
    .name = "aniso_ssf",
    .cost = 7, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "screen-space fluid: WPCA ellipsoid (or sphere) sprites, Gaussian/bilateral/curvature/narrow-range "
                   "depth filter, normals from depth",
    .paper = "xu2022",
    .needs_gl = 1,
    .grid_use = FS_GRID_AT_UPLOAD,
    .counters = FS_CNT_BIT(FS_CNT_NEIGHBOURS) | FS_CNT_BIT(FS_CNT_FRAGMENTS) | FS_CNT_BIT(FS_CNT_FILTER_TAPS) |
        FS_CNT_BIT(FS_CNT_TEXELS) | FS_CNT_BIT(FS_CNT_SPLAT_PIXELS) | FS_CNT_BIT(FS_CNT_SPLAT_ATOMICS),
    .params = params,
    .nparams = (int)(sizeof params / sizeof *params),
    .params_size = sizeof(aniso_ssf_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
};
