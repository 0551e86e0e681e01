/* Where a frame's particles come from: a file, a frame of a printf pattern,
 * or a synthetic scene. Shared by every command that renders. */
#ifndef FS_FRAME_SOURCE_H
#define FS_FRAME_SOURCE_H
#include "particles.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Frames to render: [first, last]; a single frame gives first = last = 0
 * (or the scene's frame for a pattern). */
void fs_scene_frames(const fs_scene *s, int *first, int *last);
/* Loads frame `frame` (ignored for a single file) and validates it. */
int fs_scene_load_frame(const fs_scene *s, int frame, fs_particles *p);
/* Settles what the first frame decides for the whole run, once: a scene given
 * as a bare particle file takes r from the file, unless radius_opt > 0 sets it
 * (a scene file's r stays); a file without one gets the r its spacing implies
 * (fs_particles_estimate_radius). The camera frames the particles unless the
 * scene places it. note receives one line for stderr, or "": the estimate, or
 * a given r more than 4 times off the estimate either way. */
void fs_scene_adopt_frame(fs_scene *s, const fs_particles *p, float radius_opt, char *note, int size);

#ifdef __cplusplus
}
#endif
#endif
