/* A scene written back as a scene file (scene.h, fs_scene_save): what a run
 * settled (r, the up axis, the framed camera) as plain keys, so that rendering
 * the file reproduces the run. Numbers are written with %.9g, a float's every
 * bit, and paths absolute, so the file may live in any folder. */
#include "scene.h"
#include "fs_error.h"
#include "obstacle_mesh.h"
#include "output_file.h"
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>

static cJSON *num(double v)
{
    char t[32];
    snprintf(t, sizeof t, "%.9g", v);
    return cJSON_CreateRaw(t);
}

static cJSON *vec(const float v[3])
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < 3; i++) cJSON_AddItemToArray(a, num(v[i]));
    return a;
}

/* path made absolute (its folder resolved; the name may be a frame pattern);
 * out has room for a folder (PATH_MAX) and a scene's path (FS_PATH_MAX). */
static void absolute(const char *path, char out[PATH_MAX + FS_PATH_MAX + 2], size_t size)
{
    char dir[PATH_MAX], real[PATH_MAX];
    const char *slash = strrchr(path, '/'), *name = slash ? slash + 1 : path;
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) : 1, slash ? path : ".");
    if (!dir[0]) strcpy(dir, "/");
    if (realpath(dir, real)) snprintf(out, size, "%.4095s%s%.1023s", real, strcmp(real, "/") ? "/" : "", name);
    else snprintf(out, size, "%s", path);
}

static cJSON *synthetic(const fs_scene *s)
{
    static const char *const shapes[] = {"", "slab", "sphere", "box"};
    cJSON *o = cJSON_CreateObject(), *size = cJSON_CreateArray();
    cJSON_AddStringToObject(o, "synthetic", shapes[s->synth.shape]);
    for (int i = 0; i < 3 && s->synth.size[i] > 0; i++)
        cJSON_AddItemToArray(size, cJSON_CreateNumber(s->synth.size[i]));
    if (cJSON_GetArraySize(size)) cJSON_AddItemToObject(o, "size", size);
    else cJSON_Delete(size);
    cJSON_AddItemToObject(o, "jitter", num(s->synth.jitter));
    cJSON_AddNumberToObject(o, "seed", s->synth.seed);
    cJSON_AddBoolToObject(o, "moving", s->synth.moving);
    if (s->frame_first >= 0) {
        cJSON_AddNumberToObject(o, "first", s->frame_first);
        cJSON_AddNumberToObject(o, "last", s->frame_last);
    }
    return o;
}

static cJSON *particles(const fs_scene *s)
{
    if (s->synth.shape != FS_SYNTH_NONE) return synthetic(s);
    char file[PATH_MAX + FS_PATH_MAX + 2];
    absolute(s->source, file, sizeof file);
    if (s->frame_first < 0 && !s->format[0]) return cJSON_CreateString(file);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "file", file);
    if (s->format[0]) cJSON_AddStringToObject(o, "format", s->format);
    if (s->frame_first >= 0) {
        cJSON_AddNumberToObject(o, "first", s->frame_first);
        cJSON_AddNumberToObject(o, "last", s->frame_last);
        if (s->frame_step > 1) cJSON_AddNumberToObject(o, "step", s->frame_step);
    }
    return o;
}

/* The camera; its up only when its own (camera_up_auto: it follows the scene's). */
static cJSON *camera(const fs_scene *s)
{
    const fs_camera *c = &s->camera;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "eye", vec(c->eye));
    cJSON_AddItemToObject(o, "target", vec(c->target));
    if (!s->camera_up_auto) cJSON_AddItemToObject(o, "up", vec(c->up));
    cJSON_AddItemToObject(o, "fov", num(c->fovy_deg));
    cJSON_AddNumberToObject(o, "width", c->width);
    cJSON_AddNumberToObject(o, "height", c->height);
    return o;
}

static void look(const fs_scene *s, cJSON *root)
{
    cJSON *light = cJSON_AddObjectToObject(root, "light"), *mat = cJSON_AddObjectToObject(root, "material");
    cJSON_AddItemToObject(light, "direction", vec(s->light_dir));
    cJSON_AddItemToObject(light, "color", vec(s->light_color));
    cJSON_AddItemToObject(light, "ambient", num(s->ambient));
    cJSON_AddStringToObject(mat, "type", s->material == FS_MATERIAL_OPAQUE ? "opaque" : "water");
    cJSON_AddItemToObject(mat, "color", vec(s->material_color));
    cJSON_AddItemToObject(mat, "ior", num(s->ior));
    cJSON_AddItemToObject(mat, "absorption", vec(s->absorption));
    cJSON_AddStringToObject(root, "background", s->background == FS_BACKGROUND_SKY ? "sky" : "checker");
}

static cJSON *obstacle(const fs_obstacle *o)
{
    cJSON *e = cJSON_CreateObject();
    if (o->kind == FS_OBSTACLE_MESH) {
        char file[PATH_MAX + FS_PATH_MAX + 2];
        absolute(o->mesh->path, file, sizeof file);
        cJSON_AddStringToObject(e, "mesh", file);
        cJSON_AddItemToObject(e, "scale", num(o->scale));
        cJSON_AddItemToObject(e, "offset", vec(o->offset));
    } else if (o->kind == FS_OBSTACLE_SPHERE) {
        cJSON_AddItemToObject(e, "centre", vec(o->c));
        cJSON_AddItemToObject(e, "radius", num(o->radius));
    } else {
        cJSON_AddItemToObject(e, "min", vec(o->lo));
        cJSON_AddItemToObject(e, "max", vec(o->hi));
    }
    cJSON_AddItemToObject(e, "color", vec(o->color));
    return e;
}

/* "method.param=value" settings as {"method": {"param": value}}: a number
 * stays a number, anything else ("on", a choice) a string. */
static cJSON *methods(const fs_scene *s)
{
    cJSON *all = cJSON_CreateObject();
    for (int i = 0; i < s->nsets; i++) {
        char m[160];
        snprintf(m, sizeof m, "%s", s->sets[i].text);
        char *dot = strchr(m, '.'), *eq = dot ? strchr(dot, '=') : NULL;
        if (!eq) continue; /* fs_scene_add_set stored only well-formed settings */
        *dot = *eq = 0;
        cJSON *per = cJSON_GetObjectItemCaseSensitive(all, m);
        if (!per) per = cJSON_AddObjectToObject(all, m);
        char *end;
        double v = strtod(eq + 1, &end);
        cJSON_DeleteItemFromObjectCaseSensitive(per, dot + 1); /* a later setting wins */
        if (end != eq + 1 && !*end && isfinite(v)) cJSON_AddItemToObject(per, dot + 1, num(v));
        else cJSON_AddStringToObject(per, dot + 1, eq + 1);
    }
    return all;
}

static cJSON *scene_json(const fs_scene *s)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "description", "a fluidsurf render's scene (render --save-scene)");
    cJSON_AddItemToObject(root, "particles", particles(s));
    cJSON_AddItemToObject(root, "radius", num(s->radius));
    cJSON_AddItemToObject(root, "volume_scale", num(s->volume_scale));
    cJSON_AddStringToObject(root, "kernel", fs_kernel_name(s->kernel));
    cJSON_AddItemToObject(root, "support", num(s->support_r));
    cJSON_AddItemToObject(root, "iso", num(s->iso));
    char up[2] = {(char)('x' + s->up_axis), 0};
    cJSON_AddStringToObject(root, "up", up);
    cJSON_AddItemToObject(root, "camera", camera(s));
    look(s, root);
    if (s->obstacles.n) {
        cJSON *ob = cJSON_AddArrayToObject(root, "obstacles");
        for (int i = 0; i < s->obstacles.n; i++) cJSON_AddItemToArray(ob, obstacle(&s->obstacles.o[i]));
    }
    if (s->nsets) cJSON_AddItemToObject(root, "methods", methods(s));
    return root;
}

int fs_scene_save(const fs_scene *s, const char *path)
{
    cJSON *root = scene_json(s);
    char *text = root ? cJSON_Print(root) : NULL;
    cJSON_Delete(root);
    if (!text) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for the scene", path);
    fs_output o;
    int rc = fs_output_open(&o, path);
    if (!rc) {
        fputs(text, o.f);
        fputc('\n', o.f);
        rc = fs_output_close(&o, 1);
    }
    free(text);
    return rc;
}
