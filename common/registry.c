/* The one static table of methods (libvmaf-style). Add a method here. */
#include "method.h"
#include "fs_error.h"
#include <string.h>

extern const fs_method fs_method_spheres;
extern const fs_method fs_method_reference;
extern const fs_method fs_method_raycast_pca;
extern const fs_method fs_method_aniso_ssf;
extern const fs_method fs_method_surfels;
extern const fs_method fs_method_volume_raycast;

static const fs_method *const methods[] = {
    &fs_method_spheres,
    &fs_method_reference,
    &fs_method_raycast_pca,
    &fs_method_aniso_ssf,
    &fs_method_surfels,
    &fs_method_volume_raycast,
};

int fs_method_count(void) { return (int)(sizeof methods / sizeof *methods); }
const fs_method *fs_method_at(int i) { return i >= 0 && i < fs_method_count() ? methods[i] : NULL; }

const fs_method *fs_method_find(const char *name)
{
    for (int i = 0; i < fs_method_count(); i++)
        if (!strcmp(methods[i]->name, name)) return methods[i];
    return NULL;
}

int fs_method_param_index(const fs_method *m, const char *name)
{
    for (int i = 0; i < m->nparams; i++)
        if (!strcmp(m->params[i].name, name)) return i;
    return -1;
}

int fs_method_wants_color(const fs_method *m, const fs_particles *p) { return m->writes_color && p->color != NULL; }

int fs_method_check_field(const char *method, const fs_field *f)
{
    if (f->r > 0 && f->H > 0 && f->volume > 0 && f->iso > 0) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: r %g, H %g, V %g and iso %g must all be positive", method, f->r, f->H, f->volume,
                   f->iso);
}

void fs_method_values(const fs_method_setup *setup, const fs_param_def *defs, int n, double *v)
{
    for (int i = 0; i < n; i++) v[i] = setup->params ? setup->params[i] : defs[i].def;
}
