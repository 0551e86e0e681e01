/* fluidsurf diff A.exr B.exr: the compare metrics between two outputs, and an
 * exit status for regression checks (3 when a threshold is crossed). */
#include "cli.h"
#include "fs_error.h"
#include "metrics.h"
#include "render_output.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: fluidsurf diff A.exr B.exr [--fail-iou X] [--fail-normal-deg Y] [--fail-depth-r Z] [--radius R]\n"
    "Prints the metrics of A against B (B is the reference) and exits 3 when\n"
    "  mask IoU < X,  mean normal angle > Y degrees,  or |depth bias| or depth RMSE > Z r;\n"
    "0 otherwise. r comes from A's provenance (fluidsurf:r) unless --radius is given.\n";

int cmd_diff(int argc, char **argv)
{
    const char *files[2] = {NULL, NULL};
    float fail_iou = -1, fail_normal = -1, fail_depth = -1, radius = 0;
    int nfiles = 0, rc;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(help, stdout); return 0; }
        else if (!strcmp(a, "--fail-iou")) { if ((rc = cli_float("diff", a, v, 0, 1, &fail_iou))) return rc; i++; }
        else if (!strcmp(a, "--fail-normal-deg")) { if ((rc = cli_float("diff", a, v, 0, 180, &fail_normal))) return rc; i++; }
        else if (!strcmp(a, "--fail-depth-r")) { if ((rc = cli_float("diff", a, v, 0, 1e9, &fail_depth))) return rc; i++; }
        else if (!strcmp(a, "--radius")) { if ((rc = cli_float("diff", a, v, 1e-9, 1e9, &radius))) return rc; i++; }
        else if (a[0] == '-' && a[1]) return cli_usage("diff", "unknown or incomplete option '%s'", a);
        else if (nfiles < 2) files[nfiles++] = a;
        else return cli_usage("diff", "more than two files");
    }
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
