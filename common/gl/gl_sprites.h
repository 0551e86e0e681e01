/* Pieces every sprite-splatting GL method shares: the camera uniforms and the
 * instanced draw of one quad per particle over chunked storage buffers. */
#ifndef FS_GL_SPRITES_H
#define FS_GL_SPRITES_H
#include "camera.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Makes prog current and sets whichever of u_view, u_proj, u_view_rot (mat3),
 * u_eye and u_viewport it declares. */
void fs_gl_camera_uniforms(unsigned prog, const fs_camera *cam);
/* One instanced 4-vertex strip per particle: n particles spread over nbufs
 * buffers of `chunk` particles each, bound in turn at SSBO binding 0. */
void fs_gl_draw_sprites(unsigned vao, const unsigned *bufs, int nbufs, size_t chunk, size_t n);

#ifdef __cplusplus
}
#endif
#endif
