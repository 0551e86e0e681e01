#include "cli.h"
#include "method.h"
#include "builtin_methods.h"
#include "method_params.h"
#include "fs_error.h"
#include "frame_pattern.h"
#include "frame_source.h"
#include "camera_text.h"
#include "render_output.h"
#include "gl_context.h"
#include "hash.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int cli_error(int code)
{
    fprintf(stderr, "fluidsurf: %s\n", fs_error_message());
    return code;
}

int cli_usage(const char *cmd, const char *fmt, ...)
{
    char raw[1024], text[1024]; /* the user's arguments are echoed: as one line of text */
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    fs_text_line(text, sizeof text, raw);
    fprintf(stderr, "fluidsurf: %s (try 'fluidsurf %s --help')\n", text, cmd);
    return FS_ERR_INPUT;
}

int cli_unknown_method(const char *cmd, const char *option, const char *name)
{
    const char *need = fs_method_needs_option(name);
    if (need) {
        fprintf(stderr, "fluidsurf: %s %s needs a build with %s=ON\n", option, name, need);
        return FS_ERR_INPUT;
    }
    fs_method_fail_unknown(NULL, name);
    return cli_usage(cmd, "%s", fs_error_message());
}

int cli_sets_run(const char *const *sets, int nsets, const fs_method *const *run, int nrun)
{
    for (int i = 0; i < nsets; i++) {
        fs_param_setting split;
        int rc = fs_param_split(sets[i], &split), found = 0;
        if (rc) return rc;
        for (int k = 0; k < nrun; k++) found |= !strcmp(run[k]->name, split.method);
        if (found) continue;
        char names[600] = "";
        for (int k = 0, n = 0; k < nrun && n < (int)sizeof names; k++)
            n += snprintf(names + n, sizeof names - n, "%s%s", k ? ", " : "", run[k]->name);
        return fs_fail(FS_ERR_INPUT, "--set %s: %s does not run here (what runs: %s)", sets[i], split.method, names);
    }
    return FS_OK;
}

int cli_scene_from_arg(fs_scene *s, const char *arg)
{
    size_t n = strlen(arg);
    if (n > 5 && !strcmp(arg + n - 5, ".json")) return fs_scene_load(s, arg);
    fs_scene_defaults(s);
    if (n >= sizeof s->source) return fs_fail(FS_ERR_INPUT, "%s: path too long", arg);
    strcpy(s->source, arg);
    s->up_source = FS_UP_AUTO;
    s->hash = fs_fnv1a(FS_SCENE_HASH_START, arg, n);
    return FS_OK;
}

int cli_scene_pattern(const char *cmd, fs_scene *s, const char *in, const char *frames)
{
    size_t n = strlen(in);
    int json = n > 5 && !strcmp(in + n - 5, ".json"), a, b, step;
    if (json || !fs_is_frame_pattern(in))
        return frames ? cli_usage(cmd, "--frames: %s is not a frame pattern", in) : FS_OK;
    if (!frames) return cli_usage(cmd, "%s: a frame pattern needs --frames FIRST:LAST[:STEP]", in);
    if (fs_frame_range(frames, &a, &b, &step))
        return cli_usage(cmd, "--frames %s: expected FIRST:LAST[:STEP] (0 <= FIRST <= LAST, STEP >= 1)", frames);
    int rc = fs_scene_set_frames(s, in, a, b, step);
    return rc ? cli_error(rc) : FS_OK;
}

int cli_scene_camera(const char *cmd, fs_scene *s, const char *text, const char *from)
{
    if (text && from) return cli_usage(cmd, "--camera and --camera-from: choose one");
    if (!text && !from) return FS_OK;
    fs_camera c = s->camera;
    unsigned given = FS_CAMERA_HAS_UP;
    int rc = from ? fs_read_render_camera(from, &c) : fs_camera_parse(text, "--camera", &c, &given);
    if (rc) return cli_error(rc);
    fs_scene_place_camera(s, &c, (given & FS_CAMERA_HAS_UP) != 0);
    return FS_OK;
}

void cli_scene_opts_apply(fs_scene *s, const cli_scene_opts *o)
{
    if (o->up == CLI_UP_AUTO) s->up_source = FS_UP_AUTO;
    else if (o->up >= 0) s->up_axis = o->up, s->up_source = FS_UP_OPTION;
    if (o->kernel >= 0) s->kernel = (fs_kernel)o->kernel;
    if (o->volume_scale > 0) s->volume_scale = o->volume_scale;
    if (o->iso > 0) s->iso = o->iso;
    if (o->support > 0) s->support_r = o->support;
    if (o->up >= 0 || o->kernel >= 0 || o->volume_scale > 0 || o->iso > 0 || o->support > 0)
        s->hash = fs_fnv1a(s->hash, o, sizeof *o);
}

int cli_int(const char *cmd, const char *opt, const char *text, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    long v = text ? strtol(text, &end, 10) : 0;
    if (!text || end == text || *end || errno || v < lo || v > hi)
        return cli_usage(cmd, "%s %s: expected an integer in [%d, %d]", opt, text ? text : "(missing)", lo, hi);
    *out = (int)v;
    return FS_OK;
}

int cli_float(const char *cmd, const char *opt, const char *text, double lo, double hi, float *out)
{
    char *end;
    errno = 0;
    double v = text ? strtod(text, &end) : 0;
    if (!text || end == text || *end || errno || !isfinite(v) || v < lo || v > hi)
        return cli_usage(cmd, "%s %s: expected a number in [%g, %g]", opt, text ? text : "(missing)", lo, hi);
    *out = (float)v;
    return FS_OK;
}

int cli_gl_context_create(fs_gl_context *c, fs_ctx_kind kind, int width, int height)
{
    static int said; /* a process may make several contexts: the line is said once */
    int rc = fs_gl_context_create(c, kind, width, height);
    if (rc || kind != FS_CTX_EGL || said) return rc;
    said = 1;
    fs_note("OpenGL: %s (EGL device %d of %d)", c->renderer, c->device, c->ndevices);
    return FS_OK;
}

int cli_same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}
