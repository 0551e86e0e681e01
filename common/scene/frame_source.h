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
/* The frames to render, first, first + step, ... up to last: how many, and the
 * number of the k-th. */
int fs_scene_frame_count(const fs_scene *s);
int fs_scene_frame_number(const fs_scene *s, int k);
/* s reads frames first, first + step, ... up to last of pattern ({} or a
 * printf pattern, frame_pattern.h): FS_ERR_INPUT when it is not one. */
int fs_scene_set_frames(fs_scene *s, const char *pattern, int first, int last, int step);
/* Loads frame `frame` (ignored for a single file) and validates it. */
int fs_scene_load_frame(const fs_scene *s, int frame, fs_particles *p);
/* Settles what the first frame decides for the whole run, once: r is
 * radius_opt when > 0, else the scene file's, else the particle file's, else
 * the r its spacing implies (fs_particles_estimate_radius), and s->r_source
 * says which; an up axis left to auto is chosen (fs_up_axis_guess). The camera
 * frames the particles unless the scene places it. note receives up to two
 * lines for stderr (fs_note prints each), or "": the estimate, a given r more
 * than 4 times off the estimate either way, the up axis chosen. */
void fs_scene_adopt_frame(fs_scene *s, const fs_particles *p, float radius_opt, char *note, int size);

#ifdef __cplusplus
}
#endif
#endif
