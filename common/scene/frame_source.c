#include "frame_source.h"
#include "fs_error.h"
#include "particle_io.h"
#include "particle_stats.h"
#include "synthetic.h"
#include <stdio.h>
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

/* Where r came from, for the notes. */
static const char *radius_source(const fs_scene *s, const fs_particles *p, float radius_opt)
{
    return radius_opt > 0 ? "--radius" : s->path[0] ? "the scene" : p->radius > 0 ? "the file" : NULL;
}

void fs_scene_adopt_frame(fs_scene *s, const fs_particles *p, float radius_opt, char *note, int size)
{
    note[0] = 0;
    const char *from = radius_source(s, p, radius_opt);
    if (radius_opt > 0) s->radius = radius_opt;
    else if (!s->path[0] && p->radius > 0) s->radius = p->radius;
    float est = 0;
    /* a synthetic set is made at its r: nothing to estimate or check */
    int have_est = s->synth.shape == FS_SYNTH_NONE && fs_particles_estimate_radius(p, &est) == FS_OK;
    if (!have_est) fs_error_clear();
    if (!from && have_est) {
        s->radius = est;
        snprintf(note, (size_t)size, "%s gives no particle radius: r = %g estimated from its spacing (set --radius)",
                 s->source, est);
    } else if (!from && s->synth.shape == FS_SYNTH_NONE) {
        snprintf(note, (size_t)size, "%s: used r = %g (set --radius)", s->source, s->radius);
    } else if (from && have_est && (s->radius > 4 * est || 4 * s->radius < est)) {
        snprintf(note, (size_t)size, "%s: r = %g from %s is %.2g times the r its spacing implies (%g): check the units",
                 s->source, s->radius, from, s->radius / est, est);
    }
    fs_scene_frame_particles(s, p);
}
