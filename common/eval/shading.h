/* The shared shading pass: turns any G-buffer into the final linear RGBA image
 * with the scene's light, material and background, identically for every method. */
#ifndef FS_SHADING_H
#define FS_SHADING_H
#include "gbuffer.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* rgba: 4*w*h floats, linear. floor_y: height of the checker floor (world). */
void fs_shade(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g, float floor_y, float *rgba);

#ifdef __cplusplus
}
#endif
#endif
