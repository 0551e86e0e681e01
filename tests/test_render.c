#include "test_render.h"
#include "fs_error.h"
#include "particle_io.h"
#include "scene.h"
#include <stdio.h>
#include <string.h>

static int param_values(const fs_method *m, double *v, const char *const *sets)
{
    for (int i = 0; i < m->nparams; i++) v[i] = m->params[i].def;
    for (; sets && *sets; sets++) {
        char name[64];
        const char *eq = strchr(*sets, '=');
        if (!eq) return fs_fail(FS_ERR_INPUT, "bad test parameter %s", *sets);
        snprintf(name, sizeof name, "%.*s", (int)(eq - *sets), *sets);
        int i = fs_method_param_index(m, name);
        if (i < 0) return fs_fail(FS_ERR_INPUT, "%s has no parameter %s", m->name, name);
        int rc = fs_param_parse(&m->params[i], eq + 1, &v[i], name);
        if (rc) return rc;
    }
    return FS_OK;
}

int fs_test_render(const char *method, const char *const *sets, const fs_particles *p, fs_field f,
                   const fs_camera *cam, fs_gbuffer *out, fs_stages *st)
{
    const fs_method *m = fs_method_find(method);
    if (!m) return fs_fail(FS_ERR_RUNTIME, "%s is not registered", method);
    double v[FS_MAX_PARAMS];
    int rc = param_values(m, v, sets);
    if (rc) return rc;
    fs_method_setup setup = {f, v, NULL};
    fs_grid g;
    rc = fs_grid_build(&g, p, f.H);
    void *self = rc ? NULL : m->create(&setup);
    if (!rc && !self) rc = FS_ERR_RUNTIME;
    if (!rc) rc = m->upload(self, p, &g);
    fs_stages local = {0};
    if (!rc) rc = m->render(self, cam, out, st ? st : &local);
    if (self) m->destroy(self);
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
