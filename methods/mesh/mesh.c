/* mesh: the baseline of meshing the scene's own field (splashsurf's recipe):
 * phi sampled on a sparse voxel volume near the particles, meshed at iso by
 * OpenVDB's volumeToMesh, optionally smoothed, vertex normals from the
 * analytic gradient (mesh_build.c), rasterised by OpenGL into the G-buffer
 * with a signed additive thickness (mesh_gl.c). Exists only with
 * FS_WITH_OPENVDB=ON (FS_OPTIONAL_METHODS in methods/CMakeLists.txt). */
#include "aniso_params.h"
#include "counters.h"
#include "fs_error.h"
#include "gl_gbuffer.h"
#include "mesh.h"
#include "mesh_export.h"
#include "mesh_gl.h"
#include "mesh_normals.h"
#include "mesh_smooth.h"
#include "mesh_weights.h"
#include "method.h"
#include "method_params.h"
#include "scene_provenance.h"
#include "zhu_bridson.h"
#include <stdlib.h>

typedef struct mesh_params {
    double cube;
    fs_mesh_smoothing smooth;
    int smooth_iters;
    bool thickness;
    fs_field_choice field;
    fs_aniso_param_values aniso;
    double weights_norm;
    int normal_iters;
    bool attributes;
    double zb_radius;
} mesh_params;

extern const fs_method fs_method_mesh;

#define FIELD(f) FS_PARAM_FIELD(mesh_params, f)
static const fs_param_def params[] = {
    {FIELD(cube), FS_PARAM_FLOAT, 0.5, 0.01, 16.0, NULL,
     "voxel (marching cube) size of the sampled field, in multiples of r"},
    {FIELD(smooth), FS_PARAM_ENUM, FS_MESH_SMOOTH_OFF, 0, 3, "off|laplacian|taubin|weighted",
     "mesh smoothing after meshing (weighted: splashsurf's, Loeschner et al. 2023)"},
    {FIELD(smooth_iters), FS_PARAM_INT, 10, 0, 1000, NULL,
     "smoothing iterations (a Taubin one is a lambda and a mu pass)"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL,
     "signed additive thickness pass over front and back faces (on/off)"},
    {FIELD(field), FS_PARAM_ENUM, 0, 0, 2, "isotropic|anisotropic|zhu_bridson",
     "SPH kernel, Yu & Turk's anisotropic kernel, or Zhu & Bridson's |x - xbar| - r (meshed at 0)"},
    FS_ANISO_PARAM_DEFS(mesh_params),
    {FIELD(weights_norm), FS_PARAM_FLOAT, FS_MESH_WEIGHTS_NORM, 0.01, 1000.0, NULL,
     "weighted: weighted neighbour count that gets weight 1 (splashsurf's normalization)"},
    {FIELD(normal_iters), FS_PARAM_INT, FS_MESH_NORMAL_ITERS, 0, 1000, NULL,
     "weighted: smoothing passes of the area-weighted vertex normals"},
    {FIELD(attributes), FS_PARAM_BOOL, 0, 0, 1, NULL,
     "interpolate the particles' velocity and colour onto the vertices, for the .ply/.vtk/.vtp export (on/off)"},
    {FIELD(zb_radius), FS_PARAM_FLOAT, FS_ZB_RADIUS, 1.0, 40.0, NULL,
     "zhu_bridson: kernel radius R, multiples of r (the paper's twice the particle spacing: 4)"},
};
#undef FIELD

typedef struct mesh {
    fs_field field;
    fs_mesh_opts opts;
    int thickness;
    fs_trimesh tm;
    fs_mesh_gl gl;
} mesh;

static void destroy(void *self)
{
    mesh *s = self;
    if (!s) return;
    fs_trimesh_free(&s->tm);
    fs_mesh_gl_free(&s->gl);
    free(s);
}

static void opts_of(const mesh_params *p, const fs_field *f, fs_mesh_opts *o)
{
    *o = (fs_mesh_opts){.cube = p->cube * f->r,
                        .smooth = p->smooth,
                        .smooth_iters = p->smooth_iters,
                        .aniso = p->field == FS_FIELD_ANISOTROPIC,
                        .zb = p->field == FS_FIELD_ZHU_BRIDSON,
                        .zb_radius = p->zb_radius * f->r,
                        .weights_norm = p->weights_norm,
                        .normal_iters = p->normal_iters,
                        .attributes = p->attributes};
    fs_aniso_params_set(&o->ap, &p->aniso, f->kernel, f->r);
}

int fs_mesh_opts_from_values(const double *values, const fs_field *f, fs_mesh_opts *o)
{
    mesh_params p;
    int rc = fs_method_params_fill(&fs_method_mesh, values, &p);
    if (!rc) opts_of(&p, f, o);
    return rc;
}

void fs_mesh_provenance(fs_provenance *out, const fs_scene *s, const double *values, int frame)
{
    fs_provenance_init(out, s, "CPU", NULL);
    fs_method_provenance(out, &fs_method_mesh, values, frame);
}

static void *create(const fs_method_setup *setup)
{
    mesh_params p;
    if (fs_method_check_field("mesh", &setup->field)) return NULL;
    if (fs_method_params_copy("mesh", setup, &p, sizeof p)) return NULL;
    mesh *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "out of memory");
        return NULL;
    }
    s->field = setup->field;
    opts_of(&p, &setup->field, &s->opts);
    s->thickness = p.thickness;
    if (fs_mesh_gl_init(&s->gl)) {
        free(s);
        return NULL;
    }
    return s;
}

/* The mesh is built here (the run layer's stage "upload") and handed to the GL. */
static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    mesh *s = self;
    fs_trimesh_free(&s->tm);
    int rc = fs_mesh_build(p, g, &s->field, &s->opts, &s->tm, NULL);
    if (!rc) rc = fs_mesh_gl_upload(&s->gl, &s->tm);
    if (rc) fs_trimesh_free(&s->tm);
    return rc;
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    mesh *s = self;
    int rc = fs_mesh_gl_draw(&s->gl, cam, s->thickness, st);
    return rc ? rc : fs_gl_target_read(&s->gl.target, out, NULL, 0, st);
}

static int export_file(void *self, const char *path, const fs_provenance *prov)
{
    mesh *s = self;
    if (!s->tm.nrm) return fs_fail(FS_ERR_RUNTIME, "mesh: export before upload");
    return fs_mesh_export(&s->tm, path, prov);
}

const fs_method fs_method_mesh = {
    .name = "mesh",
    .cost = 1.5, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "marching-cubes mesh of the scene's field (OpenVDB volumeToMesh), rasterised (baseline)",
    .paper = "splashsurf-style meshing (baseline)",
    .exports = FS_MESH_EXPORTS ": the mesh with vertex normals",
    .needs_gl = 1,
    .grid_use = FS_GRID_AT_UPLOAD, /* read while sampling; the mesh is all that is kept */
    .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS) | FS_CNT_BIT(FS_CNT_NEIGHBOURS) | FS_CNT_BIT(FS_CNT_FRAGMENTS),
    .params = params,
    .nparams = sizeof params / sizeof *params,
    .params_size = sizeof(mesh_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
    .export_file = export_file,
};
