/* The method registry as the library lists it: names, papers, parameter tables. */
#include "api_internal.h"
#include "fs_error.h"
#include "method.h"
#include "method_params.h"
#include "params.h"

static const fs_method *find(const char *name)
{
    fs_api_init();
    return name ? fs_method_find(name) : NULL;
}

int fluidsurf_method_count(void)
{
    fs_api_init();
    return fs_method_count();
}

const char *fluidsurf_method_name(int i)
{
    fs_api_init();
    const fs_method *m = i >= 0 && i < fs_method_count() ? fs_method_at(i) : NULL;
    return m ? m->name : NULL;
}

const char *fluidsurf_method_description(const char *method)
{
    const fs_method *m = find(method);
    return m ? m->description : NULL;
}

const char *fluidsurf_method_paper(const char *method)
{
    const fs_method *m = find(method);
    return m ? m->paper : NULL;
}

int fluidsurf_method_needs_gl(const char *method)
{
    const fs_method *m = find(method);
    return m ? m->needs_gl : -1;
}

int fluidsurf_param_count(const char *method)
{
    const fs_method *m = find(method);
    return m ? m->nparams : -1;
}

int fluidsurf_param_info(const char *method, int j, fluidsurf_param *out)
{
    static const char *const types[] = {"float", "int", "bool", "enum"};
    const fs_method *m = find(method);
    int rc = fs_api_check(out, "out");
    if (rc) return rc;
    if (!m) return fs_method_fail_unknown(NULL, method ? method : "(null)");
    if (j < 0 || j >= m->nparams)
        return fs_fail(FS_ERR_INPUT, "%s has %d parameters, not %d", m->name, m->nparams, j + 1);
    const fs_param_def *d = &m->params[j];
    *out = (fluidsurf_param){d->name, types[d->type], d->def, d->min, d->max, d->choices ? d->choices : "", d->help};
    return FLUIDSURF_OK;
}
