/* The analytic reference: the exact G-buffer of a synthetic scene's ideal shape
 * (scene/synthetic.h), against which `compare --reference analytic` measures. */
#ifndef FS_ANALYTIC_H
#define FS_ANALYTIC_H
#include "camera.h"
#include "gbuffer.h"
#include "synthetic.h"
#ifdef __cplusplus
extern "C" {
#endif

/* The exact G-buffer of the ideal shape for that frame: depth, normal, coverage,
 * thickness (path length through the ideal solid). out must already be allocated at
 * the camera's size (fs_gbuffer_alloc), as for a method's render. Like the reference,
 * only a crossing from outside ahead of the eye counts (a camera inside sees nothing). */
int fs_synthetic_analytic(const fs_scene *s, int frame, const fs_camera *cam, fs_gbuffer *out);

#ifdef __cplusplus
}
#endif
#endif
