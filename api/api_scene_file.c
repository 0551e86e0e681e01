/* A scene's particle source, its camera as --camera's text, and the scene
 * written back as a scene file: the command line's PATTERN --frames,
 * --camera and render --save-scene, for the library. */
#include "api_internal.h"
#include "camera_text.h"
#include "frame_pattern.h"
#include "frame_source.h"
#include "fs_error.h"
#include "output_file.h"

#include <stdlib.h>
#include <string.h>

int fluidsurf_scene_set_source(fluidsurf_scene *s, const char *path, int first, int last, int step)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(path, "path"))) return rc;
    if (strlen(path) >= sizeof s->s.source) return fs_fail(FS_ERR_INPUT, "%.80s...: path too long", path);
    if (!fs_is_frame_pattern(path)) {
        if (first || last || step)
            return fs_fail(FS_ERR_INPUT, "%s: not a frame pattern ({} or %%04d), so first, last and step must be 0",
                           path);
        strcpy(s->s.source, path);
        s->s.frame_first = s->s.frame_last = -1, s->s.frame_step = 1;
    } else {
        if (first < 0 || last < first || last > 100000000 || step < 1)
            return fs_fail(FS_ERR_INPUT, "%s: frames %d..%d step %d: expected 0 <= first <= last, step >= 1", path,
                           first, last, step);
        if ((rc = fs_scene_set_frames(&s->s, path, first, last, step))) return rc;
    }
    s->s.synth.shape = FS_SYNTH_NONE;
    return FLUIDSURF_OK;
}

int fluidsurf_scene_set_camera_text(fluidsurf_scene *s, const char *text)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(text, "text"))) return rc;
    fs_camera c = s->s.camera;
    unsigned given = 0;
    if ((rc = fs_camera_parse(text, "camera", &c, &given))) return rc;
    fs_scene_place_camera(&s->s, &c, (given & FS_CAMERA_HAS_UP) != 0);
    return FLUIDSURF_OK;
}

int fluidsurf_scene_save(const fluidsurf_scene *s, const fluidsurf_particles *p, const char *path)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(p, "particles")) || (rc = fs_api_check(path, "path")))
        return rc;
    if (!fs_path_ends_with(path, ".json")) return fs_fail(FS_ERR_INPUT, "%s: a scene file must end in .json", path);
    if (!s->s.source[0] && s->s.synth.shape == FS_SYNTH_NONE)
        return fs_fail(FS_ERR_INPUT, "%s: the scene has no particle source to name (fluidsurf_scene_set_source)", path);
    fs_scene *sc = malloc(sizeof *sc);
    if (!sc) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    *sc = s->s;
    /* settled as a render on p settles it (fs_api_prepare): r, up, the framing */
    fs_particles q = p->p;
    rc = fs_particles_validate(&q, "particles");
    char note[1024];
    if (!rc) {
        fs_particles_bounds(&q);
        fs_scene_adopt_frame(sc, &q, s->radius_set ? sc->radius : 0, note, sizeof note);
        rc = fs_scene_save(sc, path);
    }
    free(sc);
    return rc;
}
