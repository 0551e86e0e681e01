#include "method_params.h"
#include "fs_error.h"
#include <stdio.h>
#include <string.h>

int fs_method_params_resolve(const fs_method *m, const fs_scene *s, double values[FS_MAX_PARAMS])
{
    for (int i = 0; i < m->nparams; i++) values[i] = m->params[i].def;
    for (int k = 0; k < s->nsets; k++) {
        const char *set = s->sets[k], *dot = strchr(set, '.'), *eq = strchr(set, '=');
        char mname[64], pname[64];
        snprintf(mname, sizeof mname, "%.*s", (int)(dot - set), set);
        snprintf(pname, sizeof pname, "%.*s", (int)(eq - dot - 1), dot + 1);
        const fs_method *target = fs_method_find(mname);
        if (!target) return fs_fail(FS_ERR_INPUT, "--set %s: unknown method '%s' (see 'fluidsurf methods')", set, mname);
        int idx = fs_method_param_index(target, pname);
        if (idx < 0) return fs_fail(FS_ERR_INPUT, "--set %s: %s has no parameter '%s'", set, mname, pname);
        double v;
        char what[200];
        snprintf(what, sizeof what, "--set %s.%s", mname, pname);
        int rc = fs_param_parse(&target->params[idx], eq + 1, &v, what);
        if (rc) return rc;
        if (target == m) values[idx] = v;
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
