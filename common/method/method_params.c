#include "method_params.h"
#include "fs_error.h"
#include "scene.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fs_method_names(char *buf, int size)
{
    int n = 0;
    buf[0] = 0;
    for (int i = 0; i < fs_method_count() && n < size; i++)
        n += snprintf(buf + n, size - n, "%s%s", i ? ", " : "", fs_method_at(i)->name);
}

int fs_method_fail_unknown(const char *context, const char *name)
{
    char names[600];
    fs_method_names(names, sizeof names);
    return fs_fail(FS_ERR_INPUT, "%s%sunknown method '%.60s' (methods: %s)", context ? context : "",
                   context ? ": " : "", name, names);
}

void fs_method_param_names(const fs_method *m, char *buf, int size)
{
    int n = 0;
    buf[0] = 0;
    for (int i = 0; i < m->nparams && n < size; i++)
        n += snprintf(buf + n, size - n, "%s%s", i ? ", " : "", m->params[i].name);
}

/* The messages name the setting as written, not the flag or file it came from:
 * the command line, a scene file and the library (api/) all report them. */
int fs_method_setting_find(const char *text, fs_method_setting *out)
{
    fs_param_setting split;
    char names[600];
    int rc = fs_param_split(text, &split);
    if (rc) return rc;
    if (!(out->m = fs_method_find(split.method))) return fs_method_fail_unknown(text, split.method);
    if ((out->param = fs_method_param_index(out->m, split.param)) < 0) {
        fs_method_param_names(out->m, names, sizeof names);
        return fs_fail(FS_ERR_INPUT, "%s: %s has no parameter '%s' (its parameters: %s)", text, split.method,
                       split.param, names);
    }
    out->value = split.value;
    return FS_OK;
}

int fs_method_setting_parse(const fs_method_setting *set, const char *value, double *out)
{
    const fs_param_def *def = &set->m->params[set->param];
    char what[160];
    snprintf(what, sizeof what, "%s.%s", set->m->name, def->name);
    return fs_param_parse(def, value, out, what);
}

int fs_method_setting_resolve(fs_scene_setting *set)
{
    fs_method_setting ms;
    double v;
    int rc = fs_method_setting_find(set->text, &ms);
    if (!rc) rc = fs_method_setting_parse(&ms, ms.value, &v);
    if (rc) return rc;
    set->method = ms.m, set->param = ms.param, set->value = v;
    return FS_OK;
}

int fs_method_params_resolve(const fs_method *m, const fs_scene *s, double values[FS_MAX_PARAMS])
{
    for (int i = 0; i < m->nparams; i++) values[i] = m->params[i].def;
    for (int k = 0; k < s->nsets; k++) {
        fs_scene_setting set = s->sets[k];
        int rc; /* a setting added before any method was registered is resolved here */
        if (!set.method && (rc = fs_method_setting_resolve(&set))) return rc;
        if (set.method == m) values[set.param] = set.value;
    }
    return FS_OK;
}

void fs_method_params_string(const fs_method *m, const double *values, char *buf, int size)
{
    int n = 0;
    buf[0] = 0;
    for (int i = 0; i < m->nparams && n < size; i++) {
        char v[64];
        fs_param_format(&m->params[i], values[i], v, sizeof v);
        n += snprintf(buf + n, size - n, "%s%s=%s", i ? ";" : "", m->params[i].name, v);
    }
}

/* ---- the parameter struct handed to create() ---- */

/* The C type a kind of parameter needs. */
static fs_param_ctype ctype_for(fs_param_type t)
{
    return t == FS_PARAM_FLOAT ? FS_CTYPE_DOUBLE : (t == FS_PARAM_BOOL ? FS_CTYPE_BOOL : FS_CTYPE_INT);
}

static void store(const fs_param_def *def, double v, void *field)
{
    if (def->ctype == FS_CTYPE_DOUBLE) *(double *)field = v;
    else if (def->ctype == FS_CTYPE_BOOL) *(bool *)field = v != 0;
    else *(int *)field = (int)v; /* INT and ENUM values are whole numbers in range (fs_param_parse) */
}

int fs_method_params_fill(const fs_method *m, const double *values, void *dst)
{
    memset(dst, 0, m->params_size);
    for (int i = 0; i < m->nparams; i++) {
        const fs_param_def *def = &m->params[i];
        if (def->ctype != ctype_for(def->type))
            return fs_fail(FS_ERR_RUNTIME, "%s: parameter %s: its field's C type does not fit its kind", m->name,
                           def->name);
        if (def->offset + fs_param_ctype_size(def->ctype) > m->params_size)
            return fs_fail(FS_ERR_RUNTIME, "%s: parameter %s lies outside its %zu-byte struct", m->name, def->name,
                           m->params_size);
        store(def, values ? values[i] : def->def, (char *)dst + def->offset);
    }
    return FS_OK;
}

void *fs_method_params_alloc(const fs_method *m, const double *values)
{
    void *p = malloc(m->params_size ? m->params_size : 1);
    if (!p) {
        fs_fail(FS_ERR_RUNTIME, "%s: out of memory for its parameters", m->name);
        return NULL;
    }
    if (fs_method_params_fill(m, values, p)) {
        free(p);
        return NULL;
    }
    return p;
}

int fs_method_params_copy(const char *method, const fs_method_setup *setup, void *dst, size_t size)
{
    if (!setup->params)
        return fs_fail(FS_ERR_RUNTIME, "%s: no parameter struct in the setup (fs_method_params_fill)", method);
    memcpy(dst, setup->params, size);
    return FS_OK;
}

void fs_method_provenance(fs_provenance *out, const fs_method *m, const double *values, int frame)
{
    char pstr[600], fstr[32];
    fs_method_params_string(m, values, pstr, sizeof pstr);
    fs_provenance_set(out, "method", m->name);
    fs_provenance_set(out, "params", pstr);
    snprintf(fstr, sizeof fstr, "%d", frame);
    fs_provenance_set(out, "frame", fstr);
}

int fs_method_setup_take(const char *method, const fs_method_setup *setup, fs_field *f, void *params, size_t size,
                         fs_scene *scene)
{
    int rc = fs_method_check_field(method, &setup->field);
    if (!rc) rc = fs_method_params_copy(method, setup, params, size);
    if (rc) return rc;
    *f = setup->field;
    if (setup->scene) *scene = *setup->scene;
    else fs_scene_defaults(scene);
    return FS_OK;
}
