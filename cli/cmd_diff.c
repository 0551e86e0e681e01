/* fluidsurf diff A.exr B.exr: the compare metrics between two outputs, and an
 * exit status for regression checks (3 when a threshold is crossed). */
#include "cli.h"
#include "fs_error.h"
#include "metrics.h"
#include "options.h"
#include "render_output.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* what --help says after the options */
static const char epilogue[] =
    "Prints the metrics of A against B (B is the reference); exits 3 when a --fail-*\n"
    "threshold is crossed, 0 otherwise.\n";

int cmd_diff(int argc, char **argv)
{
    const char *files[2] = {NULL, NULL};
    float fail_iou = -1, fail_normal = -1, fail_depth = -1, radius = 0;
    int nfiles = 0, rc;
    const cli_opt opts[] = {
        CLI_FLOAT_OPT("--fail-iou", fail_iou, 0, 1, "X", "exit 3 when the mask IoU is below X"),
        CLI_FLOAT_OPT("--fail-normal-deg", fail_normal, 0, 180, "Y", "exit 3 when the mean normal angle exceeds Y degrees"),
        CLI_FLOAT_OPT("--fail-depth-r", fail_depth, 0, 1e9, "Z", "exit 3 when |depth bias| or depth RMSE exceeds Z r"),
        CLI_OPT_RADIUS(radius, "A's provenance, fluidsurf:r"),
        CLI_END,
    };
    const cli_command cmd = {"diff", "A.exr B.exr [options]", opts, {files, &nfiles, 2, "more than two files"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    if (nfiles != 2) return cli_usage("diff", "needs two EXR files");
    fs_gbuffer g[2] = {{0}};
    float *rgba[2] = {NULL, NULL}, r[2] = {0, 0};
    rc = fs_read_render(files[0], &g[0], &rgba[0], &r[0]);
    if (!rc) rc = fs_read_render(files[1], &g[1], &rgba[1], &r[1]);
    if (!rc && (g[0].w != g[1].w || g[0].h != g[1].h))
        rc = fs_fail(FS_ERR_INPUT, "%s: %dx%d, but %s is %dx%d", files[1], g[1].w, g[1].h, files[0], g[0].w, g[0].h);
    float rr = radius > 0 ? radius : r[0] > 0 ? r[0] : r[1];
    if (!rc && !(rr > 0)) rc = fs_fail(FS_ERR_INPUT, "%s: no fluidsurf:r attribute; give --radius", files[0]);
    fs_metrics m;
    if (!rc) rc = fs_metrics_compute(&g[0], rgba[0], &g[1], rgba[1], rr, &m);
    int crossed = 0;
    if (!rc) {
        printf("a: %s\nb: %s (reference)\nr: %g\n", files[0], files[1], rr);
        printf("mask_iou %.6g\ndepth_bias_r %.6g\ndepth_rmse_r %.6g\ndepth_p95_r %.6g\n", m.mask_iou, m.depth_bias_r,
               m.depth_rmse_r, m.depth_p95_r);
        printf("normal_mean_deg %.6g\nnormal_p95_deg %.6g\ninterior_normal_mean_deg %.6g\npsnr_db %.6g\nssim %.6g\n",
               m.normal_mean_deg, m.normal_p95_deg, m.interior_normal_mean_deg, m.psnr_db, m.ssim);
        /* a NAN metric (nothing to compare) never passes a threshold that asks for it */
        if (fail_iou >= 0 && !(m.mask_iou >= fail_iou)) { printf("FAIL mask_iou < %g\n", fail_iou); crossed = 1; }
        if (fail_normal >= 0 && !(m.normal_mean_deg <= fail_normal)) { printf("FAIL normal_mean_deg > %g\n", fail_normal); crossed = 1; }
        if (fail_depth >= 0 && !(fabs(m.depth_bias_r) <= fail_depth && m.depth_rmse_r <= fail_depth)) {
            printf("FAIL |depth_bias_r| or depth_rmse_r > %g\n", fail_depth);
            crossed = 1;
        }
    }
    for (int k = 0; k < 2; k++) { fs_gbuffer_free(&g[k]); free(rgba[k]); }
    if (rc) return cli_error(rc);
    return crossed ? FS_ERR_DIFF : 0;
}
