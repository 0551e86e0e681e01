#include "params.h"
#include "fs_error.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fs_param_choice(const fs_param_def *def, const char *name)
{
    const char *c = def->choices;
    size_t len = strlen(name);
    for (int i = 0; c && *c; i++) {
        const char *bar = strchr(c, '|');
        size_t n = bar ? (size_t)(bar - c) : strlen(c);
        if (n == len && !strncmp(c, name, n)) return i;
        if (!bar) break;
        c = bar + 1;
    }
    return -1;
}

int fs_param_parse(const fs_param_def *def, const char *text, double *out, const char *what)
{
    if (def->type == FS_PARAM_ENUM) {
        int i = fs_param_choice(def, text);
        if (i < 0) return fs_fail(FS_ERR_INPUT, "%s: '%s' is not one of %s", what, text, def->choices);
        *out = i;
        return FS_OK;
    }
    if (def->type == FS_PARAM_BOOL) {
        if (!strcmp(text, "on") || !strcmp(text, "1") || !strcmp(text, "true")) {
            *out = 1;
            return FS_OK;
        }
        if (!strcmp(text, "off") || !strcmp(text, "0") || !strcmp(text, "false")) {
            *out = 0;
            return FS_OK;
        }
        return fs_fail(FS_ERR_INPUT, "%s: '%s' is not on or off", what, text);
    }
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end || errno || !isfinite(v))
        return fs_fail(FS_ERR_INPUT, "%s: '%s' is not a number", what, text);
    if (def->type == FS_PARAM_INT && v != floor(v))
        return fs_fail(FS_ERR_INPUT, "%s: '%s' is not an integer", what, text);
    if (v < def->min || v > def->max)
        return fs_fail(FS_ERR_INPUT, "%s: %s is outside [%g, %g]", what, text, def->min, def->max);
    *out = v;
    return FS_OK;
}

void fs_param_format(const fs_param_def *def, double v, char *buf, int size)
{
    if (def->type == FS_PARAM_BOOL) {
        snprintf(buf, size, "%s", v != 0 ? "on" : "off");
        return;
    }
    if (def->type == FS_PARAM_ENUM) {
        const char *c = def->choices;
        for (int i = 0; i < (int)v && c; i++) {
            c = strchr(c, '|');
            if (c) c++;
        }
        if (!c) {
            snprintf(buf, size, "?");
            return;
        }
        const char *bar = strchr(c, '|');
        snprintf(buf, size, "%.*s", bar ? (int)(bar - c) : (int)strlen(c), c);
        return;
    }
    snprintf(buf, size, "%g", v);
}

int fs_param_split(const char *text, fs_param_setting *out)
{
    const char *dot = strchr(text, '.'), *eq = strchr(text, '=');
    if (!dot || !eq || dot > eq || dot == text || eq == dot + 1 || !eq[1])
        return fs_fail(FS_ERR_INPUT, "%s: expected METHOD.PARAM=VALUE", text);
    int nm = (int)(dot - text), np = (int)(eq - dot - 1);
    if (nm >= (int)sizeof out->method || np >= (int)sizeof out->param)
        return fs_fail(FS_ERR_INPUT, "%s: method or parameter name too long", text);
    snprintf(out->method, sizeof out->method, "%.*s", nm, text);
    snprintf(out->param, sizeof out->param, "%.*s", np, dot + 1);
    out->value = eq + 1;
    return FS_OK;
}

size_t fs_param_ctype_size(fs_param_ctype c)
{
    return c == FS_CTYPE_DOUBLE ? sizeof(double) : (c == FS_CTYPE_BOOL ? sizeof(bool) : sizeof(int));
}
