/* spheres: every particle drawn as an opaque sphere of radius r (sprite quads
 * with exact ray-sphere depth replacement) — the baseline of inacio2010, Table II.
 * Thickness is the sum of the view ray's chords through all spheres. */
#include "fs_error.h"
#include "gl.h"
#include "gl_stage.h"
#include "gl_gbuffer.h"
#include "gl_splat.h"
#include "gl_sprites.h"
#include "method.h"
#include "shader.h"
#include <stdlib.h>
#include <string.h>

#define MAX_CHUNKS 16

typedef struct spheres_params {
    double radius_scale;
    bool thickness;
    fs_splat_path splat;
    int splat_large_px;
} spheres_params;

#define FIELD(f) FS_PARAM_FIELD(spheres_params, f)
static const fs_param_def params[] = {
    {FIELD(radius_scale), FS_PARAM_FLOAT, 1.0, 0.05, 4.0, NULL, "sphere radius in multiples of the particle radius r"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL, "additive chord-length thickness pass (on/off)"},
    FS_SPLAT_PARAM_DEFS(spheres_params),
};
#undef FIELD

typedef struct spheres {
    fs_field field;
    float radius;
    int thickness;
    fs_splat_path path;
    fs_gl_splat cs; /* the compute splatter, when path is not raster */
    unsigned prog_surface, prog_thickness, vao;
    unsigned bufs[MAX_CHUNKS];
    size_t chunk, n; /* particles per buffer, in all */
    int nbufs;
    fs_gl_target target;
} spheres;

static void destroy(void *self)
{
    spheres *s = self;
    if (!s) return;
    if (s->prog_surface) glDeleteProgram(s->prog_surface);
    if (s->prog_thickness) glDeleteProgram(s->prog_thickness);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    if (s->nbufs) glDeleteBuffers(s->nbufs, s->bufs);
    fs_gl_splat_free(&s->cs);
    fs_gl_target_destroy(&s->target);
    free(s);
}

static void *create(const fs_method_setup *setup)
{
    spheres_params p;
    if (fs_method_params_copy("spheres", setup, &p, sizeof p)) return NULL;
    spheres *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "out of memory");
        return NULL;
    }
    s->field = setup->field;
    s->radius = (float)p.radius_scale * setup->field.r;
    s->thickness = p.thickness;
    s->path = p.splat;
    const char *surf[] = {"common/sphere_sprite.vert.glsl", "common/sphere_sprite.frag.glsl", NULL};
    int ok = s->path == FS_SPLAT_RASTER ? (s->prog_surface = fs_program_build(surf, "POS_PACKED3 1")) &&
            (s->prog_thickness = fs_program_build(surf, "POS_PACKED3 1\nMODE_THICKNESS 1"))
                                        : fs_gl_splat_init(&s->cs, s->path, FS_SPRITE_XYZ, p.splat_large_px) == FS_OK;
    if (!ok) {
        destroy(s);
        return NULL;
    }
    glCreateVertexArrays(1, &s->vao);
    return s;
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    (void)g;
    spheres *s = self;
    if (s->nbufs) glDeleteBuffers(s->nbufs, s->bufs);
    s->nbufs = 0;
    /* float triples: the shader reads exactly the positions, a quarter less than vec4 */
    size_t chunk = fs_gl_ssbo_chunk(3 * sizeof(float));
    int nb = fs_gl_upload_xyz(p->x, p->y, p->z, p->n, chunk, s->bufs, MAX_CHUNKS);
    if (nb < 0) return -nb;
    s->nbufs = nb;
    s->chunk = chunk;
    s->n = p->n;
    return FS_OK;
}

static void set_uniforms(unsigned prog, const fs_camera *cam, float radius)
{
    fs_gl_camera_uniforms(prog, cam);
    glUniform1f(glGetUniformLocation(prog, "u_radius"), radius);
}

static void draw(const spheres *s) { fs_gl_draw_sprites(s->vao, s->bufs, s->nbufs, s->chunk, s->n, 3 * sizeof(float)); }

/* The depth and thickness passes on the compute splatter (gl_splat.h). */
static int render_compute(spheres *s, const fs_camera *cam, fs_stages *t, double t0)
{
    fs_sprite_bufs sp = {s->bufs, s->nbufs, s->chunk, s->n};
    int rc = fs_gl_splat_depth(&s->cs, &s->target, cam, &sp, s->radius);
    double t1 = fs_gl_stage_end(t, fs_gl_splat_stage(&s->cs, 0), t0);
    if (!rc && s->thickness) {
        rc = fs_gl_splat_thickness(&s->cs, &s->target, cam, &sp, s->radius, 1.0f);
        fs_gl_stage_end(t, fs_gl_splat_stage(&s->cs, 1), t1);
    }
    return rc;
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *t)
{
    spheres *s = self;
    if (s->target.w != cam->width || s->target.h != cam->height) {
        fs_gl_target_destroy(&s->target);
        int rc = fs_gl_target_create(&s->target, cam->width, cam->height);
        if (rc) return rc;
    }
    double t0 = fs_gl_stage_start();
    fs_gl_target_clear(&s->target);
    if (s->path != FS_SPLAT_RASTER) {
        int rc = render_compute(s, cam, t, t0);
        return rc ? rc : fs_gl_target_read(&s->target, out, NULL, 0, t);
    }
    fs_gl_target_begin_surface(&s->target);
    set_uniforms(s->prog_surface, cam, s->radius);
    draw(s);
    double t1 = fs_gl_stage_end(t, "splat", t0);
    if (s->thickness) {
        fs_gl_target_begin_thickness(&s->target);
        set_uniforms(s->prog_thickness, cam, s->radius);
        draw(s);
        fs_gl_stage_end(t, "thickness", t1);
    }
    fs_gl_target_end_pass();
    return fs_gl_target_read(&s->target, out, NULL, 0, t);
}

const fs_method fs_method_spheres = {
    .name = "spheres",
    .cost = 1, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "particles as opaque spheres of radius r (sprites with exact depth replacement)",
    .paper = "inacio2010 (Table II baseline)",
    .needs_gl = 1,
    .grid_use = FS_GRID_UNUSED, /* the sprites are drawn in the particles' order */
    .counters = FS_CNT_BIT(FS_CNT_FRAGMENTS) | FS_CNT_BIT(FS_CNT_TEXELS) | FS_CNT_BIT(FS_CNT_SPLAT_PIXELS) |
        FS_CNT_BIT(FS_CNT_SPLAT_ATOMICS),
    .params = params,
    .nparams = sizeof params / sizeof *params,
    .params_size = sizeof(spheres_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
};
