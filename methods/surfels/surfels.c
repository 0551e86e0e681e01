/* surfels: Iwasaki, Dobashi, Yoshimoto & Nishita 2006. Per frame: the density
 * grid by slice splatting (section 4, common/gl/slice_splat.c), surfels on its
 * iso-surface (4.2, surfel_extract.c), caustics through illumination volumes
 * (5.1-5.2, caustics.c), then three-pass surfel splatting with reflection,
 * refraction and the caustics (5.3, surfel_gl.c). See README.md. */
#include "caustics.h"
#include "output_file.h"
#include "density_frame.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_stage.h"
#include "gl_target.h"
#include "method.h"
#include "object_slices.h"
#include "scene.h"
#include "surfel_extract.h"
#include "surfel_gl.h"
#include "surfel_ply.h"
#include "vec3.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef enum { GRID_SPLAT, GRID_EXACT } surfels_grid_build;
typedef enum { OBJECT_NONE, OBJECT_BOX } surfels_object;

typedef struct surfels_params {
    int grid_res;
    surfels_grid_build grid_build;
    int clusters;
    double radius_scale, gap, epsilon, gauss;
    bool caustics;
    int caustic_screen, caustic_map;
    bool thickness;
    surfels_object object;
    int object_slices;
} surfels_params;

#define FIELD(f) FS_PARAM_FIELD(surfels_params, f)
static const fs_param_def params[] = {
    {FIELD(grid_res), FS_PARAM_INT, 256, 8, 1024, NULL,
     "density grid points along the longest axis of the particles' box (paper: 256)"},
    {FIELD(grid_build), FS_PARAM_ENUM, 0, 0, 1, "splat|exact",
     "density grid: slice splatting on GL (the paper) or the exact CPU sum"},
    {FIELD(clusters), FS_PARAM_INT, 16, 1, 4096, NULL, "N_c, height clusters of particles for the slice splatting"},
    {FIELD(radius_scale), FS_PARAM_FLOAT, 1.0, 0.1, 8.0, NULL, "surfel radius R in grid spacings"},
    {FIELD(gap), FS_PARAM_FLOAT, 0.75, 0.0, 4.0, NULL,
     "gap filling: a cell whose crossings spread wider than this (grid spacings) gets a surfel at their centre; 0 = off"},
    {FIELD(epsilon), FS_PARAM_FLOAT, 0.5, 0.0, 16.0, NULL, "visibility-pass depth offset epsilon, multiples of r"},
    {FIELD(gauss), FS_PARAM_FLOAT, 2.0, 0.0, 20.0, NULL,
     "surfel blending weight g(t) = exp(-gauss t^2), t = distance / R"},
    {FIELD(caustics), FS_PARAM_BOOL, 1, 0, 1, NULL, "caustics from illumination volumes (on/off)"},
    {FIELD(caustic_screen), FS_PARAM_INT, 128, 8, 2048, NULL,
     "virtual screen pixels per side for the illumination volumes (paper: 128)"},
    {FIELD(caustic_map), FS_PARAM_INT, 256, 8, 4096, NULL, "sample plane texels per side"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL,
     "thickness for the shared shading by a march through the grid (on/off)"},
    {FIELD(object), FS_PARAM_ENUM, 1, 0, 1, "none|box",
     "an opaque box under the water, seen by refraction mapping of sliced object images (own appearance only)"},
    {FIELD(object_slices), FS_PARAM_INT, 3, 1, OBJECT_MAX_SLICES, NULL,
     "slabs (sample planes - 1) the object is sliced into"},
};
#undef FIELD

/* The box: centred under the particles' horizontal box, three tenths of its smaller
 * side wide, as tall as the particles' mean height above the floor (about half
 * the water's depth), terracotta so it stands out from the floor. */
#define OBJECT_WIDTH 0.3f
static const float OBJECT_ALBEDO[3] = {0.70f, 0.32f, 0.16f};

typedef struct surfels {
    fs_field f;
    surfels_params params;
    fs_scene scene;
    fs_density_frame fr; /* the frame: its bulk, its neighbour grid */
    float floor_h;
    fs_density_grid dg;
    fs_slice_splat *splat;
    fs_caustics *caustics;
    fs_surfel_set set;
    size_t gap_added;
    surfel_gl gl;
    int gl_ready;
    unsigned slice_tex;
    int slice_res, slice_n;
    float *slices; /* CPU slice images */
} surfels;

static void destroy(void *self)
{
    surfels *s = self;
    if (!s) return;
    if (s->splat) fs_slice_splat_destroy(s->splat);
    if (s->caustics) fs_caustics_destroy(s->caustics);
    if (s->gl_ready) surfel_gl_destroy(&s->gl);
    if (s->slice_tex) glDeleteTextures(1, &s->slice_tex);
    free(s->slices);
    fs_density_frame_free(&s->fr);
    fs_density_grid_free(&s->dg);
    fs_surfel_set_free(&s->set);
    free(s);
}

static void *create(const fs_method_setup *setup)
{
    surfels *s = calloc(1, sizeof *s);
    if (!s || fs_method_setup_take("surfels", setup, &s->f, &s->params, sizeof s->params, &s->scene)) {
        if (!s) fs_fail(FS_ERR_RUNTIME, "surfels: out of memory");
        free(s);
        return NULL;
    }
    if (surfel_gl_create(&s->gl)) {
        destroy(s);
        return NULL;
    }
    s->gl_ready = 1;
    if (!(s->splat = fs_slice_splat_create()) || !(s->caustics = fs_caustics_create())) {
        destroy(s);
        return NULL;
    }
    return s;
}

static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    surfels *s = self;
    s->floor_h = fs_scene_floor(&s->scene, g);
    /* the exact build walks cells of at least H */
    return fs_density_frame_upload(&s->fr, p, g, s->f.H, 1, "surfels", "the density grid");
}

/* The density grid and its surfels: view-independent, rebuilt every frame. */
static int build_surface(surfels *s, fs_stages *t)
{
    const fs_particles *p = s->fr.p;
    fs_density_grid_free(&s->dg);
    int rc = fs_density_grid_init(&s->dg, p->bmin, p->bmax, s->f.H, s->params.grid_res);
    if (rc) return rc;
    int splat = s->params.grid_build == GRID_SPLAT; /* slice splatting: a GL stage */
    fs_density_builder b = {
        splat ? FS_DENSITY_SLICE : FS_DENSITY_EXACT, NULL, s->splat, s->scene.up_axis, s->params.clusters, splat};
    double t1;
    if ((rc = fs_density_frame_build(&b, &s->fr, &s->f, &s->dg, 0, t, "density_grid", &t1))) return rc;
    fs_surfel_extract_opts eo = {s->f.iso, (float)s->params.radius_scale, (float)s->params.gap};
    if ((rc = fs_surfels_extract(&s->dg, &eo, &s->set, &s->gap_added))) return rc;
    if ((rc = surfel_gl_upload(&s->gl, &s->set))) return rc;
    if (s->params.thickness && (rc = surfel_gl_upload_grid(&s->gl, &s->dg))) return rc;
    glFinish();
    fs_stages_add(t, "extract", fs_now_ms() - t1);
    return FS_OK;
}

/* The look: the scene's light and material; the caustics when on. */
/* The box under the water (OBJECT_WIDTH, OBJECT_ALBEDO above). */
static object_box place_object(const fs_particles *p, int up, float floor_h)
{
    int a = (up + 1) % 3, b = (up + 2) % 3;
    const float *h = up == 0 ? p->x : (up == 1 ? p->y : p->z);
    double mean = 0;
    for (size_t i = 0; i < p->n; i++) mean += h[i];
    mean = p->n ? mean / p->n : floor_h;
    object_box box;
    float side = OBJECT_WIDTH * fminf(p->bmax[a] - p->bmin[a], p->bmax[b] - p->bmin[b]);
    box.center[0] = 0.5f * (p->bmin[a] + p->bmax[a]);
    box.center[1] = 0.5f * (p->bmin[b] + p->bmax[b]);
    box.half[0] = box.half[1] = 0.5f * side;
    box.bottom = floor_h;
    box.top = floor_h + fmaxf((float)mean - floor_h, 0.0f);
    memcpy(box.albedo, OBJECT_ALBEDO, sizeof box.albedo);
    return box;
}

/* Sliced object images into a texture array (replaced when its size changes). */
static int upload_slices(surfels *s, const object_box *box, const fs_caustics_setup *cs, const float *maps,
                         const surfel_look *l)
{
    int res = cs->plane_res, n = cs->nplanes - 1;
    if (s->slice_res != res || s->slice_n != n) {
        if (s->slice_tex) glDeleteTextures(1, &s->slice_tex);
        free(s->slices);
        s->slices = malloc((size_t)res * res * 4 * n * sizeof(float));
        if (!s->slices) return fs_fail(FS_ERR_RUNTIME, "surfels: out of memory for the object slices");
        s->slice_tex = fs_gl_texture_2d_array(GL_RGBA32F, res, res, n);
        s->slice_res = res;
        s->slice_n = n;
    }
    float direct[3];
    for (int c = 0; c < 3; c++) direct[c] = fmaxf(l->light_dir[l->up_axis], 0.0f) * l->light_color[c];
    object_slices_build(box, n, cs->plane_height, cs->rect_min, cs->rect_max, res, maps, n, l->ambient, direct,
                        s->slices);
    glTextureSubImage3D(s->slice_tex, 0, 0, 0, 0, res, res, n, GL_RGBA, GL_FLOAT, s->slices);
    return FS_OK;
}

/* The scene's light (normalised; straight up when it has none) and material. */
static void scene_look(const surfels *s, surfel_look *l)
{
    const fs_scene *sc = &s->scene;
    int up = sc->up_axis;
    memset(l, 0, sizeof *l);
    memcpy(l->light_dir, sc->light_dir, sizeof l->light_dir);
    float ln = fs_v3_len(l->light_dir);
    for (int i = 0; i < 3; i++) l->light_dir[i] = ln > 0 ? l->light_dir[i] / ln : (i == up);
    memcpy(l->light_color, sc->light_color, sizeof l->light_color);
    l->ambient = sc->ambient;
    l->ior = sc->ior;
    memcpy(l->extinction, sc->absorption, sizeof l->extinction);
    memcpy(l->tint, sc->material_color, sizeof l->tint);
    l->up_axis = up;
    l->checker = sc->background == FS_BACKGROUND_CHECKER;
    l->floor_h = s->floor_h;
    l->check = sc->radius > 0 ? 8.0f * sc->radius : 1.0f;
}

/* The caustics' setup: the light, and maps spanning the grid's horizontal
 * extent grown by the sideways reach of refracted light down to the floor, one
 * sample plane on it. */
static void caustics_setup(const surfels *s, surfel_look *l, fs_caustics_setup *cs)
{
    const fs_density_grid *g = &s->dg;
    int up = l->up_axis, a = (up + 1) % 3, b = (up + 2) % 3;
    float top = g->origin[up] + (g->dim[up] - 1) * g->spacing;
    float reach = (top - l->floor_h) * 0.5f;
    memset(cs, 0, sizeof *cs);
    cs->up_axis = up;
    memcpy(cs->light_dir, l->light_dir, sizeof cs->light_dir);
    memcpy(cs->light_color, l->light_color, sizeof cs->light_color);
    cs->ior = l->ior;
    memcpy(cs->extinction, l->extinction, sizeof cs->extinction);
    cs->rect_min[0] = g->origin[a] - reach;
    cs->rect_min[1] = g->origin[b] - reach;
    cs->rect_max[0] = g->origin[a] + (g->dim[a] - 1) * g->spacing + reach;
    cs->rect_max[1] = g->origin[b] + (g->dim[b] - 1) * g->spacing + reach;
    cs->top = top + g->spacing;
    cs->screen_res = s->params.caustic_screen;
    cs->plane_res = s->params.caustic_map;
    cs->nplanes = 1;
    cs->plane_height[0] = l->floor_h;
    memcpy(l->rect_min, cs->rect_min, sizeof l->rect_min);
    memcpy(l->rect_max, cs->rect_max, sizeof l->rect_max);
}

/* The box under the water, when there is one: sample planes evenly from the
 * floor to its top. 1 when placed. */
static int object_planes(const surfels *s, surfel_look *l, fs_caustics_setup *cs, object_box *box)
{
    if (s->params.object != OBJECT_BOX) return 0;
    *box = place_object(s->fr.p, l->up_axis, l->floor_h);
    if (!(box->top > box->bottom)) return 0;
    int n = s->params.object_slices;
    cs->nplanes = n + 1;
    for (int k = 0; k <= n; k++) cs->plane_height[k] = box->bottom + (box->top - box->bottom) * k / n;
    l->nslices = n;
    memcpy(l->slice_h, cs->plane_height, (size_t)(n + 1) * sizeof(float));
    return 1;
}

/* The look: the scene's light and material; the caustics on the sample planes
 * (the floor, and with the object the planes slicing it up to its top); the
 * sliced object images. */
static int build_look(surfels *s, surfel_look *l, fs_stages *t)
{
    scene_look(s, l);
    if (!l->checker) return FS_OK; /* no floor: nothing under the water */
    fs_caustics_setup cs;
    caustics_setup(s, l, &cs);
    object_box box;
    int object = object_planes(s, l, &cs, &box);
    const float *maps = NULL;
    if (s->params.caustics) {
        double t0 = fs_gl_stage_start();
        int rc = fs_caustics_run(s->caustics, &cs, s->gl.buf, s->gl.n);
        if (rc) return rc;
        fs_gl_stage_end(t, "caustics", t0);
        l->caustic_tex = fs_caustics_texture(s->caustics);
        maps = fs_caustics_maps(s->caustics);
    }
    if (object) {
        int rc = upload_slices(s, &box, &cs, maps, l);
        if (rc) return rc;
        l->slice_tex = s->slice_tex;
    }
    return FS_OK;
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *t)
{
    surfels *s = self;
    if (!s->fr.p) return fs_fail(FS_ERR_RUNTIME, "surfels: render before upload");
    int rc = build_surface(s, t);
    surfel_look look;
    if (!rc) rc = build_look(s, &look, t);
    if (rc) return rc;
    surfel_draw_opts o = {
        .epsilon = (float)s->params.epsilon * s->f.r,
        .gauss = (float)s->params.gauss,
        .thickness = s->params.thickness,
        .step = s->dg.spacing,
        .iso = s->f.iso,
        .grid_spacing = s->dg.spacing,
    };
    memcpy(o.grid_origin, s->dg.origin, sizeof o.grid_origin);
    return surfel_gl_render(&s->gl, cam, &look, &o, out, t);
}

static int export_file(void *self, const char *path, const fs_provenance *prov)
{
    (void)prov; /* its files carry none yet */
    surfels *s = self;
    if (!s->fr.p) return fs_fail(FS_ERR_RUNTIME, "surfels: export before upload");
    int vdb = fs_path_ends_with(path, ".vdb"), ply = fs_path_ends_with(path, ".ply");
    if (!vdb && !ply) return fs_fail(FS_ERR_INPUT, "%s: surfels exports .vdb (density grid) or .ply (surfels)", path);
    fs_stages t = {0};
    int rc = build_surface(s, &t);
    if (rc) return rc;
    return vdb ? fs_density_grid_write_vdb(&s->dg, path, "density") : fs_surfels_write_ply(&s->set, path);
}

/* the own appearance (5.3) and the caustic irradiance it used (5.1-5.2) */
static const fs_aov_def aovs[] = {{FS_AOV_OWN, 4, 0}, {FS_AOV_CAUSTICS, 1, 0}};

const fs_method fs_method_surfels = {
    .name = "surfels",
    .cost = 19, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description =
        "slice-splat density grid, iso-surface surfels, 3-pass splatting with reflection, refraction, caustics",
    .paper = "iwasaki2006",
    .appearance = "environment reflection, refraction of the floor and a sunken box, caustics (iwasaki2006)",
    .exports = ".vdb density grid (OpenVDB FloatGrid), .ply surfels",
    .needs_gl = 1,
    .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS) | FS_CNT_BIT(FS_CNT_NEIGHBOURS) | FS_CNT_BIT(FS_CNT_MARCH_SAMPLES) |
        FS_CNT_BIT(FS_CNT_FRAGMENTS) | FS_CNT_BIT(FS_CNT_TEXELS),
    .aovs = aovs,
    .naovs = sizeof aovs / sizeof *aovs,
    .params = params,
    .nparams = sizeof params / sizeof *params,
    .params_size = sizeof(surfels_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
    .export_file = export_file,
};
