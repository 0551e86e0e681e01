#include "test_render.h"
#include "fs_error.h"
#include "particle_io.h"
#include "builtin_methods.h"
#include "run.h"
#include "scene.h"
#include <stdio.h>
#include <string.h>

/* A scene whose field is f, with "method.name=value" settings for the method. */
static int scene_for(fs_scene *s, const char *method, const char *const *sets, fs_field f)
{
    fs_scene_defaults(s);
    s->radius = f.r;
    s->volume_scale = f.volume / (8.0f * f.r * f.r * f.r);
    s->kernel = f.kernel;
    s->support_r = f.H / f.r;
    s->iso = f.iso;
    for (; sets && *sets; sets++) {
        char set[256];
        snprintf(set, sizeof set, "%s.%s", method, *sets);
        int rc = fs_scene_add_set(s, set);
        if (rc) return rc;
    }
    return FS_OK;
}

int fs_test_render(const char *method, const char *const *sets, const fs_particles *p, fs_field f, const fs_camera *cam,
                   fs_gbuffer *out, fs_stages *st)
{
    fs_methods_register_builtin();
    const fs_method *m = fs_method_find(method);
    if (!m) return fs_fail(FS_ERR_RUNTIME, "%s is not registered", method);
    static fs_scene s; /* large; the run keeps a pointer until closed */
    fs_run *run = NULL;
    fs_run_image im = {0};
    int rc = scene_for(&s, method, sets, f);
    if (!rc) rc = fs_run_open(&run, m, &s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, p, NULL, st);
    if (!rc) rc = fs_run_render(run, cam, &im, st);
    fs_run_close(run);
    if (rc) {
        fs_run_image_free(&im);
        return rc;
    }
    fs_gbuffer_free(out);
    *out = im.g;
    return FS_OK;
}

int fs_test_load_dam(fs_particles *p, fs_scene *s, fs_field *f)
{
    int rc = fs_particles_read(p, FS_TEST_DATA "/splashsurf/dam_break_frame_9_6859_particles.bgeo", NULL);
    if (rc) return rc;
    fs_particles_bounds(p);
    fs_scene_defaults(s);
    s->radius = 0.025f;
    s->volume_scale = 0.8f;
    s->camera.width = s->camera.height = 128;
    fs_scene_frame_particles(s, p);
    *f = fs_scene_field(s);
    return FS_OK;
}

const char *fs_test_missing_stage(const fs_stages *st, const char *const *want)
{
    for (; *want; want++) {
        int found = 0;
        for (int k = 0; k < st->n; k++) found |= !strcmp(st->name[k], *want);
        if (!found) return *want;
    }
    return NULL;
}
