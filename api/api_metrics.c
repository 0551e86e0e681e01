/* The metrics between two images of the library, masked as compare masks, and
 * (fluidsurf_metrics_compute3) after diff's check that they can be compared
 * (common/eval/comparable.h). */
#include "api_internal.h"
#include "comparable.h"
#include "fs_error.h"
#include "metrics.h"
#include "obstacle_mask.h"

#include <stdio.h>
#include <string.h>

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

/* One image as diff's rule sees it: size, camera and scene from its provenance, r. */
static fs_comparable comparable(const fluidsurf_image *im, const char *name)
{
    return (fs_comparable){name,
                           im->im.g.w,
                           im->im.g.h,
                           fs_provenance_get(&im->prov, "camera"),
                           fs_provenance_get(&im->prov, "scene_hash"),
                           im->radius};
}

/* The findings as lines into warnings (size bytes; cut short when it is small). */
static void keep_findings(const fs_comparable_findings *f, char *warnings, size_t size)
{
    if (!warnings || !size) return;
    size_t used = 0;
    warnings[0] = 0;
    for (int i = 0; i < f->n && used < size; i++)
        used += (size_t)snprintf(warnings + used, size - used, "%s%s", i ? "\n" : "", f->text[i]);
}

int fluidsurf_metrics_compute3(const fluidsurf_image *a, const fluidsurf_image *b, double radius, int flags,
                               fluidsurf_metrics *out, fluidsurf_depth_metrics *depth, char *warnings, size_t size)
{
    int rc;
    if (warnings && size) warnings[0] = 0;
    if ((rc = fs_api_check(a, "method image")) || (rc = fs_api_check(b, "reference image"))) return rc;
    if (flags & ~FLUIDSURF_METRICS_STRICT) return fs_fail(FS_ERR_INPUT, "metrics: unknown flags %#x", flags);
    const fs_comparable im[2] = {comparable(a, "image"), comparable(b, "reference")};
    const fs_comparable_rules rules = {flags & FLUIDSURF_METRICS_STRICT ? "strict" : NULL, 0, radius > 0,
                                       radius > 0 ? "the radius given" : "the reference's r"};
    fs_comparable_findings found;
    if ((rc = fs_comparable_check(im, &rules, &found))) return rc;
    if ((rc = fluidsurf_metrics_compute2(a, b, radius, out, depth))) return rc;
    keep_findings(&found, warnings, size);
    return FLUIDSURF_OK;
}
