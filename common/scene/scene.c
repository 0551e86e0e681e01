#include "scene.h"
#include "fs_error.h"
#include "frame_pattern.h"
#include "hash.h"
#include "params.h"
#include "path_beside.h"
#include "grid.h"
#include "particles.h"
#include "vec3.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <cjson/cJSON.h>

void fs_scene_defaults(fs_scene *s)
{
    memset(s, 0, sizeof *s);
    s->frame_first = s->frame_last = -1;
    s->frame_step = 1;
    s->synth.jitter = 0.1f;
    s->synth.seed = 1;
    s->radius = 0.025f;
    s->volume_scale = 1.0f;
    s->kernel = FS_KERNEL_CUBIC;
    s->support_r = 4.0f;
    s->iso = 0.6f;
    s->up_axis = 1;
    s->camera.fovy_deg = 40.0f;
    s->camera.width = 512;
    s->camera.height = 512;
    float l[3] = {0.35f, 0.85f, 0.4f}, n = fs_v3_len(l);
    for (int i = 0; i < 3; i++) {
        s->light_dir[i] = l[i] / n;
        s->light_color[i] = 1.0f;
    }
    s->ambient = 0.25f;
    s->material = FS_MATERIAL_WATER;
    s->material_color[0] = 0.55f;
    s->material_color[1] = 0.75f;
    s->material_color[2] = 0.95f;
    s->ior = 1.333f;
    /* Clear water tinted blue over a few tens of particle diameters. */
    s->absorption[0] = 1.2f;
    s->absorption[1] = 0.45f;
    s->absorption[2] = 0.2f;
    s->background = FS_BACKGROUND_CHECKER;
}

const char *fs_radius_source_name(fs_radius_source r)
{
    static const char *const names[] = {"default", "scene", "file", "option", "estimated"};
    return (unsigned)r < 5 ? names[r] : "?";
}

const char *fs_up_source_name(fs_up_source u)
{
    static const char *const names[] = {"default", "scene", "option", "auto"};
    return (unsigned)u < 4 ? names[u] : "?";
}

fs_field fs_scene_field(const fs_scene *s)
{
    fs_field f;
    float d = 2.0f * s->radius;
    f.r = s->radius;
    f.volume = s->volume_scale * d * d * d;
    f.kernel = s->kernel;
    f.H = s->support_r * s->radius;
    f.iso = s->iso;
    return f;
}

void fs_scene_place_camera(fs_scene *s, const fs_camera *c, int up_given)
{
    s->camera = *c;
    s->has_camera = 1;
    s->camera_up_auto = !up_given;
}

static fs_scene_resolver resolver;

void fs_scene_set_resolver(fs_scene_resolver r) { resolver = r; }

int fs_scene_add_set(fs_scene *s, const char *set)
{
    fs_param_setting split;
    int rc = fs_param_split(set, &split);
    if (rc) return rc;
    if (s->nsets == FS_MAX_SETS) return fs_fail(FS_ERR_INPUT, "setting %.80s: more than %d settings", set, FS_MAX_SETS);
    fs_scene_setting *st = &s->sets[s->nsets];
    if (strlen(set) >= sizeof st->text)
        return fs_fail(FS_ERR_INPUT, "setting %.80s...: longer than %d characters", set, (int)sizeof st->text - 1);
    memset(st, 0, sizeof *st);
    strcpy(st->text, set);
    if (resolver && (rc = resolver(st))) return rc;
    s->nsets++;
    return FS_OK;
}

void fs_scene_finish_camera(fs_scene *s, const float bmin[3], const float bmax[3])
{
    if (!s->has_camera) fs_camera_frame_box(&s->camera, bmin, bmax, s->up_axis);
    if (s->has_camera && s->camera_up_auto)
        for (int i = 0; i < 3; i++) s->camera.up[i] = i == s->up_axis ? 1.0f : 0.0f;
    /* Clip planes enclose the particles grown by the kernel support. */
    float g = s->support_r * s->radius, lo[3], hi[3];
    for (int i = 0; i < 3; i++) {
        lo[i] = bmin[i] - g;
        hi[i] = bmax[i] + g;
    }
    fs_camera_fit_clip(&s->camera, lo, hi);
}

float fs_scene_floor(const fs_scene *s, const fs_grid *g) { return g->bulk_lo[s->up_axis] - s->radius; }

/* The bulk box of p (grid.h) with cells of the support H = support_r r; the
 * bounding box when the grid cannot be built (the run reports why later). */
static void bulk_box(const fs_scene *s, const fs_particles *p, float r, float lo[3], float hi[3])
{
    memcpy(lo, p->bmin, 3 * sizeof *lo);
    memcpy(hi, p->bmax, 3 * sizeof *hi);
    fs_grid g;
    if (!p->n || fs_grid_build(&g, p, s->support_r * r)) return;
    memcpy(lo, g.bulk_lo, 3 * sizeof *lo);
    memcpy(hi, g.bulk_hi, 3 * sizeof *hi);
    fs_grid_free(&g);
}

float fs_scene_floor_of(const fs_scene *s, const fs_particles *p)
{
    float lo[3], hi[3];
    bulk_box(s, p, s->radius, lo, hi);
    return lo[s->up_axis] - s->radius;
}

void fs_scene_frame_particles(fs_scene *s, const fs_particles *p)
{
    float blo[3], bhi[3], r = s->spacing_r > 0 ? s->spacing_r : s->radius;
    bulk_box(s, p, r, blo, bhi);
    if (!s->has_camera) {
        float lo[3], hi[3];
        fs_particles_core_bounds_in(p, 0.01f, blo, bhi, lo, hi);
        for (int i = 0; i < 3; i++) {
            lo[i] -= r;
            hi[i] += r;
        }
        fs_camera_frame_box(&s->camera, lo, hi, s->up_axis);
        s->has_camera = 1;
    }
    fs_scene_finish_camera(s, blo, bhi);
}

/* ---- JSON scene files ---- */

typedef struct jctx {
    const char *path;
    int rc;
} jctx;

static int bad(jctx *c, const char *key, const char *what)
{
    if (!c->rc) c->rc = fs_fail(FS_ERR_INPUT, "%s: \"%s\" %s", c->path, key, what);
    return c->rc;
}

/* Each key of obj appears once: cJSON would let the first of two "radius" keys
 * win without a word. */
static void check_unique(jctx *c, const cJSON *obj)
{
    for (const cJSON *it = obj->child; it && !c->rc; it = it->next)
        for (const cJSON *later = it->next; later && !c->rc; later = later->next)
            if (it->string && later->string && !strcmp(it->string, later->string)) bad(c, it->string, "appears twice");
}

/* Every key of obj must be one of allowed, and appear once. */
static void check_keys(jctx *c, const cJSON *obj, const char *where, const char *const *allowed)
{
    check_unique(c, obj);
    for (const cJSON *it = obj->child; it && !c->rc; it = it->next) {
        int ok = 0;
        for (const char *const *a = allowed; *a; a++) ok |= !strcmp(*a, it->string);
        if (!ok) {
            char msg[256];
            snprintf(msg, sizeof msg, "is not a known key%s%s", where ? " of " : "", where ? where : "");
            bad(c, it->string, msg);
        }
    }
}

static void get_num(jctx *c, const cJSON *o, const char *key, float *out, double lo, double hi)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v || c->rc) return;
    if (!cJSON_IsNumber(v)) {
        bad(c, key, "must be a number");
        return;
    }
    if (!(v->valuedouble >= lo && v->valuedouble <= hi)) {
        char msg[128];
        snprintf(msg, sizeof msg, "must lie in [%g, %g], got %g", lo, hi, v->valuedouble);
        bad(c, key, msg);
        return;
    }
    *out = (float)v->valuedouble;
}

/* Integers are read as the double JSON holds (not through a float, which has 24
 * bits), checked against [lo, hi] before the conversion. */
static void get_int(jctx *c, const cJSON *o, const char *key, int *out, int lo, int hi)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v || c->rc) return;
    if (!cJSON_IsNumber(v)) {
        bad(c, key, "must be a number");
        return;
    }
    double d = v->valuedouble;
    if (!(d >= lo && d <= hi)) {
        char msg[128];
        snprintf(msg, sizeof msg, "must lie in [%d, %d], got %g", lo, hi, d);
        bad(c, key, msg);
        return;
    }
    if (d != floor(d)) {
        bad(c, key, "must be an integer");
        return;
    }
    *out = (int)d;
}

static void get_vec3(jctx *c, const cJSON *o, const char *key, float out[3])
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v || c->rc) return;
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 3) {
        bad(c, key, "must be an array of 3 numbers");
        return;
    }
    for (int i = 0; i < 3; i++) {
        const cJSON *e = cJSON_GetArrayItem(v, i);
        if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble)) {
            bad(c, key, "must be an array of 3 numbers");
            return;
        }
        out[i] = (float)e->valuedouble;
    }
}

static const char *get_str(jctx *c, const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v || c->rc) return NULL;
    if (!cJSON_IsString(v)) {
        bad(c, key, "must be a string");
        return NULL;
    }
    return v->valuestring;
}

static void set_path(fs_scene *s, jctx *c, const char *file)
{
    if (fs_path_beside(s->path, file, s->source, sizeof s->source)) bad(c, "particles", "path is too long");
}

/* A synthetic set's keys (shape syn). */
static void parse_synthetic(fs_scene *s, jctx *c, const cJSON *v, const char *syn)
{
    static const char *const shapes[] = {"", "slab", "sphere", "box"};
    for (int i = 1; i < 4; i++)
        if (!strcmp(syn, shapes[i])) s->synth.shape = (fs_synth_shape)i;
    if (!s->synth.shape) {
        bad(c, "synthetic", "must be slab, sphere or box");
        return;
    }
    const cJSON *size = cJSON_GetObjectItemCaseSensitive(v, "size");
    if (size) {
        int n = cJSON_IsArray(size) ? cJSON_GetArraySize(size) : 0;
        if (n < 1 || n > 3) {
            bad(c, "size", "must be an array of 1 to 3 particle counts");
            return;
        }
        for (int i = 0; i < n; i++) {
            const cJSON *e = cJSON_GetArrayItem(size, i);
            if (!cJSON_IsNumber(e) || e->valuedouble < 1 || e->valuedouble > 1000 ||
                e->valuedouble != floor(e->valuedouble)) {
                bad(c, "size", "entries must be integers in [1, 1000]");
                return;
            }
            s->synth.size[i] = (int)e->valuedouble;
        }
    }
    get_num(c, v, "jitter", &s->synth.jitter, 0, 1);
    int seed = (int)s->synth.seed;
    get_int(c, v, "seed", &seed, 0, 2147483647);
    s->synth.seed = (unsigned)seed;
    const cJSON *mv = cJSON_GetObjectItemCaseSensitive(v, "moving");
    if (mv && !cJSON_IsBool(mv)) bad(c, "moving", "must be true or false");
    s->synth.moving = mv && cJSON_IsTrue(mv);
}

/* A sequence's file: a printf pattern, or {} for the frame number. */
static void frame_pattern(fs_scene *s, jctx *c)
{
    char pat[sizeof s->source];
    if (fs_frame_pattern(s->source, pat, sizeof pat)) bad(c, "file", "needs one {} or %d for the frame number");
    else strcpy(s->source, pat);
}

static void parse_particles(fs_scene *s, jctx *c, const cJSON *v)
{
    if (cJSON_IsString(v)) {
        set_path(s, c, v->valuestring);
        return;
    }
    if (!cJSON_IsObject(v)) {
        bad(c, "particles", "must be a file name or an object");
        return;
    }
    static const char *const keys[] = {"file", "format", "first", "last",   "step", "synthetic",
                                       "size", "jitter", "seed",  "moving", NULL};
    check_keys(c, v, "particles", keys);
    const char *file = get_str(c, v, "file"), *fmt = get_str(c, v, "format"), *syn = get_str(c, v, "synthetic");
    if (c->rc) return;
    if (!!file == !!syn) {
        bad(c, "particles", "needs exactly one of \"file\" and \"synthetic\"");
        return;
    }
    if (file) set_path(s, c, file);
    if (fmt) snprintf(s->format, sizeof s->format, "%s", fmt);
    if (syn) parse_synthetic(s, c, v, syn);
    const cJSON *first = cJSON_GetObjectItemCaseSensitive(v, "first"),
                *last = cJSON_GetObjectItemCaseSensitive(v, "last");
    if (!!first != !!last) {
        bad(c, first ? "first" : "last", "needs both \"first\" and \"last\"");
        return;
    }
    if (first && file) frame_pattern(s, c);
    if (first) {
        get_int(c, v, "first", &s->frame_first, 0, 100000000);
        get_int(c, v, "last", &s->frame_last, 0, 100000000);
        get_int(c, v, "step", &s->frame_step, 1, 100000000);
        if (!c->rc && s->frame_last < s->frame_first) bad(c, "last", "is before \"first\"");
    } else if (cJSON_GetObjectItemCaseSensitive(v, "step")) bad(c, "step", "needs \"first\" and \"last\"");
}

static void parse_camera(fs_scene *s, jctx *c, const cJSON *v)
{
    if (!cJSON_IsObject(v)) {
        bad(c, "camera", "must be an object");
        return;
    }
    static const char *const keys[] = {"eye", "target", "up", "fov", "width", "height", NULL};
    check_keys(c, v, "camera", keys);
    fs_camera *cam = &s->camera;
    int has_eye = cJSON_GetObjectItemCaseSensitive(v, "eye") != NULL;
    int has_target = cJSON_GetObjectItemCaseSensitive(v, "target") != NULL;
    if (has_eye != has_target) {
        bad(c, has_eye ? "eye" : "target", "needs both \"eye\" and \"target\"");
        return;
    }
    cam->up[0] = cam->up[2] = 0;
    cam->up[1] = 1;
    get_vec3(c, v, "eye", cam->eye);
    get_vec3(c, v, "target", cam->target);
    get_vec3(c, v, "up", cam->up);
    get_num(c, v, "fov", &cam->fovy_deg, 1, 170);
    get_int(c, v, "width", &cam->width, 1, 16384);
    get_int(c, v, "height", &cam->height, 1, 16384);
    s->has_camera = has_eye;
    s->camera_up_auto = has_eye && !cJSON_GetObjectItemCaseSensitive(v, "up");
    if (has_eye && !c->rc) {
        float d[3] = {cam->target[0] - cam->eye[0], cam->target[1] - cam->eye[1], cam->target[2] - cam->eye[2]};
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1e-20f) bad(c, "target", "must differ from \"eye\"");
    }
}

static void parse_material(fs_scene *s, jctx *c, const cJSON *v)
{
    const char *type = NULL;
    if (cJSON_IsString(v)) type = v->valuestring;
    else if (cJSON_IsObject(v)) {
        static const char *const keys[] = {"type", "color", "ior", "absorption", NULL};
        check_keys(c, v, "material", keys);
        type = get_str(c, v, "type");
        get_vec3(c, v, "color", s->material_color);
        get_num(c, v, "ior", &s->ior, 1, 3);
        get_vec3(c, v, "absorption", s->absorption);
    } else {
        bad(c, "material", "must be \"water\", \"opaque\" or an object");
        return;
    }
    if (type && !strcmp(type, "opaque")) s->material = FS_MATERIAL_OPAQUE;
    else if (type && strcmp(type, "water")) bad(c, "material", "type must be water or opaque");
}

static void parse_methods(fs_scene *s, jctx *c, const cJSON *v)
{
    if (!cJSON_IsObject(v)) {
        bad(c, "methods", "must be an object of method parameter objects");
        return;
    }
    check_unique(c, v);
    for (const cJSON *m = v->child; m && !c->rc; m = m->next) {
        if (!cJSON_IsObject(m)) {
            bad(c, m->string, "must be an object of parameters");
            return;
        }
        check_unique(c, m);
        for (const cJSON *p = m->child; p && !c->rc; p = p->next) {
            char set[200];
            if (cJSON_IsNumber(p)) snprintf(set, sizeof set, "%s.%s=%.17g", m->string, p->string, p->valuedouble);
            else if (cJSON_IsString(p)) snprintf(set, sizeof set, "%s.%s=%s", m->string, p->string, p->valuestring);
            else if (cJSON_IsBool(p))
                snprintf(set, sizeof set, "%s.%s=%s", m->string, p->string, cJSON_IsTrue(p) ? "on" : "off");
            else {
                bad(c, p->string, "must be a number, a string or a boolean");
                return;
            }
            if (fs_scene_add_set(s, set)) c->rc = fs_fail(FS_ERR_INPUT, "%s: %s", c->path, fs_error_message());
        }
    }
}

static char *read_all(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *buf = NULL;
    size_t cap = 0, n = 0;
    for (;;) {
        if (n + 4096 > cap) {
            cap = (n + 4096) * 2;
            char *nb = realloc(buf, cap);
            if (!nb) {
                free(buf);
                fclose(f);
                return NULL;
            }
            buf = nb;
        }
        size_t got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (!got) break;
    }
    fclose(f);
    buf[n] = 0;
    *len = n;
    return buf;
}

/* The scene file's JSON tree, its bytes' hash kept in s (NULL after an error). */
static cJSON *parse_file(fs_scene *s, const char *path)
{
    size_t len = 0;
    char *text = read_all(path, &len);
    if (!text) {
        fs_fail(FS_ERR_INPUT, "%s: cannot read the scene file", path);
        return NULL;
    }
    s->hash = fs_fnv1a(FS_SCENE_HASH_START, text, len);
    if (!len) {
        free(text);
        fs_fail(FS_ERR_INPUT, "%s: empty scene file", path);
        return NULL;
    }
    const char *err = NULL;
    cJSON *root = cJSON_ParseWithOpts(text, &err, 1);
    if (!root) {
        int line = 1;
        for (const char *p = text; err && p < err; p++) line += *p == '\n';
        fs_fail(FS_ERR_INPUT, "%s: malformed JSON near line %d", path, line);
    }
    free(text);
    return root;
}

/* The field's entries: the particles' radius and volume, the kernel, its support and iso. */
static void parse_field(fs_scene *s, jctx *c, const cJSON *root)
{
    if (cJSON_HasObjectItem(root, "radius")) s->r_source = FS_R_SCENE;
    get_num(c, root, "radius", &s->radius, 1e-9, 1e9);
    get_num(c, root, "volume_scale", &s->volume_scale, 1e-6, 1e6);
    get_num(c, root, "support", &s->support_r, 0.5, 64);
    get_num(c, root, "iso", &s->iso, 1e-6, 1e6);
    const char *k = get_str(c, root, "kernel");
    if (k && (int)(s->kernel = (fs_kernel)fs_kernel_from_name(k)) < 0)
        bad(c, "kernel", "must be cubic, poly6, spiky or wyvill");
}

static void parse_up(fs_scene *s, jctx *c, const cJSON *root)
{
    const char *up = get_str(c, root, "up");
    if (!up) return;
    s->up_source = FS_UP_SCENE;
    if (strlen(up) == 1 && up[0] >= 'x' && up[0] <= 'z') s->up_axis = up[0] - 'x';
    else if (!strcmp(up, "auto")) s->up_source = FS_UP_AUTO;
    else bad(c, "up", "must be x, y, z or auto");
}

static void parse_light(fs_scene *s, jctx *c, const cJSON *v)
{
    static const char *const lkeys[] = {"direction", "color", "ambient", NULL};
    if (!cJSON_IsObject(v)) {
        bad(c, "light", "must be an object");
        return;
    }
    check_keys(c, v, "light", lkeys);
    get_vec3(c, v, "direction", s->light_dir);
    get_vec3(c, v, "color", s->light_color);
    get_num(c, v, "ambient", &s->ambient, 0, 10);
    float n = fs_v3_len(s->light_dir);
    if (!c->rc && n < 1e-12f) bad(c, "direction", "must not be zero");
    else
        for (int i = 0; i < 3; i++) s->light_dir[i] /= n;
}

static void parse_background(fs_scene *s, jctx *c, const cJSON *root)
{
    const char *bg = get_str(c, root, "background");
    if (!bg) return;
    if (!strcmp(bg, "sky")) s->background = FS_BACKGROUND_SKY;
    else if (!strcmp(bg, "checker")) s->background = FS_BACKGROUND_CHECKER;
    else bad(c, "background", "must be sky or checker");
}

/* The scene's entries in the order the errors are reported. */
static void parse_scene(fs_scene *s, jctx *c, const cJSON *root)
{
    static const char *const keys[] = {"particles",  "radius",    "volume_scale", "kernel",      "support",
                                       "iso",        "up",        "camera",       "light",       "material",
                                       "background", "obstacles", "methods",      "description", NULL};
    if (!cJSON_IsObject(root)) bad(c, "(top level)", "must be an object");
    if (!c->rc) check_keys(c, root, NULL, keys);
    const cJSON *v;
    if (!c->rc && !(v = cJSON_GetObjectItemCaseSensitive(root, "particles"))) bad(c, "particles", "is missing");
    else if (!c->rc) parse_particles(s, c, v);
    parse_field(s, c, root);
    parse_up(s, c, root);
    if (!c->rc && (v = cJSON_GetObjectItemCaseSensitive(root, "camera"))) parse_camera(s, c, v);
    if (!c->rc && (v = cJSON_GetObjectItemCaseSensitive(root, "light"))) parse_light(s, c, v);
    if (!c->rc && (v = cJSON_GetObjectItemCaseSensitive(root, "material"))) parse_material(s, c, v);
    parse_background(s, c, root);
    if (!c->rc && (v = cJSON_GetObjectItemCaseSensitive(root, "obstacles")))
        c->rc = fs_obstacles_parse(v, c->path, &s->obstacles);
    if (!c->rc && (v = cJSON_GetObjectItemCaseSensitive(root, "methods"))) parse_methods(s, c, v);
}

int fs_scene_load(fs_scene *s, const char *path)
{
    fs_scene_defaults(s);
    if (strlen(path) >= sizeof s->path) return fs_fail(FS_ERR_INPUT, "%s: path too long", path);
    strcpy(s->path, path);
    cJSON *root = parse_file(s, path);
    if (!root) return FS_ERR_INPUT;
    jctx c = {path, 0};
    parse_scene(s, &c, root);
    cJSON_Delete(root);
    return c.rc;
}
