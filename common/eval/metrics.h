/* Metrics of a method's G-buffer against a reference's (docs/DESIGN.md, References
 * and metrics). a = the method, b = the reference; both the same size. */
#ifndef FS_METRICS_H
#define FS_METRICS_H
#include "gbuffer.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_metrics {
    double mask_iou;        /* |A and B| / |A or B| of coverage (1 when both empty) */
    double depth_bias_r;    /* mean (a - b) eye depth over pixels both cover, in r */
    double depth_rmse_r;    /* RMS of (a - b - bias), in r: the error around the bias */
    double depth_p95_r;     /* 95th percentile of |a - b - bias|, in r: around the mean, so a few
                                        outliers that pull the mean make it read their pull */
    double normal_mean_deg; /* mean angle between normals over pixels both cover */
    double normal_p95_deg;
    double interior_normal_mean_deg; /* over the interior mask (>= 3 px from either silhouette) */
    double psnr_db;                  /* sRGB luminance over the union of the masks; INFINITY if equal */
    double ssim;                     /* Wang et al. 2004 on sRGB luminance, mean over the union */
    size_t n_both, n_union, n_interior;
    /* The depth error e = (a - b) / r itself, not around its mean: robust to a few outliers */
    double depth_median_r;  /* median of e (signed) */
    double depth_abs_p50_r; /* 50th, 95th and 99th percentiles of |e| */
    double depth_abs_p95_r;
    double depth_abs_p99_r;
    double depth_over_1r_frac; /* share of the pixels both cover with |e| > 1 */
} fs_metrics;

/* rgba_a/rgba_b: linear RGBA of the shaded images (PSNR/SSIM; either NULL -> both
 * NAN); r: particle radius. Metrics without any pixel to average over are NAN.
 * Percentiles are nearest-rank; see common/eval/metrics.c for the exact definitions.
 * Sizes that differ or r <= 0: FS_ERR_INPUT; out of memory: FS_ERR_RUNTIME. */
int fs_metrics_compute(const fs_gbuffer *a, const float *rgba_a, const fs_gbuffer *b, const float *rgba_b, float r,
                       fs_metrics *out);
/* Pixels covered by both and at least dist px (chessboard distance) from every pixel
 * outside either mask (silhouettes and image borders count as outside). Measured
 * from the silhouette line: a dist-px ring is removed, so a 20x20 square keeps its
 * central 14x14 at dist 3 (an erosion by a (2 dist + 1)^2 square). mask: w*h, 0/1. */
void fs_interior_mask(const fs_gbuffer *a, const fs_gbuffer *b, int dist, unsigned char *mask);
/* Per-pixel maps for heatmaps: angle in degrees and |depth error - bias| in r where
 * both cover, NAN elsewhere. */
void fs_normal_error_map(const fs_gbuffer *a, const fs_gbuffer *b, float *deg);
void fs_depth_error_map(const fs_gbuffer *a, const fs_gbuffer *b, float r, double bias_r, float *err_r);
/* sRGB-encoded luminance (Rec. 709 weights on the sRGB-encoded channels), 0..1. */
void fs_srgb_luminance(const float *rgba, int w, int h, float *lum);
/* Mean SSIM (Gaussian window sigma 1.5, K1 0.01, K2 0.03, L 1) over pixels with
 * mask != 0 (all when mask is NULL); the window is cut at the image borders and
 * renormalised over the pixels inside. NAN without any pixel (or out of memory). */
double fs_ssim(const float *x, const float *y, int w, int h, const unsigned char *mask);

#ifdef __cplusplus
}
#endif
#endif
