#include "caller_words.h"
#include "sweep.h"
#include "fs_error.h"
#include "method_params.h"
#include <ctype.h>
#include <stdio.h>
#include <string.h>

int fs_sweep_add(fs_sweep *sweeps, int *nsweeps, const char *spec)
{
    fs_method_setting set;
    int rc = fs_method_setting_find(spec, &set);
    if (rc) return rc;
    if (*nsweeps == FS_MAX_SWEEPS) return fs_fail(FS_ERR_INPUT, "%s %s: too many sweeps", fs_word("set"), spec);
    fs_sweep *sw = &sweeps[*nsweeps];
    memset(sw, 0, sizeof *sw);
    sw->m = set.m;
    sw->param = set.param;
    for (int i = 0; i < *nsweeps; i++)
        if (sweeps[i].m == sw->m && sweeps[i].param == sw->param)
            return fs_fail(FS_ERR_INPUT, "%s %s: %s.%s is swept twice", fs_word("set"), spec, sw->m->name,
                           sw->m->params[sw->param].name);
    for (const char *v = set.value; *v;) {
        const char *comma = strchr(v, ',');
        int len = comma ? (int)(comma - v) : (int)strlen(v);
        if (sw->nvalues == FS_MAX_SWEEP_VALUES)
            return fs_fail(FS_ERR_INPUT, "%s %s: too many values", fs_word("set"), spec);
        if (len <= 0 || len >= (int)sizeof sw->values[0])
            return fs_fail(FS_ERR_INPUT, "%s %s: empty or long value", fs_word("set"), spec);
        snprintf(sw->values[sw->nvalues], sizeof sw->values[0], "%.*s", len, v);
        double parsed;
        if ((rc = fs_method_setting_parse(&set, sw->values[sw->nvalues], &parsed))) return rc;
        sw->nvalues++;
        v += len + (comma ? 1 : 0);
        if (comma && !*v) return fs_fail(FS_ERR_INPUT, "%s %s: trailing comma", fs_word("set"), spec);
    }
    (*nsweeps)++;
    return FS_OK;
}

void fs_label_value(const char *value, char *out, int size)
{
    int n = 0;
    for (const char *c = value; *c && n + 1 < size; c++) {
        unsigned char ch = (unsigned char)*c;
        if (ch == '+') continue;
        out[n++] = isalnum(ch) || ch == '_' ? (char)ch : ch == '.' ? 'p' : ch == '-' ? 'm' : 'x';
    }
    if (size > 0) out[n] = 0;
}

int fs_label_is_safe(const char *text)
{
    if (!*text) return 0;
    for (const char *c = text; *c; c++)
        if (!isalnum((unsigned char)*c) && *c != '_' && *c != '-') return 0;
    return 1;
}

int fs_sweep_variants(const fs_method *m, const fs_scene *s, const fs_sweep *sweeps, int nsweeps, fs_variant *out,
                      int max)
{
    int mine[FS_MAX_SWEEPS], n = 0, total = 1;
    for (int i = 0; i < nsweeps; i++)
        if (sweeps[i].m == m) {
            mine[n++] = i;
            total *= sweeps[i].nvalues;
        }
    if (total > max) return -fs_fail(FS_ERR_INPUT, "%s: %d variants, at most %d", m->name, total, max);
    double base[FS_MAX_PARAMS] = {0};
    int rc = fs_method_params_resolve(m, s, base);
    if (rc) return -rc;
    for (int v = 0; v < total; v++) {
        fs_variant *o = &out[v];
        memset(o, 0, sizeof *o);
        o->m = m;
        memcpy(o->params, base, sizeof base);
        snprintf(o->label, sizeof o->label, "%s", m->name);
        int rest = v, lab = (int)strlen(o->label), var = 0;
        /* the first sweep varies slowest, so a 2-parameter grid reads row by row */
        int idx[FS_MAX_SWEEPS];
        for (int k = n - 1; k >= 0; k--) {
            idx[k] = rest % sweeps[mine[k]].nvalues;
            rest /= sweeps[mine[k]].nvalues;
        }
        for (int k = 0; k < n; k++) {
            const fs_sweep *sw = &sweeps[mine[k]];
            const fs_param_def *def = &m->params[sw->param];
            fs_param_parse(def, sw->values[idx[k]], &o->params[sw->param], def->name);
            char safe[sizeof sw->values[0]];
            fs_label_value(sw->values[idx[k]], safe, sizeof safe);
            lab += snprintf(o->label + lab, sizeof o->label - lab, "_%s-%s", def->name, safe);
            var += snprintf(o->variant + var, sizeof o->variant - var, "%s%s=%s", k ? ";" : "", def->name,
                            sw->values[idx[k]]);
            if (lab >= (int)sizeof o->label ||
                var >= (int)sizeof o->variant) /* a cut label could name another variant */
                return -fs_fail(FS_ERR_INPUT, "%s: the sweep's variant names are longer than %d characters", m->name,
                                (int)sizeof o->label - 1);
            if (k < 2) {
                o->sweep_index[k] = mine[k];
                o->value_index[k] = idx[k];
            }
        }
        o->nswept = n;
    }
    return total;
}
