/* volume_raycast: Inacio, Nobrega, Carvalho & von Wangenheim 2010. Per frame:
 * the density volume as an R32F 3D texture (section IV-A: single-pass layered
 * splatting, common/gl/layered_splat.c; or, for comparison, iwasaki2006's slice
 * splatting or the exact CPU grid, uploaded), then ray casting (IV-B): the front
 * and back faces of the volume's bounding box rasterised into two float
 * textures give each ray's entry and exit, and a compute pass marches between
 * them (shaders/volume_raycast/march.comp.glsl) writing the G-buffer and the
 * transfer-function image. See README.md. */
#include "density_frame.h"
#include "output_file.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_stage.h"
#include "gl_sprites.h"
#include "gl_gbuffer.h"
#include "method.h"
#include "scene.h"
#include "shader.h"
#include "shading.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the params' order is the builders' (density_frame.h) */
typedef enum {
    BUILD_LAYERED = FS_DENSITY_LAYERED,
    BUILD_SLICE = FS_DENSITY_SLICE,
    BUILD_EXACT = FS_DENSITY_EXACT
} vr_build;
typedef enum { MODE_SURFACE, MODE_TRANSLUCENT } vr_mode;

typedef struct volume_raycast_params {
    int grid_res;
    vr_build build;
    int clusters;
    double step;
    int refine;
    vr_mode mode;
    double opacity, absorption, termination;
    bool thickness;
} volume_raycast_params;

#define FIELD(f) FS_PARAM_FIELD(volume_raycast_params, f)
static const fs_param_def params[] = {
    {FIELD(grid_res), FS_PARAM_INT, 256, 8, 1024, NULL,
     "volume points along the longest axis of the particles' box + H (paper: 128^3 CPU path, 128x512x512 GPU path)"},
    {FIELD(build), FS_PARAM_ENUM, 0, 0, 2, "layered|slice|exact",
     "volume generation: single-pass layered splatting (the paper), iwasaki2006 slice splatting, or the exact CPU grid"},
    {FIELD(clusters), FS_PARAM_INT, 16, 1, 4096, NULL, "height clusters for build=slice"},
    {FIELD(step), FS_PARAM_FLOAT, 0.5, 0.05, 4.0, NULL, "ray-march step, grid spacings"},
    {FIELD(refine), FS_PARAM_INT, 8, 0, 30, NULL, "bisection steps refining the iso crossing"},
    {FIELD(mode), FS_PARAM_ENUM, 0, 0, 1, "surface|translucent",
     "transfer function of the own image: opaque iso-surface, or translucent (Fig. 8) with early ray termination"},
    {FIELD(opacity), FS_PARAM_FLOAT, 0.35, 0.0, 1.0, NULL, "translucent: opacity of the iso-surface at each crossing"},
    {FIELD(absorption), FS_PARAM_FLOAT, 0.01, 0.0, 1.0, NULL, "translucent: opacity of the inside per grid spacing"},
    {FIELD(termination), FS_PARAM_FLOAT, 0.95, 0.5, 1.0, NULL,
     "translucent: early ray termination once the accumulated opacity reaches this"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL,
     "thickness for the shared shading: march the whole ray (off: stop at the surface)"},
};
#undef FIELD

typedef struct vr {
    fs_field f;
    volume_raycast_params params;
    fs_scene scene;
    fs_density_frame fr; /* the frame: its bulk, its neighbour grid */
    float floor_h;
    fs_density_grid dg; /* shape always; data filled by the CPU builds and by export */
    fs_layered_splat *layered;
    fs_slice_splat *slice;
    unsigned tex3d;
    int tex_dim[3];
    unsigned prog_faces, prog_march, vao, box_buf;
    unsigned face_fbo[2], face_tex[2], own_tex; /* front, back */
    fs_gl_target target;
    float *background; /* the scene's background for the own image, per size */
    int bg_w, bg_h;
} vr;

static void destroy(void *self)
{
    vr *s = self;
    if (!s) return;
    fs_layered_splat_destroy(s->layered);
    fs_slice_splat_destroy(s->slice);
    if (s->tex3d) glDeleteTextures(1, &s->tex3d);
    if (s->prog_faces) glDeleteProgram(s->prog_faces);
    if (s->prog_march) glDeleteProgram(s->prog_march);
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    if (s->box_buf) glDeleteBuffers(1, &s->box_buf);
    for (int i = 0; i < 2; i++) {
        if (s->face_fbo[i]) glDeleteFramebuffers(1, &s->face_fbo[i]);
        if (s->face_tex[i]) glDeleteTextures(1, &s->face_tex[i]);
    }
    if (s->own_tex) glDeleteTextures(1, &s->own_tex);
    fs_gl_target_destroy(&s->target);
    fs_density_frame_free(&s->fr);
    fs_density_grid_free(&s->dg);
    free(s->background);
    free(s);
}

/* The 12 triangles of the unit cube, counter-clockwise seen from outside. */
static void box_corners(float out[36 * 4])
{
    int n = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            /* (a, b, axis) is right-handed: a x b = +axis; reverse the order on the low side */
            const int q[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            const int tri[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; k++) {
                int c = side ? tri[k] : tri[5 - k];
                float *v = out + 4 * n++;
                v[axis] = (float)side;
                v[a] = (float)q[c][0];
                v[b] = (float)q[c][1];
                v[3] = 1.0f;
            }
        }
}

static void *create(const fs_method_setup *setup)
{
    vr *s = calloc(1, sizeof *s);
    if (!s || fs_method_setup_take("volume_raycast", setup, &s->f, &s->params, sizeof s->params, &s->scene)) {
        if (!s) fs_fail(FS_ERR_RUNTIME, "volume_raycast: out of memory");
        free(s);
        return NULL;
    }
    const char *faces[] = {"volume_raycast/faces.vert.glsl", "volume_raycast/faces.frag.glsl", NULL};
    const char *march[] = {"volume_raycast/march.comp.glsl", NULL};
    if (!(s->prog_faces = fs_program_build(faces, NULL)) || !(s->prog_march = fs_program_build(march, NULL))) {
        destroy(s);
        return NULL;
    }
    int b = s->params.build;
    if ((b == BUILD_LAYERED && !(s->layered = fs_layered_splat_create())) ||
        (b == BUILD_SLICE && !(s->slice = fs_slice_splat_create()))) {
        destroy(s);
        return NULL;
    }
    float corners[36 * 4];
    box_corners(corners);
    glCreateBuffers(1, &s->box_buf);
    glNamedBufferStorage(s->box_buf, sizeof corners, corners, 0);
    glCreateVertexArrays(1, &s->vao);
    return s;
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    vr *s = self;
    s->floor_h = fs_scene_floor(&s->scene, g);
    /* only the exact build walks the neighbour grid */
    return fs_density_frame_upload(&s->fr, p, g, s->f.H, s->params.build == BUILD_EXACT, "volume_raycast",
                                   "the volume");
}

/* IV-A: the volume texture over the bulk's box grown by H. */
static int build_volume(vr *s, fs_stages *t)
{
    const fs_particles *p = s->fr.p;
    int b = s->params.build;
    fs_density_grid_free(&s->dg);
    int rc = fs_density_grid_init(&s->dg, p->bmin, p->bmax, s->f.H, s->params.grid_res);
    if (rc) return rc;
    if (!s->tex3d || memcmp(s->tex_dim, s->dg.dim, sizeof s->tex_dim)) {
        if (s->tex3d) glDeleteTextures(1, &s->tex3d);
        if (!(s->tex3d = fs_density_texture_create(&s->dg))) return FS_ERR_RUNTIME;
        memcpy(s->tex_dim, s->dg.dim, sizeof s->tex_dim);
    }
    /* a CPU-side build ends in main memory: timed by the wall clock, with its upload */
    fs_density_builder db = {(fs_density_build)b, s->layered,         s->slice,
                             s->scene.up_axis,    s->params.clusters, b == BUILD_LAYERED};
    return fs_density_frame_build(&db, &s->fr, &s->f, &s->dg, s->tex3d, t, "volume", NULL);
}

static int resize(vr *s, int w, int h)
{
    if (s->target.w == w && s->target.h == h) return FS_OK;
    fs_gl_target_destroy(&s->target);
    int rc = fs_gl_target_create(&s->target, w, h);
    if (rc) return rc;
    for (int i = 0; i < 2; i++) {
        if (s->face_fbo[i]) glDeleteFramebuffers(1, &s->face_fbo[i]);
        if (s->face_tex[i]) glDeleteTextures(1, &s->face_tex[i]);
        s->face_tex[i] = fs_gl_texture_2d(GL_RGBA32F, w, h);
        glCreateFramebuffers(1, &s->face_fbo[i]);
        glNamedFramebufferTexture(s->face_fbo[i], GL_COLOR_ATTACHMENT0, s->face_tex[i], 0);
        if (glCheckNamedFramebufferStatus(s->face_fbo[i], GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            return fs_fail(FS_ERR_RUNTIME, "volume_raycast: RGBA32F framebuffer of %dx%d is incomplete", w, h);
    }
    if (s->own_tex) glDeleteTextures(1, &s->own_tex);
    s->own_tex = fs_gl_texture_2d(GL_RGBA32F, w, h);
    return glGetError() == GL_NO_ERROR ? FS_OK
                                       : fs_fail(FS_ERR_RUNTIME, "volume_raycast: cannot allocate %dx%d images", w, h);
}

/* IV-B, first half: front faces, then back faces, of the volume's box. The clip
 * range is widened to hold the whole box (the scene's planes fit the particles
 * only), so no ray loses its entry or exit to clipping. */
static void draw_faces(vr *s, const fs_camera *cam, const float ext[3])
{
    fs_camera c = *cam;
    const float *o = s->dg.origin;
    float far = 0;
    for (int k = 0; k < 8; k++) {
        float d2 = 0;
        for (int a = 0; a < 3; a++) {
            float x = o[a] + ((k >> a) & 1) * ext[a] - cam->eye[a];
            d2 += x * x;
        }
        far = fmaxf(far, sqrtf(d2));
    }
    c.zfar = fmaxf(c.zfar, 1.01f * far);
    c.znear = fminf(c.znear, 0.01f * c.zfar);
    fs_gl_camera_uniforms(s->prog_faces, &c);
    glUniform3fv(glGetUniformLocation(s->prog_faces, "u_box_origin"), 1, o);
    glUniform3fv(glGetUniformLocation(s->prog_faces, "u_box_extent"), 1, ext);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, s->box_buf);
    glBindVertexArray(s->vao);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 2; i++) {
        glBindFramebuffer(GL_FRAMEBUFFER, s->face_fbo[i]);
        glViewport(0, 0, cam->width, cam->height);
        glClearNamedFramebufferfv(s->face_fbo[i], GL_COLOR, 0, zero);
        glCullFace(i == 0 ? GL_BACK : GL_FRONT); /* a convex box: one face per pixel either way */
        glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

static void march(vr *s, const fs_camera *cam, const float ext[3], int own)
{
    unsigned P = s->prog_march;
    const fs_scene *sc = &s->scene;
    fs_gl_camera_uniforms(P, cam);
    glUniform3fv(glGetUniformLocation(P, "u_box_origin"), 1, s->dg.origin);
    glUniform3fv(glGetUniformLocation(P, "u_box_extent"), 1, ext);
    glUniform3f(glGetUniformLocation(P, "u_grid_dim"), (float)s->dg.dim[0], (float)s->dg.dim[1], (float)s->dg.dim[2]);
    glUniform1f(glGetUniformLocation(P, "u_spacing"), s->dg.spacing);
    glUniform1f(glGetUniformLocation(P, "u_step"), (float)s->params.step * s->dg.spacing);
    glUniform1f(glGetUniformLocation(P, "u_iso"), s->f.iso);
    glUniform1i(glGetUniformLocation(P, "u_refine"), s->params.refine);
    glUniform1i(glGetUniformLocation(P, "u_thick"), s->params.thickness);
    /* no own image wanted: the translucent compositing would only cost time */
    glUniform1i(glGetUniformLocation(P, "u_translucent"), own && s->params.mode == MODE_TRANSLUCENT);
    glUniform1i(glGetUniformLocation(P, "u_own_on"), own);
    glUniform1f(glGetUniformLocation(P, "u_opacity"), (float)s->params.opacity);
    glUniform1f(glGetUniformLocation(P, "u_absorption"), (float)s->params.absorption);
    glUniform1f(glGetUniformLocation(P, "u_term"), (float)s->params.termination);
    glUniform3fv(glGetUniformLocation(P, "u_light_dir"), 1, sc->light_dir);
    glUniform3fv(glGetUniformLocation(P, "u_light_color"), 1, sc->light_color);
    glUniform3fv(glGetUniformLocation(P, "u_material"), 1, sc->material_color);
    glUniform1f(glGetUniformLocation(P, "u_ambient"), sc->ambient);
    glUniform1i(glGetUniformLocation(P, "u_grid"), 0);
    glBindTextureUnit(0, s->tex3d);
    glBindImageTexture(0, s->face_tex[0], 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, s->face_tex[1], 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(2, s->target.tex[FS_TARGET_DEPTH], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(3, s->target.tex[FS_TARGET_NORMAL], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(4, s->target.tex[FS_TARGET_THICKNESS], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(5, s->own_tex, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute((unsigned)(cam->width + 7) / 8, (unsigned)(cam->height + 7) / 8, 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

/* The own image (read back into the AOV): the premultiplied transfer-function
 * colour over the scene's background (the shared shading of an empty G-buffer:
 * sky or checker floor), on the CPU. */
static int composite_own(vr *s, const fs_camera *cam, fs_gbuffer *out)
{
    int w = cam->width, h = cam->height;
    size_t n = (size_t)w * h;
    if (!s->background || s->bg_w != w || s->bg_h != h) {
        free(s->background);
        if (!(s->background = malloc(n * 4 * sizeof(float)))) {
            s->bg_w = s->bg_h = 0;
            return fs_fail(FS_ERR_RUNTIME, "volume_raycast: out of memory");
        }
        s->bg_w = w;
        s->bg_h = h;
    }
    /* shaded every frame: it follows the camera (the viewer orbits at a fixed size) */
    fs_gbuffer empty;
    int rc = fs_gbuffer_alloc(&empty, w, h);
    if (rc) return rc;
    fs_shade(&s->scene, cam, &empty, s->floor_h, s->background);
    fs_gbuffer_free(&empty);
    float *own = fs_gbuffer_aov(out, FS_AOV_OWN), *caustics = fs_gbuffer_aov(out, FS_AOV_CAUSTICS);
    for (size_t i = 0; i < n; i++) {
        float *o = own + 4 * i, a = o[3];
        for (int c = 0; c < 3; c++) o[c] += (1.0f - a) * s->background[4 * i + c];
        o[3] = 1.0f;
    }
    if (caustics) memset(caustics, 0, n * sizeof(float));
    return FS_OK;
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *t)
{
    vr *s = self;
    if (!s->fr.p) return fs_fail(FS_ERR_RUNTIME, "volume_raycast: render before upload");
    int rc = build_volume(s, t);
    if (!rc) rc = resize(s, cam->width, cam->height);
    if (rc) return rc;
    float ext[3];
    for (int a = 0; a < 3; a++) ext[a] = (float)(s->dg.dim[a] - 1) * s->dg.spacing;
    float *own = fs_gbuffer_aov(out, FS_AOV_OWN); /* the caller allocates it when it wants the own image */
    double t0 = fs_gl_stage_start();
    draw_faces(s, cam, ext);
    double t1 = fs_gl_stage_end(t, "faces", t0);
    march(s, cam, ext, own != NULL);
    fs_gl_stage_end(t, "march", t1);
    const fs_gl_read own_read = {s->own_tex, 4, own};
    rc = fs_gl_target_read(&s->target, out, &own_read, own ? 1 : 0, t);
    if (!rc && own) {
        double t2 = fs_now_ms();
        rc = composite_own(s, cam, out);
        fs_stages_add(t, "own", fs_now_ms() - t2);
    }
    if (!rc && glGetError() != GL_NO_ERROR) rc = fs_fail(FS_ERR_RUNTIME, "volume_raycast: OpenGL error");
    return rc;
}

/* .vdb: the volume, read back from its texture, as a FloatGrid "density". */
static int export_file(void *self, const char *path, const fs_provenance *prov)
{
    (void)prov; /* its files carry none yet */
    vr *s = self;
    if (!s->fr.p) return fs_fail(FS_ERR_RUNTIME, "volume_raycast: export before upload");
    if (!fs_path_ends_with(path, ".vdb"))
        return fs_fail(FS_ERR_INPUT, "%s: volume_raycast exports .vdb (the density volume)", path);
    int rc = build_volume(s, NULL);
    if (!rc) rc = fs_density_texture_read(s->tex3d, &s->dg);
    return rc ? rc : fs_density_grid_write_vdb(&s->dg, path, "density");
}

/* the transfer function's image; caustics stay 0 (the model has none), declared
 * so its EXRs keep the channels every own-appearance method's have had */
static const fs_aov_def aovs[] = {{FS_AOV_OWN, 4, 0}, {FS_AOV_CAUSTICS, 1, 0}};

const fs_method fs_method_volume_raycast = {
    .name = "volume_raycast",
    .cost = 67, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "single-pass layered density volume (geometry shader), bounding-box ray casting, transfer functions",
    .paper = "inacio2010",
    .appearance = "its transfer function: the opaque iso-surface, or translucent with mode=translucent (inacio2010)",
    .exports = ".vdb density volume (OpenVDB FloatGrid)",
    .needs_gl = 1,
    .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS) | FS_CNT_BIT(FS_CNT_NEIGHBOURS) | FS_CNT_BIT(FS_CNT_MARCH_SAMPLES) |
        FS_CNT_BIT(FS_CNT_FRAGMENTS) | FS_CNT_BIT(FS_CNT_TEXELS),
    .aovs = aovs,
    .naovs = sizeof aovs / sizeof *aovs,
    .params = params,
    .nparams = sizeof params / sizeof *params,
    .params_size = sizeof(volume_raycast_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
    .export_file = export_file,
};
