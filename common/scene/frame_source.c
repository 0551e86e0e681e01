#include "caller_words.h"
#include "frame_source.h"
#include "fs_error.h"
#include "particle_io.h"
#include "particle_stats.h"
#include "synthetic.h"
#include "up_axis.h"
#include <stdio.h>
#include <string.h>

void fs_scene_frames(const fs_scene *s, int *first, int *last)
{
    if (s->frame_first >= 0) {
        *first = s->frame_first;
        *last = s->frame_last;
    } else {
        *first = 0;
        *last = 0;
    }
}

int fs_scene_set_frames(fs_scene *s, const char *pattern, int first, int last, int step)
{
    int rc = fs_frame_pattern(pattern, s->source, sizeof s->source);
    if (rc) return rc;
    s->frame_first = first, s->frame_last = last, s->frame_step = step;
    return FS_OK;
}

int fs_scene_frame_count(const fs_scene *s)
{
    return s->frame_first < 0 ? 1 : (s->frame_last - s->frame_first) / s->frame_step + 1;
}

int fs_scene_frame_number(const fs_scene *s, int k)
{
    return s->frame_first < 0 ? 0 : s->frame_first + k * s->frame_step;
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
static const char *radius_source(const fs_scene *s)
{
    switch (s->r_source) {
    case FS_R_OPTION: return fs_word("radius");
    case FS_R_SCENE: return "the scene";
    case FS_R_FILE: return "the file";
    default: return NULL;
    }
}

/* r: the option's, else the scene file's, else the particle file's, else the
 * spacing's (note), else the default (note). */
static void settle_radius(fs_scene *s, const fs_particles *p, float radius_opt, char *note, int size)
{
    if (radius_opt > 0) s->radius = radius_opt, s->r_source = FS_R_OPTION;
    else if (!s->synth.shape && s->r_source != FS_R_SCENE && p->radius > 0)
        s->radius = p->radius, s->r_source = FS_R_FILE;
    float est = 0;
    /* a synthetic set is made at its r: nothing to estimate or check */
    int have_est = s->synth.shape == FS_SYNTH_NONE && fs_particles_estimate_radius(p, &est) == FS_OK;
    if (!have_est) fs_error_clear();
    s->spacing_r = have_est ? est : 0;
    const char *from = radius_source(s);
    if (!from && have_est) {
        s->radius = est;
        s->r_source = FS_R_ESTIMATED;
        snprintf(note, (size_t)size, "%.400s gives no particle radius: r = %g estimated from its spacing (set %s)",
                 s->source, est, fs_word("radius"));
    } else if (!from && s->synth.shape == FS_SYNTH_NONE) {
        snprintf(note, (size_t)size, "%.400s: used the default r = %g (set %s)", s->source, s->radius,
                 fs_word("radius"));
    } else if (from && have_est && (s->radius > 4 * est || 4 * s->radius < est)) {
        snprintf(note, (size_t)size,
                 "%.400s: r = %g from %s is %.2g times the r its spacing implies (%g): check the units", s->source,
                 s->radius, from, s->radius / est, est);
    }
}

/* up "auto": the first frame decides, and a note says how. */
static void settle_up(fs_scene *s, const fs_particles *p, char *note, int size)
{
    if (s->up_source != FS_UP_AUTO) return;
    char why[200];
    s->up_axis = fs_up_axis_guess(p, s->source, s->spacing_r > 0 ? s->spacing_r : s->radius, why, sizeof why);
    snprintf(note, (size_t)size, "%.200s: up is %c (auto: %s; set %s)", s->source, 'x' + s->up_axis, why,
             fs_word("up"));
}

void fs_scene_adopt_frame(fs_scene *s, const fs_particles *p, float radius_opt, char *note, int size)
{
    char r_note[640] = "", up_note[480] = "";
    settle_radius(s, p, radius_opt, r_note, sizeof r_note);
    settle_up(s, p, up_note, sizeof up_note);
    snprintf(note, (size_t)size, "%s%s%s", r_note, r_note[0] && up_note[0] ? "\n" : "", up_note);
    fs_scene_frame_particles(s, p);
}
