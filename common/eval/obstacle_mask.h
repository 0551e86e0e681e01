/* Metrics in a scene with obstacles (obstacles.h): the pixels where a solid lies
 * in front of the reference surface show the solid whatever the fluid does, so
 * they are left out of every metric (docs/DESIGN.md, "Obstacles"). */
#ifndef FS_OBSTACLE_MASK_H
#define FS_OBSTACLE_MASK_H
#include "metrics.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* hidden[i] = 1 where an obstacle of s is nearer the camera than ref's surface,
 * or ref has no surface and an obstacle is hit; 0 elsewhere. hidden: w*h of ref.
 * FS_ERR_RUNTIME when out of memory. */
int fs_obstacle_hidden_mask(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *ref, unsigned char *hidden);
/* Views of the ng G-buffers g (views[k]: g[k] with its coverage in cov + k w h) with
 * every pixel emptied that an obstacle hides in front of any of the nby G-buffers by
 * (their surfaces: the references a measure is taken against). All the same size
 * (FS_ERR_INPUT); cov: ng w h floats. FS_ERR_RUNTIME when out of memory. */
int fs_obstacle_hide(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *const *by, int nby,
                     const fs_gbuffer *const *g, int ng, fs_gbuffer *views, float *cov);
/* The one rule of what a solid hides, from the solids' depth at each pixel
 * (solid_depth: w*h of ref; 0 or not finite where no solid is hit): hidden[i] = 1
 * where a solid is nearer the camera than ref's surface, or ref has no surface
 * there and a solid is hit. */
void fs_solids_hidden(const float *solid_depth, const fs_gbuffer *ref, unsigned char *hidden);
/* fs_metrics_compute of a against the reference b with the pixels fs_solids_hidden
 * marks (against b) emptied in both; solid_depth NULL: all pixels. *nhidden (may be
 * NULL): how many pixels were left out. compare (below), diff and the C API all
 * measure through it. */
int fs_metrics_compute_masked(const float *solid_depth, const fs_gbuffer *a, const float *rgba_a, const fs_gbuffer *b,
                              const float *rgba_b, float r, fs_metrics *out, long *nhidden);
/* fs_metrics_compute of a against the reference b over the pixels no obstacle
 * hides (all pixels when s has none): fs_metrics_compute_masked with the depth of
 * s's solids seen through cam. */
int fs_metrics_compute_in_scene(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *a, const float *rgba_a,
                                const fs_gbuffer *b, const float *rgba_b, fs_metrics *out);
/* view: g, plus (when s has solids and g has no such layer yet) the AOV
 * FS_AOV_SOLID_DEPTH, the solids' depth seen through cam (0 where none), in *buf
 * (malloc'd, the caller frees it; NULL when none was added). So an EXR written from
 * view carries what fs_metrics_compute_masked needs. view shares g's other layers:
 * never fs_gbuffer_free it. FS_ERR_RUNTIME when out of memory. */
int fs_solids_layer(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g, fs_gbuffer *view, float **buf);

#ifdef __cplusplus
}
#endif
#endif
