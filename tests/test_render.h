/* Test helper: renders a registered method through the run layer on particles,
 * with field f and its default parameters plus "name=value" settings (set by
 * name through the scene, as --set does). */
#ifndef FS_TEST_RENDER_H
#define FS_TEST_RENDER_H
#include "method.h"

/* FS_OK or an error code with fs_fail set (also for a bad setting). out is replaced
 * by the method's G-buffer at the camera's size. st may be NULL. */
int fs_test_render(const char *method, const char *const *sets, const fs_particles *p, fs_field f, const fs_camera *cam,
                   fs_gbuffer *out, fs_stages *st);

/* The first name of the NULL-terminated list want that st does not report, or NULL. */
const char *fs_test_missing_stage(const fs_stages *st, const char *const *want);

struct fs_scene;
/* The 6,859-particle SPlisHSPlasH dam break (r 0.025, volume_scale 0.8) with a
 * default scene framing it at 128x128 and its field. FS_OK or an error code
 * (fs_fail set); p is empty on failure. */
int fs_test_load_dam(fs_particles *p, struct fs_scene *s, fs_field *f);

#endif
