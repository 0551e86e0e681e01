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
/* fs_metrics_compute of a against the reference b over the pixels no obstacle
 * hides (all pixels when s has none). */
int fs_metrics_compute_in_scene(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *a, const float *rgba_a,
                                const fs_gbuffer *b, const float *rgba_b, fs_metrics *out);

#ifdef __cplusplus
}
#endif
#endif
