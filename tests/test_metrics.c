/* Metrics against constructed G-buffers and images with known answers. */
#include "fs_error.h"
#include "fs_test.h"
#include "gbuffer.h"
#include "srgb.h"
#include "metrics.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64
#define N (W * H)
#define PI 3.14159265358979323846
static const float R_PART = 0.25f; /* particle radius r */

static fs_gbuffer new_gbuf(void)
{
    fs_gbuffer g;
    if (fs_gbuffer_alloc(&g, W, H) != FS_OK) {
        fprintf(stderr, "%s\n", fs_error_message());
        exit(1);
    }
    return g;
}

static void set_px(fs_gbuffer *g, int x, int y, double depth, const double n[3])
{
    size_t i = (size_t)y * W + x;
    g->coverage[i] = 1;
    g->depth[i] = (float)depth;
    for (int c = 0; c < 3; c++) g->normal[3 * i + c] = (float)n[c];
}

static int in_disk(int x, int y, double cx, double cy, double rad)
{
    return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= rad * rad;
}

/* A hemisphere of radius 20 px (eye depth 5 - 0.05 height) at (cx, cy). */
static void fill_sphere(fs_gbuffer *g, double cx, double cy)
{
    const double rad = 20;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            if (!in_disk(x, y, cx, cy, rad)) continue;
            double dx = (x - cx) / rad, dy = (y - cy) / rad, dz = sqrt(fmax(0, 1 - dx * dx - dy * dy));
            double n[3] = {dx, dy, dz};
            set_px(g, x, y, 5 - 0.05 * rad * dz, n);
        }
}

static void copy_gbuf(fs_gbuffer *dst, const fs_gbuffer *src)
{
    memcpy(dst->depth, src->depth, N * sizeof(float));
    memcpy(dst->normal, src->normal, 3 * N * sizeof(float));
    memcpy(dst->coverage, src->coverage, N * sizeof(float));
}

/* Deterministic texture in 0..1 (sines plus a hash), linear grey RGBA. */
static double texture(int x, int y)
{
    unsigned h = (unsigned)(x * 73856093u) ^ (unsigned)(y * 19349663u);
    h = (h ^ (h >> 13)) * 1274126177u;
    return 0.5 + 0.25 * sin(0.4 * x) * cos(0.3 * y) + 0.1 * ((h & 1023) / 1023.0 - 0.5);
}

static void fill_grey(float *rgba, int x, int y, float linear)
{
    float *p = rgba + 4 * ((size_t)y * W + x);
    p[0] = p[1] = p[2] = linear;
    p[3] = 1;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Nearest-rank 95th percentile by sorting (independent of the library's quickselect). */
static double p95_sorted(double *v, size_t n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return v[(size_t)ceil(0.95 * n - 1e-9) - 1];
}

/* Nearest-rank pct-th percentile by sorting: the ceil(pct n / 100)-th smallest. */
static double pct_sorted(double *v, size_t n, int pct)
{
    qsort(v, n, sizeof *v, cmp_double);
    return v[((size_t)pct * n + 99) / 100 - 1];
}

static size_t count_covered(const fs_gbuffer *g)
{
    size_t c = 0;
    for (size_t i = 0; i < N; i++) c += g->coverage[i] > 0.5f;
    return c;
}

static void test_identical(void)
{
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    fill_sphere(&a, 30, 33);
    copy_gbuf(&b, &a);
    float *img = malloc(4 * N * sizeof(float)), *img2 = malloc(4 * N * sizeof(float));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) fill_grey(img, x, y, (float)texture(x, y));
    memcpy(img2, img, 4 * N * sizeof(float));
    fs_metrics m;
    CHECK(fs_metrics_compute(&a, img, &b, img2, R_PART, &m) == FS_OK, "%s", fs_error_message());
    size_t n = count_covered(&a);
    CHECK(n > 1000 && m.n_both == n && m.n_union == n, "n_both %zu n_union %zu, disk %zu", m.n_both, m.n_union, n);
    CHECK(m.mask_iou == 1, "IoU %g", m.mask_iou);
    CHECK(m.depth_bias_r == 0 && m.depth_rmse_r == 0 && m.depth_p95_r == 0, "depth %g %g %g", m.depth_bias_r,
          m.depth_rmse_r, m.depth_p95_r);
    CHECK(m.normal_mean_deg == 0 && m.normal_p95_deg == 0 && m.interior_normal_mean_deg == 0, "normal %g %g %g",
          m.normal_mean_deg, m.normal_p95_deg, m.interior_normal_mean_deg);
    CHECK(m.n_interior > 0 && m.n_interior < n, "n_interior %zu", m.n_interior);
    CHECK(isinf(m.psnr_db) && m.psnr_db > 0, "PSNR %g", m.psnr_db);
    CHECK_NEAR(m.ssim, 1, 1e-12, "SSIM of identical images");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    free(img);
    free(img2);
}

static void test_depth_offset(void)
{
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    fill_sphere(&a, 32, 32);
    copy_gbuf(&b, &a);
    for (size_t i = 0; i < N; i++)
        if (a.coverage[i] > 0) b.depth[i] = a.depth[i] + 0.3f * R_PART;
    fs_metrics m;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK_NEAR(m.depth_bias_r, -0.3, 1e-5, "depth bias (a - b) of b = a + 0.3 r");
    CHECK(m.depth_rmse_r < 1e-5 && m.depth_p95_r < 1e-5, "error around the bias: rmse %g p95 %g", m.depth_rmse_r,
          m.depth_p95_r);
    CHECK(m.normal_mean_deg == 0, "normals unchanged: %g", m.normal_mean_deg);
    CHECK(isnan(m.psnr_db) && isnan(m.ssim), "no images: PSNR %g SSIM %g", m.psnr_db, m.ssim);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

/* a - b = (0.2 + 0.01 (k - 49.5)) r over a 10x10 square, k = 0..99 row-major. */
static void test_depth_spread(void)
{
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    double n[3] = {0, 0, 1}, e[100];
    for (int k = 0; k < 100; k++) {
        int x = 5 + k % 10, y = 7 + k / 10;
        e[k] = 0.01 * (k - 49.5);
        double da = 3 + 0.01 * x;
        set_px(&a, x, y, da, n);
        set_px(&b, x, y, (float)da - (0.2 + e[k]) * R_PART, n);
    }
    fs_metrics m;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    double sq = 0, ae[100];
    for (int k = 0; k < 100; k++) sq += e[k] * e[k], ae[k] = fabs(e[k]);
    CHECK(m.n_both == 100, "n_both %zu", m.n_both);
    CHECK_NEAR(m.depth_bias_r, 0.2, 1e-5, "bias");
    CHECK_NEAR(m.depth_rmse_r, sqrt(sq / 100), 1e-5, "rmse around the bias");
    CHECK_NEAR(m.depth_p95_r, p95_sorted(ae, 100), 1e-5, "p95 of |error - bias| (nearest rank)");
    float *map = malloc(N * sizeof(float));
    fs_depth_error_map(&a, &b, R_PART, m.depth_bias_r, map);
    int bad = 0;
    for (int k = 0; k < 100; k++) bad += fabs(map[(7 + k / 10) * W + 5 + k % 10] - fabs(e[k])) > 1e-5;
    CHECK(bad == 0, "%d depth-map pixels differ from |error - bias|", bad);
    CHECK(isnan(map[0]) && isnan(map[N - 1]), "depth map is NAN where not both cover");
    free(map);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

/* Issue 32's constructed case: a tilted plane of 50 x 50 px whose errors spread
 * within +-0.004 r, with 0.2% of its pixels (5 of 2500) moved 50 r. The outliers
 * pull the mean to ~0.1 r, so bias and depth_p95_r (around the mean) read their
 * pull; the median, the percentiles of |e| and the share over 1 r read the plane. */
static void test_depth_outliers(void)
{
    enum { S = 50, NP = S * S, NOUT = 5 };
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    double n[3] = {0, 0, 1}, d[NP], ad[NP];
    for (int k = 0; k < NP; k++) {
        int x = 7 + k % S, y = 5 + k / S;
        double db = 3 + 0.01 * x + 0.005 * y, e = 0.004 * sin(1.7 * k) * R_PART;
        if (k % (NP / NOUT) == 250) e = 50 * R_PART; /* 5 outliers spread over the plane */
        set_px(&b, x, y, db, n);
        set_px(&a, x, y, db + e, n);
        size_t i = (size_t)y * W + x;
        d[k] = ((double)a.depth[i] - b.depth[i]) / R_PART;
        ad[k] = fabs(d[k]);
    }
    fs_metrics m;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK(m.n_both == NP, "n_both %zu", m.n_both);
    printf("outliers: bias %.6g rmse %.6g p95 %.6g | median %.3g abs p50 %.3g p95 %.3g p99 %.3g over_1r %.6g\n",
           m.depth_bias_r, m.depth_rmse_r, m.depth_p95_r, m.depth_median_r, m.depth_abs_p50_r, m.depth_abs_p95_r,
           m.depth_abs_p99_r, m.depth_over_1r_frac);
    /* what the outliers move: the mean, and the spread around it */
    CHECK_NEAR(m.depth_bias_r, 0.1, 1e-3, "bias pulled to 5 x 50 r / 2500 = 0.1 r");
    CHECK(m.depth_p95_r > 0.095 && m.depth_p95_r < 0.105, "depth_p95_r reads the pull, |0 - bias|: %g", m.depth_p95_r);
    CHECK(m.depth_rmse_r > 2, "rmse %g", m.depth_rmse_r);
    /* what they do not move */
    CHECK(fabs(m.depth_median_r) < 0.005 && m.depth_abs_p50_r < 0.005 && m.depth_abs_p95_r < 0.005 &&
              m.depth_abs_p99_r < 0.005,
          "median %g, |e| p50 %g p95 %g p99 %g: not within the plane's 0.005 r", m.depth_median_r, m.depth_abs_p50_r,
          m.depth_abs_p95_r, m.depth_abs_p99_r);
    CHECK(m.depth_over_1r_frac == (double)NOUT / NP, "over_1r_frac %g, want %g", m.depth_over_1r_frac,
          (double)NOUT / NP);
    /* each exactly the nearest-rank value of the sorted errors */
    CHECK_NEAR(m.depth_abs_p50_r, pct_sorted(ad, NP, 50), 1e-12, "|e| p50 (nearest rank)");
    CHECK_NEAR(m.depth_abs_p95_r, pct_sorted(ad, NP, 95), 1e-12, "|e| p95 (nearest rank)");
    CHECK_NEAR(m.depth_abs_p99_r, pct_sorted(ad, NP, 99), 1e-12, "|e| p99 (nearest rank)");
    CHECK_NEAR(m.depth_median_r, pct_sorted(d, NP, 50), 1e-12, "median of the signed error (nearest rank)");
    CHECK(m.depth_median_r != m.depth_abs_p50_r, "median %g is signed, |e| p50 %g is not", m.depth_median_r,
          m.depth_abs_p50_r);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

static void rotate(const double v[3], const double u[3], double ang, double out[3])
{
    /* Rodrigues: v cos + (u x v) sin + u (u.v)(1 - cos) */
    double c = cos(ang), s = sin(ang), d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int i = 0; i < 3; i++) out[i] = v[i] * c + x[i] * s + u[i] * d * (1 - c);
}

/* Normals in the plane perpendicular to the axis u, varying over the image, rotated
 * about u by ang_of(x, y) degrees in b. */
static void fill_rotated(fs_gbuffer *a, fs_gbuffer *b, int x0, int y0, int x1, int y1, double (*ang_of)(int, int))
{
    double u[3] = {1 / sqrt(14), 2 / sqrt(14), 3 / sqrt(14)};
    double e1[3] = {2 / sqrt(5), -1 / sqrt(5), 0}; /* perpendicular to u */
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double na[3], nb[3];
            rotate(e1, u, 0.05 * x + 0.03 * y, na); /* still perpendicular to u */
            rotate(na, u, ang_of(x, y) * PI / 180, nb);
            set_px(a, x, y, 4, na);
            set_px(b, x, y, 4, nb);
        }
}

static double ang_10(int x, int y)
{
    (void)x, (void)y;
    return 10;
}
static double ang_col(int x, int y)
{
    (void)y;
    return 0.5 * (x - 4);
}
static double ang_ring(int x, int y) { return x >= 13 && x < 27 && y >= 13 && y < 27 ? 10 : 30; }

static void test_normal_rotation(void)
{
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    fill_rotated(&a, &b, 8, 8, 56, 50, ang_10);
    fs_metrics m;
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK_NEAR(m.normal_mean_deg, 10, 1e-3, "mean angle of a 10 deg rotation");
    CHECK_NEAR(m.normal_p95_deg, 10, 1e-3, "p95 angle of a 10 deg rotation");
    CHECK_NEAR(m.interior_normal_mean_deg, 10, 1e-3, "interior mean angle");
    CHECK(m.n_interior == (48 - 6) * (42 - 6), "n_interior %zu", m.n_interior);
    float *map = malloc(N * sizeof(float));
    fs_normal_error_map(&a, &b, map);
    CHECK_NEAR(map[20 * W + 20], 10, 1e-3, "normal error map inside");
    CHECK(isnan(map[0]), "normal error map outside: %g", map[0]);
    free(map);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);

    /* angle 0.5 (x - 4) deg on 40 columns x 10 rows: mean and nearest-rank p95 */
    a = new_gbuf(), b = new_gbuf();
    fill_rotated(&a, &b, 4, 20, 44, 30, ang_col);
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    double v[400], sum = 0;
    for (int k = 0; k < 400; k++) v[k] = ang_col(4 + k % 40, 0), sum += v[k];
    CHECK_NEAR(m.normal_mean_deg, sum / 400, 1e-3, "mean of a column ramp of angles");
    CHECK_NEAR(m.normal_p95_deg, p95_sorted(v, 400), 1e-3, "p95 of a column ramp of angles");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);

    /* 30 deg in the 3-px ring of a 20x20 square, 10 deg inside: the interior mean sees 10 */
    a = new_gbuf(), b = new_gbuf();
    fill_rotated(&a, &b, 10, 10, 30, 30, ang_ring);
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK(m.n_interior == 196, "n_interior %zu", m.n_interior);
    CHECK_NEAR(m.interior_normal_mean_deg, 10, 1e-3, "interior mean excludes the ring");
    CHECK_NEAR(m.normal_mean_deg, (196 * 10.0 + 204 * 30.0) / 400, 1e-3, "mean over both");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

static void fill_rect(fs_gbuffer *g, int x0, int y0, int x1, int y1)
{
    double n[3] = {0, 0, 1};
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) set_px(g, x, y, 2 + 0.01 * y, n);
}

static void test_masks(void)
{
    float *img_a = calloc(4 * N, sizeof(float)), *img_b = calloc(4 * N, sizeof(float));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) fill_grey(img_a, x, y, (float)texture(x, y)), fill_grey(img_b, x, y, 0.2f);
    fs_metrics m;
    /* disjoint halves */
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    fill_rect(&a, 0, 0, W / 2, H);
    fill_rect(&b, W / 2, 0, W, H);
    CHECK(fs_metrics_compute(&a, img_a, &b, img_b, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK(m.mask_iou == 0 && m.n_both == 0 && m.n_union == N && m.n_interior == 0, "disjoint: IoU %g n %zu %zu %zu",
          m.mask_iou, m.n_both, m.n_union, m.n_interior);
    CHECK(isnan(m.depth_bias_r) && isnan(m.depth_rmse_r) && isnan(m.depth_p95_r), "disjoint depth not NAN");
    CHECK(isnan(m.depth_median_r) && isnan(m.depth_abs_p50_r) && isnan(m.depth_abs_p95_r) && isnan(m.depth_abs_p99_r) &&
              isnan(m.depth_over_1r_frac),
          "disjoint robust depth not NAN");
    CHECK(isnan(m.normal_mean_deg) && isnan(m.normal_p95_deg) && isnan(m.interior_normal_mean_deg),
          "disjoint normals not NAN");
    CHECK(isfinite(m.psnr_db) && isfinite(m.ssim) && m.ssim < 1, "disjoint PSNR %g SSIM %g", m.psnr_db, m.ssim);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);

    /* overlapping rectangles: |A and B| = 20 x 15, |A or B| = 2 * 900 - 300 */
    a = new_gbuf(), b = new_gbuf();
    fill_rect(&a, 10, 10, 40, 40);
    fill_rect(&b, 20, 25, 50, 55);
    CHECK(fs_metrics_compute(&a, NULL, &b, NULL, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK(m.n_both == 300 && m.n_union == 1500, "overlap counts %zu %zu", m.n_both, m.n_union);
    CHECK_NEAR(m.mask_iou, 300.0 / 1500.0, 1e-15, "IoU of overlapping rectangles");
    CHECK(m.depth_bias_r == 0 && m.normal_mean_deg == 0, "same depth/normal where both cover");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);

    /* both empty */
    a = new_gbuf(), b = new_gbuf();
    CHECK(fs_metrics_compute(&a, img_a, &b, img_b, R_PART, &m) == FS_OK, "%s", fs_error_message());
    CHECK(m.mask_iou == 1 && m.n_both == 0 && m.n_union == 0, "empty: IoU %g", m.mask_iou);
    CHECK(isnan(m.depth_bias_r) && isnan(m.normal_mean_deg) && isnan(m.psnr_db) && isnan(m.ssim),
          "empty masks give NAN metrics");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    free(img_a);
    free(img_b);
}

/* Brute-force interior: both cover every pixel of the (2 dist + 1)^2 window, the
 * window inside the image. */
static int brute_interior(const fs_gbuffer *a, const fs_gbuffer *b, int dist, int x, int y)
{
    for (int dy = -dist; dy <= dist; dy++)
        for (int dx = -dist; dx <= dist; dx++) {
            int u = x + dx, v = y + dy;
            if (u < 0 || u >= W || v < 0 || v >= H) return 0;
            if (!(a->coverage[v * W + u] > 0.5f && b->coverage[v * W + u] > 0.5f)) return 0;
        }
    return 1;
}

static void test_interior(void)
{
    unsigned char *mask = malloc(N);
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    fill_rect(&a, 10, 10, 30, 30);
    fill_rect(&b, 10, 10, 30, 30);
    fill_rect(&a, 40, 40, 60, 60); /* covered by a only: never interior */
    fill_rect(&a, 0, 40, 20, 64);  /* touches the left and bottom borders */
    fill_rect(&b, 0, 40, 20, 64);
    fs_interior_mask(&a, &b, 3, mask);
    int wrong = 0, count = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int expect = (x >= 13 && x < 27 && y >= 13 && y < 27) || (x >= 3 && x < 17 && y >= 43 && y < 61);
            wrong += mask[y * W + x] != expect;
            count += mask[y * W + x] != 0;
        }
    CHECK(wrong == 0 && count == 196 + 14 * 18, "interior of squares: %d wrong pixels, %d interior", wrong, count);

    /* random blobs against brute-force erosion, several distances */
    fs_gbuffer_clear(&a);
    fs_gbuffer_clear(&b);
    unsigned s = 12345;
    double n[3] = {0, 0, 1};
    for (int k = 0; k < 12; k++) {
        s = s * 1103515245u + 12345u;
        double cx = (s >> 8) % W, cy = (s >> 20) % H, rad = 4 + (s >> 3) % 13;
        fs_gbuffer *g = k % 3 == 2 ? &b : &a;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                if (in_disk(x, y, cx, cy, rad)) set_px(g, x, y, 1, n);
    }
    for (size_t i = 0; i < N; i++) /* b covers a too, minus its own disks' holes */
        if (a.coverage[i] > 0 && !(b.coverage[i] > 0) && (i % 7)) set_px(&b, (int)(i % W), (int)(i / W), 1, n);
    for (int dist = 0; dist <= 5; dist++) {
        fs_interior_mask(&a, &b, dist, mask);
        int bad = 0, cnt = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                bad += mask[y * W + x] != brute_interior(&a, &b, dist, x, y);
                cnt += mask[y * W + x];
            }
        CHECK(bad == 0 && (dist == 5 || cnt > 0), "dist %d: %d pixels differ from brute force (%d interior)", dist, bad,
              cnt);
    }
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    free(mask);
}

static void test_ssim(void)
{
    float *x = malloc(N * sizeof(float)), *y = malloc(N * sizeof(float));
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) x[j * W + i] = (float)texture(i, j);
    /* contrast reduction about 0.5: SSIM < 1 and decreasing with more reduction */
    double prev = 1;
    const double scales[] = {0.8, 0.5, 0.2};
    for (int k = 0; k < 3; k++) {
        for (int q = 0; q < N; q++) y[q] = (float)(0.5 + scales[k] * (x[q] - 0.5));
        double s = fs_ssim(x, y, W, H, NULL);
        CHECK(s < prev - 1e-3 && s > 0, "contrast %g: SSIM %g (previous %g)", scales[k], s, prev);
        CHECK_NEAR(fs_ssim(y, x, W, H, NULL), s, 1e-12, "SSIM is symmetric");
        prev = s;
    }
    /* constant images: SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1) at every pixel,
     * border pixels included (renormalised window) */
    const double c1 = 0.3, c2 = 0.6, C1 = 1e-4;
    for (int q = 0; q < N; q++) x[q] = (float)c1, y[q] = (float)c2;
    double mx = (float)c1, my = (float)c2, expect = (2 * mx * my + C1) / (mx * mx + my * my + C1);
    CHECK_NEAR(fs_ssim(x, y, W, H, NULL), expect, 1e-9, "SSIM of constant images");
    unsigned char *mask = calloc(N, 1);
    for (int j = 0; j < H; j++) mask[j * W] = 1; /* left column only */
    mask[0] = mask[W - 1] = 1;                   /* and two corners */
    CHECK_NEAR(fs_ssim(x, y, W, H, mask), expect, 1e-9, "SSIM of constant images at the borders");
    /* mask: images equal on the left, different from column 32 on: a mask of
     * columns < 26 (beyond the 5-px window) sees SSIM 1 */
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            x[j * W + i] = (float)texture(i, j);
            y[j * W + i] = i < 32 ? x[j * W + i] : 1 - x[j * W + i];
            mask[j * W + i] = i < 26;
        }
    CHECK_NEAR(fs_ssim(x, y, W, H, mask), 1, 1e-12, "SSIM over a mask away from the differences");
    CHECK(fs_ssim(x, y, W, H, NULL) < 0.9, "SSIM over the whole image sees the differences");
    memset(mask, 0, N);
    CHECK(isnan(fs_ssim(x, y, W, H, mask)), "SSIM over an empty mask is NAN");
    free(mask);
    free(x);
    free(y);
}

static void test_psnr(void)
{
    /* luminance: Rec. 709 weights on sRGB-encoded channels */
    float px[4 * 5] = {1, 0, 0, 1, 0, 1, 0, 1, 0.5f, 0.5f, 0.5f, 1, 2, 2, 2, 1, -1, NAN, -1, 1};
    float lum[5];
    fs_srgb_luminance(px, 5, 1, lum);
    CHECK_NEAR(lum[0], 0.2126, 1e-6, "luminance of linear red");
    CHECK_NEAR(lum[1], 0.7152, 1e-6, "luminance of linear green");
    CHECK_NEAR(lum[2], fs_srgb_encode8(0.5f) / 255.0, 0.5 / 255, "luminance of linear grey 0.5");
    CHECK(lum[3] == 1 && lum[4] == 0, "clamped luminance %g %g", lum[3], lum[4]);
    int bad = 0;
    for (int c = 0; c < 256; c++) bad += fabs(fs_srgb_encode(fs_srgb_decode8((unsigned char)c)) - c / 255.0) > 1e-6;
    CHECK(bad == 0, "fs_srgb_encode inverts fs_srgb_decode8 for %d codes", 256 - bad);

    /* a uniform offset of 10 codes over the union; outside it anything goes */
    fs_gbuffer a = new_gbuf(), b = new_gbuf();
    fill_sphere(&a, 26, 30);
    fill_sphere(&b, 36, 34);
    float *img_a = malloc(4 * N * sizeof(float)), *img_b = malloc(4 * N * sizeof(float));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int in = in_disk(x, y, 26, 30, 20) || in_disk(x, y, 36, 34, 20);
            fill_grey(img_a, x, y, fs_srgb_decode8(100));
            fill_grey(img_b, x, y, in ? fs_srgb_decode8(110) : 1.0f);
        }
    fs_metrics m;
    CHECK(fs_metrics_compute(&a, img_a, &b, img_b, R_PART, &m) == FS_OK, "%s", fs_error_message());
    double off = 10 / 255.0;
    CHECK_NEAR(m.psnr_db, 10 * log10(1 / (off * off)), 1e-3, "PSNR of a uniform luminance offset");
    CHECK(m.ssim < 1, "SSIM of an offset %g", m.ssim);
    CHECK(m.mask_iou > 0 && m.mask_iou < 1, "IoU of shifted disks %g", m.mask_iou);
    free(img_a);
    free(img_b);
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
}

static void test_bad_input(void)
{
    fs_gbuffer a = new_gbuf(), c;
    CHECK(fs_gbuffer_alloc(&c, W, H / 2) == FS_OK, "alloc");
    fs_metrics m;
    memset(&m, 0x55, sizeof m);
    fs_metrics before = m;
    CHECK(fs_metrics_compute(&a, NULL, &c, NULL, R_PART, &m) == FS_ERR_INPUT, "size mismatch accepted");
    CHECK(strstr(fs_error_message(), "sizes differ") != NULL, "message: %s", fs_error_message());
    CHECK(fs_metrics_compute(&a, NULL, &a, NULL, 0, &m) == FS_ERR_INPUT, "r = 0 accepted");
    CHECK(fs_metrics_compute(&a, NULL, &a, NULL, NAN, &m) == FS_ERR_INPUT, "r = NaN accepted");
    CHECK(memcmp(&m, &before, sizeof m) == 0, "failed calls wrote their output");
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&c);
}

int main(void)
{
    test_identical();
    test_depth_offset();
    test_depth_spread();
    test_depth_outliers();
    test_normal_rotation();
    test_masks();
    test_interior();
    test_ssim();
    test_psnr();
    test_bad_input();
    TEST_DONE();
}
