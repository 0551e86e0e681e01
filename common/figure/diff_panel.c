/* Error heatmaps of a G-buffer against a reference (diff_panel.h). */
#include "diff_panel.h"
#include "fs_error.h"
#include "metrics.h"
#include <math.h>
#include <stdlib.h>

int fs_normal_heatmap(const fs_gbuffer *a, const fs_gbuffer *b, double scale_deg, fs_rgba_image *out)
{
    float *map = malloc((size_t)a->w * a->h * sizeof *map);
    if (!map) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    fs_normal_error_map(a, b, map);
    int rc = fs_heatmap(map, a->w, a->h, scale_deg, "normal error", "deg", out);
    free(map);
    return rc;
}

int fs_depth_heatmap(const fs_gbuffer *a, const fs_gbuffer *b, float r, double bias_r, double scale_r,
                     fs_rgba_image *out)
{
    float *map = malloc((size_t)a->w * a->h * sizeof *map);
    if (!map) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    fs_depth_error_map(a, b, r, isfinite(bias_r) ? bias_r : 0, map);
    int rc = fs_heatmap(map, a->w, a->h, scale_r, "|depth error - bias|", "r", out);
    free(map);
    return rc;
}

int fs_write_diff_panel(const char *path, const fs_gbuffer *a, const fs_gbuffer *b, float r, double bias_r,
                        double normal_scale_deg, double depth_scale_r, const char *title)
{
    fs_rgba_image hm[2] = {{0}}, panel = {0};
    int rc = fs_normal_heatmap(a, b, normal_scale_deg, &hm[0]);
    if (!rc) rc = fs_depth_heatmap(a, b, r, bias_r, depth_scale_r, &hm[1]);
    const fs_rgba_image *tiles[2] = {&hm[0], &hm[1]};
    fs_panel_spec spec = {1, 2, tiles, NULL, NULL, NULL, title};
    if (!rc) rc = fs_panel_compose(&spec, &panel);
    const char *names[4] = {"R", "G", "B", "A"};
    fs_image img = {panel.w, panel.h, 4, names, panel.pix};
    if (!rc) rc = fs_write_png(path, &img);
    fs_rgba_free(&hm[0]);
    fs_rgba_free(&hm[1]);
    fs_rgba_free(&panel);
    return rc;
}
