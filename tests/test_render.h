/* Test helper: renders a registered method on particles with its default
 * parameters plus "name=value" overrides (grid built with cell = f.H). */
#ifndef FS_TEST_RENDER_H
#define FS_TEST_RENDER_H
#include "method.h"

/* FS_OK or an error code with fs_fail set (also for a bad override). st may be NULL. */
int fs_test_render(const char *method, const char *const *sets, const fs_particles *p, fs_field f,
                   const fs_camera *cam, fs_gbuffer *out, fs_stages *st);

#endif
