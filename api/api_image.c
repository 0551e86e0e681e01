/* Images of the library: a rendered or read G-buffer, its stages and
 * provenance, and the metrics between two of them. */
#include "api_internal.h"
#include "fs_error.h"
#include "metrics.h"
#include "obstacle_mask.h"
#include "render_output.h"

#include <stdlib.h>
#include <string.h>

int fluidsurf_image_read(const char *path, fluidsurf_image **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out")) || (rc = fs_api_check(path, "path"))) return rc;
    fs_api_init();
    *out = NULL;
    fluidsurf_image *im = calloc(1, sizeof *im);
    if (!im) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    if ((rc = fs_read_render(path, &im->im.g, &im->im.rgba, &im->radius))) {
        free(im);
        return rc;
    }
    *out = im;
    return FLUIDSURF_OK;
}

/* n floats of src (NULL: leave dst as allocated, cleared) into dst. */
static void copy_layer(float *dst, const float *src, size_t n)
{
    if (src) memcpy(dst, src, n * sizeof *src);
}

int fluidsurf_image_from_arrays(int w, int h, const float *depth, const float *normal, const float *thickness,
                                const float *coverage, const float *rgba, double radius, fluidsurf_image **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out")) || (rc = fs_api_check(depth, "depth")) ||
        (rc = fs_api_check(normal, "normal")) || (rc = fs_api_check(coverage, "coverage")))
        return rc;
    *out = NULL;
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
        return fs_fail(FS_ERR_INPUT, "image size %dx%d: each side 1 to 16384", w, h);
    if (!(radius >= 0)) return fs_fail(FS_ERR_INPUT, "radius %g: must be 0 or positive", radius);
    fluidsurf_image *im = calloc(1, sizeof *im);
    size_t n = (size_t)w * h;
    if (!im || fs_gbuffer_alloc(&im->im.g, w, h) || (rgba && !(im->im.rgba = malloc(n * 4 * sizeof(float))))) {
        fluidsurf_image_free(im);
        return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    copy_layer(im->im.g.depth, depth, n), copy_layer(im->im.g.normal, normal, 3 * n);
    copy_layer(im->im.g.thickness, thickness, n), copy_layer(im->im.g.coverage, coverage, n);
    copy_layer(im->im.rgba, rgba, 4 * n);
    im->radius = (float)radius;
    *out = im;
    return FLUIDSURF_OK;
}

int fluidsurf_image_set_solid_depth(fluidsurf_image *im, const float *solid_depth)
{
    int rc;
    if ((rc = fs_api_check(im, "image")) || (rc = fs_api_check(solid_depth, "solid_depth"))) return rc;
    float *have = fs_gbuffer_aov(&im->im.g, FS_AOV_SOLID_DEPTH);
    if (!have && (rc = fs_gbuffer_add_aov(&im->im.g, FS_AOV_SOLID_DEPTH, 1))) return rc;
    copy_layer(fs_gbuffer_aov(&im->im.g, FS_AOV_SOLID_DEPTH), solid_depth, (size_t)im->im.g.w * im->im.g.h);
    return FLUIDSURF_OK;
}

void fluidsurf_image_free(fluidsurf_image *im)
{
    if (!im) return;
    fs_run_image_free(&im->im);
    free(im);
}

int fluidsurf_image_width(const fluidsurf_image *im) { return im ? im->im.g.w : 0; }
int fluidsurf_image_height(const fluidsurf_image *im) { return im ? im->im.g.h : 0; }
double fluidsurf_image_radius(const fluidsurf_image *im) { return im ? im->radius : 0; }

int fluidsurf_image_camera(const fluidsurf_image *im, fluidsurf_camera *c)
{
    int rc;
    if ((rc = fs_api_check(im, "image")) || (rc = fs_api_check(c, "camera"))) return rc;
    if (!im->has_camera) return fs_fail(FS_ERR_INPUT, "image: not rendered by this library, so it has no camera");
    fs_api_camera_out(&im->camera, c);
    return FLUIDSURF_OK;
}

const float *fluidsurf_image_layer(const fluidsurf_image *im, const char *name, int *ncomp)
{
    if (ncomp) *ncomp = 0;
    if (!im || !name) return NULL;
    const fs_gbuffer *g = &im->im.g;
    const struct {
        const char *name;
        const float *data;
        int ncomp;
    } core[] = {
        {"depth", g->depth, 1},       {"normal", g->normal, 3}, {"thickness", g->thickness, 1},
        {"coverage", g->coverage, 1}, {"rgba", im->im.rgba, 4},
    };
    for (size_t i = 0; i < sizeof core / sizeof *core; i++)
        if (!strcmp(core[i].name, name)) {
            if (ncomp && core[i].data) *ncomp = core[i].ncomp;
            return core[i].data;
        }
    for (int i = 0; i < g->naovs; i++)
        if (!strcmp(g->aov[i].name, name)) {
            if (ncomp) *ncomp = g->aov[i].ncomp;
            return g->aov[i].data;
        }
    return NULL;
}

int fluidsurf_image_aov_count(const fluidsurf_image *im) { return im ? im->im.g.naovs : 0; }
const char *fluidsurf_image_aov_name(const fluidsurf_image *im, int i)
{
    return im && i >= 0 && i < im->im.g.naovs ? im->im.g.aov[i].name : NULL;
}

static int stage_ok(const fluidsurf_image *im, int i) { return im && i >= 0 && i < im->st.n; }
int fluidsurf_image_stage_count(const fluidsurf_image *im) { return im ? im->st.n : 0; }
const char *fluidsurf_image_stage_name(const fluidsurf_image *im, int i)
{
    return stage_ok(im, i) ? im->st.name[i] : NULL;
}
double fluidsurf_image_stage_ms(const fluidsurf_image *im, int i) { return stage_ok(im, i) ? im->st.ms[i] : 0; }
const char *fluidsurf_image_stage_renderer(const fluidsurf_image *im, int i)
{
    return stage_ok(im, i) ? im->renderer[i] : NULL;
}

static int prov_ok(const fluidsurf_image *im, int i) { return im && i >= 0 && i < im->prov.n; }
int fluidsurf_image_provenance_count(const fluidsurf_image *im) { return im ? im->prov.n : 0; }
const char *fluidsurf_image_provenance_name(const fluidsurf_image *im, int i)
{
    return prov_ok(im, i) ? im->prov.name[i] : NULL;
}
const char *fluidsurf_image_provenance_value(const fluidsurf_image *im, int i)
{
    return prov_ok(im, i) ? im->prov.value[i] : NULL;
}

int fluidsurf_metrics_compute2(const fluidsurf_image *a, const fluidsurf_image *b, double radius,
                               fluidsurf_metrics *out, fluidsurf_depth_metrics *depth)
{
    int rc;
    if ((rc = fs_api_check(a, "method image")) || (rc = fs_api_check(b, "reference image")) ||
        (rc = fs_api_check(out, "out")))
        return rc;
    double r = radius > 0 ? radius : b->radius;
    if (!(r > 0)) return fs_fail(FS_ERR_INPUT, "metrics: no radius (the reference image has none; pass one)");
    fs_metrics m; /* masked as compare masks, where either image carries the solids' depth (the reference's first) */
    const float *solids = fs_gbuffer_aov(&b->im.g, FS_AOV_SOLID_DEPTH);
    if (!solids) solids = fs_gbuffer_aov(&a->im.g, FS_AOV_SOLID_DEPTH);
    if ((rc = fs_metrics_compute_masked(solids, &a->im.g, a->im.rgba, &b->im.g, b->im.rgba, (float)r, &m, NULL)))
        return rc;
    *out = (fluidsurf_metrics){m.mask_iou,
                               m.depth_bias_r,
                               m.depth_rmse_r,
                               m.depth_p95_r,
                               m.normal_mean_deg,
                               m.normal_p95_deg,
                               m.interior_normal_mean_deg,
                               m.psnr_db,
                               m.ssim,
                               m.n_both,
                               m.n_union,
                               m.n_interior};
    if (depth)
        *depth = (fluidsurf_depth_metrics){m.depth_median_r, m.depth_abs_p50_r, m.depth_abs_p95_r, m.depth_abs_p99_r,
                                           m.depth_over_1r_frac};
    return FLUIDSURF_OK;
}

int fluidsurf_metrics_compute(const fluidsurf_image *a, const fluidsurf_image *b, double radius, fluidsurf_metrics *out)
{
    return fluidsurf_metrics_compute2(a, b, radius, out, NULL);
}
