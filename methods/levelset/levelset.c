/* levelset: OpenVDB's union-of-spheres narrow-band level set of the particles
 * (ParticlesToLevelSet, as `vdb_tool -points2ls`; or points::rasterizeSpheres,
 * or points::rasterizeSmoothSpheres' Zhu & Bridson surface), optionally dilated, smoothed
 * and eroded (LevelSetFilter), ray traced on the CPU with OpenVDB's level-set
 * ray intersector, one ray per pixel (OpenMP over rows). A baseline users pick
 * instead of the papers' methods (Museth 2013, OpenVDB). The OpenVDB calls live
 * in levelset_vdb.cpp; this file (and the method) exists only with
 * FS_WITH_OPENVDB=ON (FS_OPTIONAL_METHODS in methods/CMakeLists.txt). */
#include "counters.h"
#include "fs_error.h"
#include "levelset_vdb.h"
#include "method.h"
#include "output_file.h"
#include "timing.h"
#include "vec3.h"
#include <math.h>
#include <omp.h>
#include <stdlib.h>

typedef struct levelset_params {
    double radius, voxel, half_width;
    int dilate;
    fs_ls_smoothing smooth;
    int smooth_iters, erode;
    bool thickness;
    fs_ls_rasterizer rasterizer;
    double search;
} levelset_params;

#define FIELD(f) FS_PARAM_FIELD(levelset_params, f)
static const fs_param_def params[] = {
    {FIELD(radius), FS_PARAM_FLOAT, 2.0, 0.01, 64.0, NULL,
     "sphere radius of each particle, in multiples of r (>= 1.5 voxels)"},
    {FIELD(voxel), FS_PARAM_FLOAT, 0.5, 0.01, 16.0, NULL, "voxel size of the level set, in multiples of r"},
    {FIELD(half_width), FS_PARAM_FLOAT, 3.0, 1.0, 32.0, NULL, "narrow-band half width, in voxels"},
    {FIELD(dilate), FS_PARAM_INT, 0, 0, 16, NULL, "recipe: dilate the level set by this many voxels first (0: off)"},
    {FIELD(smooth), FS_PARAM_ENUM, FS_LS_SMOOTH_OFF, 0, 2, "off|gaussian|meancurvature",
     "recipe: smoothing filter after the dilation"},
    {FIELD(smooth_iters), FS_PARAM_INT, 1, 0, 64, NULL, "recipe: iterations of the smoothing filter"},
    {FIELD(erode), FS_PARAM_INT, 0, 0, 16, NULL, "recipe: erode by this many voxels last (0: off)"},
    {FIELD(thickness), FS_PARAM_BOOL, 1, 0, 1, NULL, "march on through every layer for the thickness (on/off)"},
    {FIELD(rasterizer), FS_PARAM_ENUM, FS_LS_RASTER_PARTICLES, 0, 2, "particles|spheres|smooth",
     "tools::ParticlesToLevelSet, points::rasterizeSpheres or points::rasterizeSmoothSpheres (Zhu & Bridson)"},
    {FIELD(search), FS_PARAM_FLOAT, 4.0, 0.01, 64.0, NULL,
     "smooth: Zhu & Bridson's kernel (search) radius, in multiples of r (>= radius)"},
};
#undef FIELD

typedef struct levelset {
    fs_field field;
    fs_ls_build b;
    int thickness;
    fs_ls_grid *grid;
} levelset;

static void destroy(void *self)
{
    levelset *s = self;
    if (!s) return;
    fs_ls_grid_free(s->grid);
    free(s);
}

static void *create(const fs_method_setup *setup)
{
    levelset_params p;
    if (fs_method_check_field("levelset", &setup->field)) return NULL;
    if (fs_method_params_copy("levelset", setup, &p, sizeof p)) return NULL;
    if (p.rasterizer == FS_LS_RASTER_PARTICLES && p.radius < 1.5 * p.voxel) {
        fs_fail(FS_ERR_INPUT,
                "levelset: radius %g r is under 1.5 voxels (voxel %g r): OpenVDB's rasteriser drops such particles",
                p.radius, p.voxel);
        return NULL;
    }
    if (p.rasterizer == FS_LS_RASTER_SMOOTH && p.search < p.radius) {
        fs_fail(FS_ERR_INPUT,
                "levelset: search %g r is under the radius %g r: rasterizeSmoothSpheres needs search >= radius",
                p.search, p.radius);
        return NULL;
    }
    levelset *s = calloc(1, sizeof *s);
    if (!s) {
        fs_fail(FS_ERR_RUNTIME, "out of memory");
        return NULL;
    }
    s->field = setup->field;
    double r = setup->field.r;
    s->b = (fs_ls_build){.voxel = p.voxel * r,
                         .radius = p.radius * r,
                         .half_width = p.half_width,
                         .dilate = p.dilate,
                         .smooth = p.smooth,
                         .smooth_iters = p.smooth_iters,
                         .erode = p.erode,
                         .rasterizer = p.rasterizer,
                         .search = p.search * r};
    s->thickness = p.thickness;
    return s;
}

/* The level set is built here (the run layer's stage "upload"); its active
 * voxels are counted as texels_written. */
static int upload(void *self, const fs_particles *p, const fs_grid *g)
{
    (void)g;
    levelset *s = self;
    fs_ls_grid_free(s->grid);
    s->grid = fs_ls_grid_build(p->x, p->y, p->z, p->n, &s->b);
    if (!s->grid) return FS_ERR_RUNTIME; /* fs_fail set */
    fs_count_add(FS_CNT_TEXELS, fs_ls_grid_active_voxels(s->grid));
    return FS_OK;
}

static int render(void *self, const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    levelset *s = self;
    if (!s->grid) return fs_fail(FS_ERR_RUNTIME, "levelset: render before upload");
    double t0 = fs_now_ms();
    float right[3], up[3], fwd[3];
    fs_camera_basis(cam, right, up, fwd);
    /* one intersector per thread, made here so a failure's message (thread-local) is ours */
    int nth = omp_get_max_threads();
    fs_ls_tracer **tr = calloc((size_t)nth, sizeof *tr);
    if (!tr) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < nth; i++)
        if (!(tr[i] = fs_ls_tracer_create(s->grid))) {
            while (i--) fs_ls_tracer_free(tr[i]);
            free(tr);
            return FS_ERR_RUNTIME;
        }
#pragma omp parallel num_threads(nth)
    {
        fs_ls_tracer *t = tr[omp_get_thread_num()];
        uint64_t queries = 0;
#pragma omp for schedule(dynamic, 1)
        for (int py = 0; py < cam->height; py++) {
            for (int px = 0; px < cam->width; px++) {
                float d[3];
                fs_ls_hit h;
                fs_camera_ray(cam, px + 0.5f, py + 0.5f, d);
                fs_ls_trace(t, cam->eye, d, s->thickness, &h);
                queries += h.queries;
                if (!h.hit) continue;
                size_t id = (size_t)py * cam->width + px;
                float nw[3] = {(float)h.n[0], (float)h.n[1], (float)h.n[2]}, nv[3], dv[3];
                fs_camera_to_view_dir(cam, nw, nv);
                fs_camera_to_view_dir(cam, d, dv);
                float len = fs_v3_len(nv);
                if (!(len > 0)) {
                    nv[0] = nv[1] = 0;
                    nv[2] = len = 1;
                } /* a flat SDF spot: face the eye */
                float sg = nv[0] * dv[0] + nv[1] * dv[1] + nv[2] * dv[2] > 0 ? -1.0f : 1.0f; /* face the camera */
                for (int a = 0; a < 3; a++) out->normal[3 * id + a] = sg * nv[a] / len;
                out->depth[id] = (float)h.t * (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]);
                out->thickness[id] = (float)h.thick;
                out->coverage[id] = 1.0f;
            }
        }
        fs_count_add(FS_CNT_MARCH_SAMPLES, queries);
    }
    for (int i = 0; i < nth; i++) fs_ls_tracer_free(tr[i]);
    free(tr);
    if (st) fs_stages_add(st, "trace", fs_now_ms() - t0);
    return FS_OK;
}

static int export_file(void *self, const char *path, const fs_provenance *prov)
{
    (void)prov; /* its files carry none yet */
    levelset *s = self;
    if (!s->grid) return fs_fail(FS_ERR_RUNTIME, "levelset: export before upload");
    if (!fs_path_ends_with(path, ".vdb"))
        return fs_fail(FS_ERR_INPUT, "%s: levelset exports .vdb (the level set)", path);
    return fs_ls_grid_write(s->grid, path);
}

const fs_method fs_method_levelset = {
    .name = "levelset",
    .cost = 11, /* results/demo/timings.csv at 16904c2 (docs/DESIGN.md, "Sharded studies") */
    .description = "OpenVDB union-of-spheres narrow-band level set, ray traced on the CPU (baseline)",
    .paper = "museth2013 (OpenVDB, vdb_tool -points2ls; baseline)",
    .exports = ".vdb: the narrow-band level set (float grid 'surface', class level set)",
    .needs_gl = 0,
    .grid_use = FS_GRID_UNUSED, /* OpenVDB rasterises the particles itself */
    .counters = FS_CNT_BIT(FS_CNT_MARCH_SAMPLES) | FS_CNT_BIT(FS_CNT_TEXELS),
    .params = params,
    .nparams = sizeof params / sizeof *params,
    .params_size = sizeof(levelset_params),
    .create = create,
    .upload = upload,
    .render = render,
    .destroy = destroy,
    .export_file = export_file,
};
