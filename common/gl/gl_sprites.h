/* Pieces every sprite-splatting GL method shares: the camera uniforms and the
 * instanced draw of one quad per particle over chunked storage buffers. */
#ifndef FS_GL_SPRITES_H
#define FS_GL_SPRITES_H
#include "camera.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Sprites per draw call of fs_gl_draw_sprites. llvmpipe bins a whole draw
 * before rasterising it and keeps allocating scenes while the rasterisers lag
 * (about 0.8 KB per sprite), so one draw of 1M sprites peaked at ~170 MB. */
#define FS_GL_SPRITE_BATCH 16384

/* Makes prog current and sets whichever of u_view, u_proj, u_view_rot (mat3),
 * u_eye and u_viewport it declares. */
void fs_gl_camera_uniforms(unsigned prog, const fs_camera *cam);
/* One instanced 4-vertex strip per particle: n particles spread over nbufs
 * buffers of `chunk` particles of `stride` bytes each, bound in turn at SSBO
 * binding 0, drawn FS_GL_SPRITE_BATCH at a time with at most two batches in
 * flight. The fragments reach each pixel in the same order as one draw, so
 * the image is the same bit for bit. */
void fs_gl_draw_sprites(unsigned vao, const unsigned *bufs, int nbufs, size_t chunk, size_t n, size_t stride);

#ifdef __cplusplus
}
#endif
#endif
