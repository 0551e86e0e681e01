/* fluidsurf diff A.exr B.exr: the compare metrics between two outputs that can be
 * compared (diff_check.c), as text or JSON (diff_print.c), the heatmaps with -o,
 * and an exit status for regression checks (3 when a threshold is crossed). */
#include "cli.h"
#include "diff.h"
#include "diff_panel.h"
#include "fs_error.h"
#include "obstacle_mask.h"
#include "options.h"
#include "output_file.h"
#include "render_output.h"
#include "stats.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* what --help says after the options */
static const char epilogue[] = "Prints the metrics of A against B (B is the reference), named as metrics.csv's\n"
                               "columns: depth_bias_r, depth_rmse_r and depth_p95_r measure around the mean error;\n"
                               "depth_median_r, depth_abs_p50/p95/p99_r and depth_over_1r_frac the error itself,\n"
                               "which a few far outliers barely move. The EXRs must be comparable: a different\n"
                               "size or camera (fluidsurf:camera) is refused (exit 2); a different scene\n"
                               "(fluidsurf:scene_hash) or r (fluidsurf:r), or provenance that cannot tell, gives\n"
                               "a warning, or with --strict a refusal. Exits 3 when a --fail-* threshold is\n"
                               "crossed, 0 otherwise. Where the EXRs carry the solids' depth (the solid_depth\n"
                               "layer fluidsurf writes for a scene with solids; B's, else A's), the pixels a\n"
                               "solid hides are left out as compare leaves them out, and a line says how many.\n";

typedef struct diff_opts {
    float fail_iou, fail_normal, fail_depth, fail_ssim, fail_psnr, fail_interior, fail_p95, radius, nscale, dscale;
    int strict, json;
    const char *out;
} diff_opts;

/* A metric that must stay at or above (low = 1) or at or below a threshold
 * (a negative threshold: not asked). */
static void gate(diff_fail *fails, int *n, const char *name, double value, double limit, int low)
{
    if (limit < 0 || (low ? value >= limit : value <= limit)) return;
    snprintf(fails[(*n)++].text, sizeof fails->text, "%s %s %g", name, low ? "<" : ">", limit);
}

/* The thresholds crossed; a NAN metric (nothing to compare) never passes a threshold that asks for it. */
static int thresholds(const diff_opts *o, const fs_metrics *m, diff_fail *fails)
{
    int n = 0;
    gate(fails, &n, "mask_iou", m->mask_iou, o->fail_iou, 1);
    gate(fails, &n, "normal_mean_deg", m->normal_mean_deg, o->fail_normal, 0);
    if (o->fail_depth >= 0 && !(fabs(m->depth_bias_r) <= o->fail_depth && m->depth_rmse_r <= o->fail_depth))
        snprintf(fails[n++].text, sizeof fails->text, "|depth_bias_r| or depth_rmse_r > %g", o->fail_depth);
    gate(fails, &n, "ssim", m->ssim, o->fail_ssim, 1);
    gate(fails, &n, "psnr_db", m->psnr_db, o->fail_psnr, 1);
    gate(fails, &n, "interior_normal_mean_deg", m->interior_normal_mean_deg, o->fail_interior, 0);
    gate(fails, &n, "depth_abs_p95_r", m->depth_abs_p95_r, o->fail_p95, 0);
    return n;
}

/* -o FILE.png: compare's heatmaps, scaled as compare scales them by default. */
static int write_heatmaps(const diff_opts *o, const char *const files[2], const fs_gbuffer g[2], float r,
                          const fs_metrics *m)
{
    double ns = o->nscale > 0 ? o->nscale : fs_nice_ceil(m->normal_p95_deg > 0 ? m->normal_p95_deg : 10);
    double ds = o->dscale > 0 ? o->dscale : fs_nice_ceil(m->depth_p95_r > 0 ? m->depth_p95_r : 1);
    char title[2 * 600];
    snprintf(title, sizeof title, "%s against %s", files[0], files[1]);
    return fs_write_diff_panel(o->out, &g[0], &g[1], r, m->depth_bias_r, ns, ds, title);
}

/* Reads, checks and measures; prints; 0, 3 (a threshold crossed) or an error code. */
static int run_diff(const diff_opts *o, const char *const files[2], fs_gbuffer g[2], float *rgba[2])
{
    float r[2] = {0, 0};
    int rc = fs_read_render(files[0], &g[0], &rgba[0], &r[0]);
    if (!rc) rc = fs_read_render(files[1], &g[1], &rgba[1], &r[1]);
    if (!rc) rc = diff_check_comparable(files, g, r, o->strict, o->radius > 0);
    float rr = o->radius > 0 ? o->radius : r[0] > 0 ? r[0] : r[1];
    if (!rc && !(rr > 0)) rc = fs_fail(FS_ERR_INPUT, "%s: no fluidsurf:r attribute; give --radius", files[0]);
    fs_metrics m;
    long masked = -1; /* -1: neither file carries the solids' depth */
    if (!rc) {
        const float *solids = fs_gbuffer_aov(&g[1], FS_AOV_SOLID_DEPTH);
        if (!solids) solids = fs_gbuffer_aov(&g[0], FS_AOV_SOLID_DEPTH);
        rc = fs_metrics_compute_masked(solids, &g[0], rgba[0], &g[1], rgba[1], rr, &m, &masked);
        if (!solids) masked = -1;
    }
    if (!rc && o->out) rc = write_heatmaps(o, files, g, rr, &m);
    if (rc) return rc;
    diff_fail fails[DIFF_GATES];
    int nfails = thresholds(o, &m, fails);
    if (o->json) diff_print_json(stdout, files, rr, masked, &m, fails, nfails);
    else diff_print_text(stdout, files, rr, masked, &m, fails, nfails);
    return nfails ? FS_ERR_DIFF : FS_OK;
}

int cmd_diff(int argc, char **argv)
{
    const char *files[2] = {NULL, NULL};
    diff_opts o = {-1, -1, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, NULL};
    int nfiles = 0, rc;
    const cli_opt opts[] = {
        CLI_FLOAT_OPT("--fail-iou", o.fail_iou, 0, 1, "X", "exit 3 when the mask IoU is below X"),
        CLI_FLOAT_OPT("--fail-normal-deg", o.fail_normal, 0, 180, "Y",
                      "exit 3 when the mean normal angle exceeds Y degrees"),
        CLI_FLOAT_OPT("--fail-depth-r", o.fail_depth, 0, 1e9, "Z",
                      "exit 3 when |depth bias| or depth RMSE exceeds Z r"),
        CLI_FLOAT_OPT(
            "--fail-depth-p95-r", o.fail_p95, 0, 1e9, "Z",
            "exit 3 when the 95th percentile of |depth error|\n(depth_abs_p95_r, robust to outliers) exceeds Z r"),
        CLI_FLOAT_OPT(
            "--fail-interior-normal-deg", o.fail_interior, 0, 180, "Y",
            "exit 3 when the mean normal angle over the interior\n(>= 3 px from either silhouette) exceeds Y degrees"),
        CLI_FLOAT_OPT("--fail-ssim", o.fail_ssim, 0, 1, "S", "exit 3 when the SSIM is below S"),
        CLI_FLOAT_OPT("--fail-psnr", o.fail_psnr, 0, 1e9, "DB", "exit 3 when the PSNR is below DB decibels"),
        CLI_OPT_RADIUS(o.radius, "A's provenance, fluidsurf:r"),
        CLI_FLAG_OPT("--strict", o.strict,
                     "refuse (exit 2) a different scene or r, or provenance that\ncannot tell, instead of warning"),
        CLI_FLAG_OPT("--json", o.json, "print the metrics as one JSON object (NaN as null,\ninfinity as 1e999)"),
        CLI_OPT_OUT(o.out, "FILE.png", "write the normal and depth error heatmaps (as compare's\ndiff_<label>.png)"),
        CLI_FLOAT_OPT("--normal-scale", o.nscale, 1e-6, 180, "DEG",
                      "heatmap scale of the normal error (default: from the data)"),
        CLI_FLOAT_OPT("--depth-scale", o.dscale, 1e-9, 1e9, "R",
                      "heatmap scale of the depth error, in r (default: from the data)"),
        CLI_END,
    };
    const cli_command cmd = {
        "diff", "A.exr B.exr [options]", opts, {files, &nfiles, 2, "more than two files"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    if (nfiles != 2) return cli_usage("diff", "needs two EXR files");
    if (o.out && !fs_path_ends_with(o.out, ".png")) return cli_usage("diff", "-o %s: the heatmaps are a .png", o.out);
    fs_gbuffer g[2] = {{0}};
    float *rgba[2] = {NULL, NULL};
    rc = run_diff(&o, files, g, rgba);
    for (int k = 0; k < 2; k++) {
        fs_gbuffer_free(&g[k]);
        free(rgba[k]);
    }
    if (rc && rc != FS_ERR_DIFF) return cli_error(rc);
    return rc;
}
