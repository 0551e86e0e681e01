#include "frame_source.h"
#include "fs_error.h"
#include "particle_io.h"
#include "synthetic.h"
#include <string.h>

void fs_scene_frames(const fs_scene *s, int *first, int *last)
{
    if (s->frame_first >= 0) { *first = s->frame_first; *last = s->frame_last; }
    else { *first = 0; *last = 0; }
}

int fs_scene_load_frame(const fs_scene *s, int frame, fs_particles *p)
{
    memset(p, 0, sizeof *p);
    if (s->synth.shape != FS_SYNTH_NONE) return fs_synthetic_generate(s, frame, p);
    if (s->frame_first < 0) return fs_particles_read(p, s->source, s->format);
    char path[FS_PATH_MAX];
    int rc = fs_frame_path(path, sizeof path, s->source, frame);
    return rc ? rc : fs_particles_read(p, path, s->format);
}

int fs_scene_adopt_frame(fs_scene *s, const fs_particles *p, float radius_opt)
{
    int fallback = 0;
    if (radius_opt > 0) s->radius = radius_opt;
    else if (!s->path[0] && p->radius > 0) s->radius = p->radius;
    else fallback = !s->path[0];
    fs_scene_frame_particles(s, p);
    return fallback;
}
