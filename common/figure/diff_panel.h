/* The error heatmaps of a method's G-buffer against a reference's: compare's
 * diff_<label>.png and diff -o write the same panel (docs/DESIGN.md, "Metrics"). */
#ifndef FS_DIFF_PANEL_H
#define FS_DIFF_PANEL_H
#include "figure.h"
#include "gbuffer.h"
#ifdef __cplusplus
extern "C" {
#endif

/* The normal angle (degrees, 0..scale_deg) where both cover, as a heatmap. */
int fs_normal_heatmap(const fs_gbuffer *a, const fs_gbuffer *b, double scale_deg, fs_rgba_image *out);
/* |depth error - bias| in r (0..scale_r) where both cover, as a heatmap; a
 * non-finite bias counts as 0. */
int fs_depth_heatmap(const fs_gbuffer *a, const fs_gbuffer *b, float r, double bias_r, double scale_r,
                     fs_rgba_image *out);
/* Both heatmaps side by side under title, written to path as a PNG. */
int fs_write_diff_panel(const char *path, const fs_gbuffer *a, const fs_gbuffer *b, float r, double bias_r,
                        double normal_scale_deg, double depth_scale_r, const char *title);

#ifdef __cplusplus
}
#endif
#endif
