#include "test_render.h"
#include "fs_error.h"
#include "method_params.h"
#include "particle_io.h"
#include "scene.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The method's values with "name=value" overrides, set by name through a
 * scene's "method.name=value" settings like every other caller. */
static int param_values(const fs_method *m, double *v, const char *const *sets)
{
    fs_scene s;
    fs_scene_defaults(&s);
    for (; sets && *sets; sets++) {
        char set[160];
        snprintf(set, sizeof set, "%s.%s", m->name, *sets);
        int rc = fs_scene_add_set(&s, set);
        if (rc) return rc;
    }
    return fs_method_params_resolve(m, &s, v);
}

int fs_test_render(const char *method, const char *const *sets, const fs_particles *p, fs_field f,
                   const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    const fs_method *m = fs_method_find(method);
    if (!m) return fs_fail(FS_ERR_RUNTIME, "%s is not registered", method);
    double v[FS_MAX_PARAMS];
    int rc = param_values(m, v, sets);
    if (rc) return rc;
    fs_method_setup setup = {f, fs_method_params_alloc(m, v), NULL};
    fs_grid g;
    rc = fs_grid_build(&g, p, f.H);
    void *self = rc ? NULL : m->create(&setup);
    if (!rc && !self) rc = FS_ERR_RUNTIME;
    if (!rc) rc = m->upload(self, p, &g);
    fs_stages local = {0};
    if (!rc) rc = m->render(self, cam, out, st ? st : &local);
    if (self) m->destroy(self);
    free((void *)setup.params);
    fs_grid_free(&g);
    return rc;
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
