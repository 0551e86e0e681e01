/* The key of a method's render: a hash of everything its G-buffer depends on,
 * so a stored G-buffer with the same key can stand in for rendering it again
 * (the reference cache, docs/DESIGN.md "Reference cache"). */
#ifndef FS_RENDER_KEY_H
#define FS_RENDER_KEY_H
#include "camera.h"
#include "hash.h"
#include "kernels.h"
#include "method.h"
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* The hash of: a format tag; fluidsurf's version and commit (for a build from
 * a modified tree, "-dirty", also the executable's size and modification time);
 * the method's name and every parameter value (table order, as text and as
 * the doubles); the field (r, V, kernel, H, iso); the camera (eye, target, up,
 * fov, width, height, near, far); the particle count and positions (and the
 * colours when the method declares a colour layer). Floats are hashed as their
 * bits. Valid for methods whose G-buffer depends on nothing else (the reference). */
fs_digest fs_render_key(const fs_method *m, const double *values, const fs_field *f, const fs_camera *cam,
                        const fs_particles *p);
/* The build part of the key as text: the commit, plus the executable's
 * identity for a "-dirty" or "unknown" build. */
void fs_render_key_build(char *buf, int size);

#ifdef __cplusplus
}
#endif
#endif
