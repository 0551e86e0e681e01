/* Metrics of a method's G-buffer (a) against a reference's (b); docs/DESIGN.md,
 * "References and metrics". Definitions, exactly as computed here:
 *   covered            coverage >= 0.5 (the G-buffer stores 0 or 1)
 *   mask_iou           |A and B| / |A or B|; 1 when both masks are empty
 *   depth (in r)       d = (a - b) / r over pixels both cover; bias = mean(d);
 *                      rmse = sqrt(mean((d - bias)^2)), the error around the bias;
 *                      p95 = 95th percentile of |d - bias|;
 *                      median = median of d (signed); abs p50/p95/p99 =
 *                      percentiles of |d|; over_1r_frac = share with |d| > 1
 *   normal angle       acos(clamp(dot(na, nb), -1, 1)) in degrees over pixels both
 *                      cover (computed as atan2(|na x nb|, na . nb): the same angle for
 *                      unit vectors, but exact near 0 deg, where acos of a float dot
 *                      product is off by ~0.02 deg); mean and 95th percentile
 *   interior mean      normal mean over fs_interior_mask(a, b, 3)
 *   psnr_db            10 log10(1 / MSE) of sRGB luminance over the union; INFINITY if
 *                      MSE == 0
 *   ssim               Wang et al. 2004 on sRGB luminance, averaged over the union
 * Percentiles are nearest-rank: the ceil(0.95 n)-th smallest value (1-based; the
 * median is the ceil(0.5 n)-th).
 * A metric without any pixel to average over is NAN. Sums are taken per row and
 * added in row order, so results do not depend on the thread count. */
#include "metrics.h"
#include "fs_error.h"
#include "percentile.h"
#include "srgb.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define INTERIOR_DIST 3
#define RAD2DEG (180.0 / 3.14159265358979323846)

static int is_covered(float c) { return c >= 0.5f; }

/* Angle in degrees between two normals. A zero vector gives 90 deg, as
 * acos(clamp(0)) would; non-finite components give NaN. */
static double normal_angle_deg(const float *na, const float *nb)
{
    double ax = na[0], ay = na[1], az = na[2], bx = nb[0], by = nb[1], bz = nb[2];
    double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    double cross = sqrt(cx * cx + cy * cy + cz * cz), dot = ax * bx + ay * by + az * bz;
    if (cross == 0 && dot == 0) return 90.0;
    return atan2(cross, dot) * RAD2DEG;
}

/* Sum of per-row partial sums in row order (deterministic for any thread count). */
static double sum_rows(const double *row, int h)
{
    double s = 0;
    for (int y = 0; y < h; y++) s += row[y];
    return s;
}

void fs_interior_mask(const fs_gbuffer *a, const fs_gbuffer *b, int dist, unsigned char *mask)
{
    /* Two-pass chessboard distance transform (Rosenfeld & Pfaltz), saturated at
     * K = dist + 1 so it fits in the mask bytes: m = min(K, distance from the pixel
     * centre to the nearest centre of a pixel not covered by both; pixels beyond
     * the image border count as such). A pixel is interior when m >= K: the nearest
     * outside pixel is more than dist px away, i.e. the pixel's own square lies at
     * least dist px inside the silhouette line, so a dist-px ring is removed along
     * every silhouette and image border (a 20x20 square keeps its central 14x14 at
     * dist 3). This is an erosion by a (2 dist + 1)^2 square. dist is clamped to 0..254. */
    int w = a->w, h = a->h;
    int K = dist < 0 ? 1 : dist > 254 ? 255 : dist + 1;
    for (size_t i = 0; i < (size_t)w * h; i++)
        mask[i] = is_covered(a->coverage[i]) && is_covered(b->coverage[i]) ? (unsigned char)K : 0;
#define M(x, y) ((x) < 0 || (x) >= w || (y) < 0 || (y) >= h ? 0 : (int)mask[(size_t)(y)*w + (x)])
#define RELAX(x, y)                                                                                                    \
    do {                                                                                                               \
        int _n = M(x, y) + 1;                                                                                          \
        if (_n < v) v = _n;                                                                                            \
    } while (0)
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int v = mask[(size_t)y * w + x];
            if (!v) continue;
            RELAX(x - 1, y);
            RELAX(x - 1, y - 1);
            RELAX(x, y - 1);
            RELAX(x + 1, y - 1);
            mask[(size_t)y * w + x] = (unsigned char)v;
        }
    for (int y = h - 1; y >= 0; y--)
        for (int x = w - 1; x >= 0; x--) {
            int v = mask[(size_t)y * w + x];
            if (!v) continue;
            RELAX(x + 1, y);
            RELAX(x + 1, y + 1);
            RELAX(x, y + 1);
            RELAX(x - 1, y + 1);
            mask[(size_t)y * w + x] = (unsigned char)v;
        }
#undef RELAX
#undef M
    for (size_t i = 0; i < (size_t)w * h; i++) mask[i] = mask[i] >= K;
}

void fs_normal_error_map(const fs_gbuffer *a, const fs_gbuffer *b, float *deg)
{
    size_t n = (size_t)a->w * a->h;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
        deg[i] = is_covered(a->coverage[i]) && is_covered(b->coverage[i])
            ? (float)normal_angle_deg(a->normal + 3 * i, b->normal + 3 * i)
            : NAN;
}

void fs_depth_error_map(const fs_gbuffer *a, const fs_gbuffer *b, float r, double bias_r, float *err_r)
{
    size_t n = (size_t)a->w * a->h;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
        err_r[i] = is_covered(a->coverage[i]) && is_covered(b->coverage[i])
            ? (float)fabs(((double)a->depth[i] - b->depth[i]) / r - bias_r)
            : NAN;
}

void fs_srgb_luminance(const float *rgba, int w, int h, float *lum)
{
    /* Rec. 709 weights on the sRGB-encoded (not linear) channels; alpha ignored. */
    size_t n = (size_t)w * h;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
        const float *p = rgba + 4 * i;
        lum[i] = (float)(0.2126 * fs_srgb_encode(p[0]) + 0.7152 * fs_srgb_encode(p[1]) + 0.0722 * fs_srgb_encode(p[2]));
    }
}

/* Mean SSIM following Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality
 * assessment: from error visibility to structural similarity" (eq. 13-16):
 *   SSIM = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2)),
 * local statistics weighted by an 11x11 Gaussian window, sigma 1.5, normalised;
 * C1 = (0.01 L)^2, C2 = (0.03 L)^2, L = 1. At the image borders the window is cut
 * to the pixels inside the image and renormalised to sum 1 (the cut window is a
 * rectangle, so renormalising each separable 1-D pass does exactly that).
 * Local moments come from two separable passes, O(w h 11). The SSIM map covers
 * the full images; its mean is taken over mask != 0 (all pixels if mask is NULL).
 * Returns FS_ERR_RUNTIME when out of memory; *out = NAN without any pixel. */
enum { SSIM_R = 5 }; /* the window's half width: 11x11 */

/* Horizontal pass: mx, my, E[x^2], E[y^2], E[xy] of each pixel's row segment into hp (5 a pixel). */
static void ssim_rows(const float *x, const float *y, int w, int h, const double *g, double *hp)
{
    const int R = SSIM_R;
#pragma omp parallel for schedule(static)
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            int k0 = i - R < 0 ? -i : -R, k1 = i + R >= w ? w - 1 - i : R;
            double sw = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
            for (int k = k0; k <= k1; k++) {
                size_t q = (size_t)j * w + i + k;
                double gk = g[k + R], xv = x[q], yv = y[q];
                sw += gk;
                sx += gk * xv;
                sy += gk * yv;
                sxx += gk * xv * xv;
                syy += gk * yv * yv;
                sxy += gk * xv * yv;
            }
            double *o = hp + 5 * ((size_t)j * w + i);
            o[0] = sx / sw;
            o[1] = sy / sw;
            o[2] = sxx / sw;
            o[3] = syy / sw;
            o[4] = sxy / sw;
        }
}

/* Vertical pass, then the SSIM of each pixel in the mask, summed per row. */
static void ssim_columns(const double *hp, int w, int h, const double *g, const unsigned char *mask, double *row_sum,
                         size_t *row_cnt)
{
    const int R = SSIM_R;
    const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
#pragma omp parallel for schedule(static)
    for (int j = 0; j < h; j++) {
        double rs = 0;
        size_t rc = 0;
        int k0 = j - R < 0 ? -j : -R, k1 = j + R >= h ? h - 1 - j : R;
        double sw = 0;
        for (int k = k0; k <= k1; k++) sw += g[k + R];
        for (int i = 0; i < w; i++) {
            if (mask && !mask[(size_t)j * w + i]) continue;
            double m[5] = {0, 0, 0, 0, 0};
            for (int k = k0; k <= k1; k++) {
                const double *p = hp + 5 * ((size_t)(j + k) * w + i);
                for (int c = 0; c < 5; c++) m[c] += g[k + R] * p[c];
            }
            for (int c = 0; c < 5; c++) m[c] /= sw;
            double mx = m[0], my = m[1];
            double vx = m[2] - mx * mx, vy = m[3] - my * my, cxy = m[4] - mx * my;
            rs += (2 * mx * my + C1) * (2 * cxy + C2) / ((mx * mx + my * my + C1) * (vx + vy + C2));
            rc++;
        }
        row_sum[j] = rs;
        row_cnt[j] = rc;
    }
}

static int ssim_mean(const float *x, const float *y, int w, int h, const unsigned char *mask, double *out)
{
    double g[2 * SSIM_R + 1];
    for (int k = -SSIM_R; k <= SSIM_R; k++) g[k + SSIM_R] = exp(-(k * k) / (2 * 1.5 * 1.5));
    size_t n = (size_t)w * h;
    double *hp = malloc(5 * n * sizeof(double)), *row_sum = malloc((size_t)h * sizeof(double));
    size_t *row_cnt = malloc((size_t)h * sizeof(size_t)), cnt = 0;
    int rc =
        hp && row_sum && row_cnt ? FS_OK : fs_fail(FS_ERR_RUNTIME, "out of memory for SSIM of a %dx%d image", w, h);
    *out = NAN;
    if (!rc) {
        ssim_rows(x, y, w, h, g, hp);
        ssim_columns(hp, w, h, g, mask, row_sum, row_cnt);
        for (int j = 0; j < h; j++) cnt += row_cnt[j];
        *out = cnt ? sum_rows(row_sum, h) / (double)cnt : NAN;
    }
    free(hp);
    free(row_sum);
    free(row_cnt);
    return rc;
}

double fs_ssim(const float *x, const float *y, int w, int h, const unsigned char *mask)
{
    double s;
    if (w <= 0 || h <= 0 || ssim_mean(x, y, w, h, mask, &s) != FS_OK) return NAN;
    return s;
}

/* Scratch buffers of fs_metrics_compute. */
typedef struct metric_scratch {
    double *dd;            /* per pixel: (a - b) / r where both cover */
    double *ang;           /* per pixel: normal angle where both cover */
    double *vals;          /* n_both values for a percentile */
    double *row_a, *row_b; /* per-row partial sums */
    size_t *row_n, *row_u, *row_off;
    unsigned char *both, *uni, *interior;
    float *lum_a, *lum_b;
} metric_scratch;

static void scratch_free(metric_scratch *s)
{
    free(s->dd);
    free(s->ang);
    free(s->vals);
    free(s->row_a);
    free(s->row_b);
    free(s->row_n);
    free(s->row_u);
    free(s->row_off);
    free(s->both);
    free(s->uni);
    free(s->interior);
    free(s->lum_a);
    free(s->lum_b);
}

static int scratch_alloc(metric_scratch *s, int w, int h, int with_rgba)
{
    size_t n = (size_t)w * h;
    memset(s, 0, sizeof *s);
    s->dd = malloc(n * sizeof(double));
    s->ang = malloc(n * sizeof(double));
    s->vals = malloc(n * sizeof(double));
    s->row_a = malloc((size_t)h * sizeof(double));
    s->row_b = malloc((size_t)h * sizeof(double));
    s->row_n = malloc((size_t)h * sizeof(size_t));
    s->row_u = malloc((size_t)h * sizeof(size_t));
    s->row_off = malloc((size_t)h * sizeof(size_t));
    s->both = malloc(n);
    s->uni = malloc(n);
    s->interior = malloc(n);
    if (with_rgba) {
        s->lum_a = malloc(n * sizeof(float));
        s->lum_b = malloc(n * sizeof(float));
    }
    if (!s->dd || !s->ang || !s->vals || !s->row_a || !s->row_b || !s->row_n || !s->row_u || !s->row_off || !s->both ||
        !s->uni || !s->interior || (with_rgba && (!s->lum_a || !s->lum_b))) {
        scratch_free(s);
        return fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", w, h);
    }
    return FS_OK;
}

static int check_gbuffer(const fs_gbuffer *g, const char *which)
{
    if (!g) return fs_fail(FS_ERR_INPUT, "metrics: no G-buffer %s", which);
    if (g->w <= 0 || g->h <= 0 || !g->depth || !g->normal || !g->coverage)
        return fs_fail(FS_ERR_INPUT, "metrics: G-buffer %s is empty or incomplete (%dx%d)", which, g->w, g->h);
    return FS_OK;
}

/* Copies the depth errors d of the pixels both cover into s->vals, in row order,
 * as d (signed) or |d|; counts per row (s->row_a) those with |d| > 1. */
static void gather_depth(int w, int h, metric_scratch *s, int absolute)
{
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++) {
        double *v = s->vals + s->row_off[y], over = 0;
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (!s->both[i]) continue;
            double d = s->dd[i];
            over += fabs(d) > 1;
            *v++ = absolute ? fabs(d) : d;
        }
        s->row_a[y] = over;
    }
}

/* The depth error itself, not around its mean: median of d, percentiles of |d|,
 * the share with |d| > 1 r. A few far outliers move none of these much. */
static void robust_depth_stats(const fs_gbuffer *a, metric_scratch *s, size_t nb, fs_metrics *out)
{
    gather_depth(a->w, a->h, s, 0);
    out->depth_median_r = fs_percentile(s->vals, nb, 50);
    gather_depth(a->w, a->h, s, 1);
    out->depth_abs_p50_r = fs_percentile(s->vals, nb, 50);
    out->depth_abs_p95_r = fs_percentile(s->vals, nb, 95);
    out->depth_abs_p99_r = fs_percentile(s->vals, nb, 99);
    out->depth_over_1r_frac = nb ? sum_rows(s->row_a, a->h) / (double)nb : NAN;
}

/* Pass 1: the masks, each covered pixel's depth error and normal angle, and their row sums. */
static void pixel_errors(const fs_gbuffer *a, const fs_gbuffer *b, float r, metric_scratch *s)
{
    int w = a->w, h = a->h;
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++) {
        double sd = 0, sa = 0;
        size_t nb = 0, nu = 0;
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int ca = is_covered(a->coverage[i]), cb = is_covered(b->coverage[i]);
            s->both[i] = (unsigned char)(ca && cb);
            s->uni[i] = (unsigned char)(ca || cb);
            nu += ca || cb;
            if (!(ca && cb)) continue;
            s->dd[i] = ((double)a->depth[i] - b->depth[i]) / r;
            s->ang[i] = normal_angle_deg(a->normal + 3 * i, b->normal + 3 * i);
            sd += s->dd[i];
            sa += s->ang[i];
            nb++;
        }
        s->row_a[y] = sd;
        s->row_b[y] = sa;
        s->row_n[y] = nb;
        s->row_u[y] = nu;
    }
}

/* Pass 2: the depth error around the bias (RMS, and |.| for its percentile). */
static void depth_spread(int w, int h, double bias, metric_scratch *s, size_t nb, fs_metrics *out)
{
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++) {
        double sq = 0;
        double *v = s->vals + s->row_off[y];
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (!s->both[i]) continue;
            double e = s->dd[i] - bias;
            sq += e * e;
            *v++ = fabs(e);
        }
        s->row_a[y] = sq;
    }
    out->depth_rmse_r = nb ? sqrt(sum_rows(s->row_a, h) / (double)nb) : NAN;
    out->depth_p95_r = fs_percentile(s->vals, nb, 95);
}

/* Pass 3: the angles for their percentile. */
static void angle_p95(int w, int h, metric_scratch *s, size_t nb, fs_metrics *out)
{
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++) {
        double *v = s->vals + s->row_off[y];
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (s->both[i]) *v++ = s->ang[i];
        }
    }
    out->normal_p95_deg = fs_percentile(s->vals, nb, 95);
}

/* Depth and normal statistics over the pixels both cover. */
static void depth_normal_stats(const fs_gbuffer *a, const fs_gbuffer *b, float r, metric_scratch *s, fs_metrics *out)
{
    int w = a->w, h = a->h;
    pixel_errors(a, b, r, s);
    size_t nb = 0, nu = 0;
    for (int y = 0; y < h; y++) {
        s->row_off[y] = nb;
        nb += s->row_n[y];
        nu += s->row_u[y];
    }
    out->n_both = nb;
    out->n_union = nu;
    out->mask_iou = nu ? (double)nb / (double)nu : 1.0;
    double bias = nb ? sum_rows(s->row_a, h) / (double)nb : NAN;
    out->depth_bias_r = bias;
    out->normal_mean_deg = nb ? sum_rows(s->row_b, h) / (double)nb : NAN;
    depth_spread(w, h, bias, s, nb, out);
    robust_depth_stats(a, s, nb, out);
    angle_p95(w, h, s, nb, out);
}

static void interior_stats(const fs_gbuffer *a, const fs_gbuffer *b, metric_scratch *s, fs_metrics *out)
{
    int w = a->w, h = a->h;
    fs_interior_mask(a, b, INTERIOR_DIST, s->interior);
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++) {
        double sa = 0;
        size_t ni = 0;
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (!s->interior[i]) continue;
            sa += s->ang[i];
            ni++;
        }
        s->row_a[y] = sa;
        s->row_n[y] = ni;
    }
    size_t ni = 0;
    for (int y = 0; y < h; y++) ni += s->row_n[y];
    out->n_interior = ni;
    out->interior_normal_mean_deg = ni ? sum_rows(s->row_a, h) / (double)ni : NAN;
}

/* PSNR and SSIM of the sRGB luminance over the union of the masks. */
static int image_stats(const float *rgba_a, const float *rgba_b, int w, int h, metric_scratch *s, fs_metrics *out)
{
    fs_srgb_luminance(rgba_a, w, h, s->lum_a);
    fs_srgb_luminance(rgba_b, w, h, s->lum_b);
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++) {
        double sq = 0;
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            if (!s->uni[i]) continue;
            double e = (double)s->lum_a[i] - s->lum_b[i];
            sq += e * e;
        }
        s->row_a[y] = sq;
    }
    if (out->n_union == 0) out->psnr_db = NAN;
    else {
        double mse = sum_rows(s->row_a, h) / (double)out->n_union;
        out->psnr_db = mse == 0 ? INFINITY : 10.0 * log10(1.0 / mse);
    }
    return ssim_mean(s->lum_a, s->lum_b, w, h, s->uni, &out->ssim);
}

int fs_metrics_compute(const fs_gbuffer *a, const float *rgba_a, const fs_gbuffer *b, const float *rgba_b, float r,
                       fs_metrics *out)
{
    int rc;
    if ((rc = check_gbuffer(a, "a")) || (rc = check_gbuffer(b, "b"))) return rc;
    if (a->w != b->w || a->h != b->h)
        return fs_fail(FS_ERR_INPUT, "metrics: image sizes differ (%dx%d vs %dx%d)", a->w, a->h, b->w, b->h);
    if (!(r > 0) || !isfinite(r)) return fs_fail(FS_ERR_INPUT, "metrics: particle radius %g is not positive", r);
    if (!out) return fs_fail(FS_ERR_INPUT, "metrics: no output");
    int with_rgba = rgba_a && rgba_b;
    metric_scratch s;
    if ((rc = scratch_alloc(&s, a->w, a->h, with_rgba))) return rc;
    fs_metrics m;
    memset(&m, 0, sizeof m);
    depth_normal_stats(a, b, r, &s, &m);
    interior_stats(a, b, &s, &m);
    m.psnr_db = m.ssim = NAN;
    if (with_rgba && (rc = image_stats(rgba_a, rgba_b, a->w, a->h, &s, &m))) {
        scratch_free(&s);
        return rc;
    }
    scratch_free(&s);
    *out = m;
    return FS_OK;
}
