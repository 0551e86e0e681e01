/* The registry of methods (libvmaf-style): methods/builtin_methods.c registers the
 * built-in table; a test may register a method of its own the same way. */
#include "method.h"
#include "fs_error.h"
#include "method_params.h"
#include <string.h>

#define MAX_METHODS 32

/* Registered methods, in registration order; hidden ones are found by name
 * but not listed. */
static const fs_method *methods[MAX_METHODS];
static int hidden[MAX_METHODS], nmethods;

int fs_method_register(const fs_method *m, int flags)
{
    for (int i = 0; i < nmethods; i++)
        if (methods[i] == m) return FS_OK;
        else if (!strcmp(methods[i]->name, m->name))
            return fs_fail(FS_ERR_INPUT, "method '%s' is registered twice", m->name);
    if (nmethods == MAX_METHODS)
        return fs_fail(FS_ERR_RUNTIME, "method '%s': more than %d methods", m->name, MAX_METHODS);
    hidden[nmethods] = (flags & FS_METHOD_HIDDEN) != 0;
    methods[nmethods++] = m;
    fs_scene_set_resolver(fs_method_setting_resolve); /* settings are resolved as they are added */
    return FS_OK;
}

int fs_method_count(void)
{
    int n = 0;
    for (int i = 0; i < nmethods; i++) n += !hidden[i];
    return n;
}

const fs_method *fs_method_at(int i)
{
    for (int k = 0; k < nmethods; k++)
        if (!hidden[k] && i-- == 0) return methods[k];
    return NULL;
}

const fs_method *fs_method_find(const char *name)
{
    for (int i = 0; i < nmethods; i++)
        if (!strcmp(methods[i]->name, name)) return methods[i];
    return NULL;
}
int fs_method_param_index(const fs_method *m, const char *name)
{
    for (int i = 0; i < m->nparams; i++)
        if (!strcmp(m->params[i].name, name)) return i;
    return -1;
}

const fs_aov_def *fs_method_aov(const fs_method *m, const char *name)
{
    for (int i = 0; i < m->naovs; i++)
        if (!strcmp(m->aovs[i].name, name)) return &m->aovs[i];
    return NULL;
}

int fs_method_aov_wanted(const fs_aov_def *d, const fs_particles *p) { return !d->needs_color || p->color != NULL; }

int fs_method_check_field(const char *method, const fs_field *f)
{
    if (f->r > 0 && f->H > 0 && f->volume > 0 && f->iso > 0) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: r %g, H %g, V %g and iso %g must all be positive", method, f->r, f->H, f->volume,
                   f->iso);
}
