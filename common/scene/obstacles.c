/* Static obstacles (obstacles.h): parsing, distance and ray intersection. */
#include "obstacles.h"
#include "fs_error.h"
#include "obstacle_mesh.h"
#include "path_beside.h"
#include "vec3.h"
#include <stdio.h>
#include <cjson/cJSON.h>
#include <math.h>
#include <string.h>

/* The default solid: a light warm grey, distinct from the water and the floor. */
static const float DEFAULT_COLOR[3] = {0.62f, 0.58f, 0.52f};

static int vec3(const cJSON *a, float out[3])
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != 3) return 0;
    for (int i = 0; i < 3; i++) {
        const cJSON *v = cJSON_GetArrayItem(a, i);
        if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble) || fabs(v->valuedouble) > 1e30) return 0;
        out[i] = (float)v->valuedouble;
    }
    return 1;
}

/* A mesh obstacle's "scale" and "offset"; NULL or the reason they are malformed. */
static const char *parse_placement(const cJSON *e, fs_obstacle *o)
{
    const cJSON *sc = cJSON_GetObjectItemCaseSensitive(e, "scale"),
                *off = cJSON_GetObjectItemCaseSensitive(e, "offset");
    o->scale = 1;
    if (sc && (!cJSON_IsNumber(sc) || !(sc->valuedouble > 0) || sc->valuedouble > 1e30))
        return "\"scale\" must be a positive number";
    if (sc) o->scale = (float)sc->valuedouble;
    if (off && !vec3(off, o->offset)) return "\"offset\" must be an array of 3 numbers";
    return NULL;
}

/* One obstacle object; NULL or the reason it is malformed. A mesh's file is loaded
 * by the caller (*mesh_file: its name as given). */
static const char *parse_one(const cJSON *e, fs_obstacle *o, const char **mesh_file)
{
    if (!cJSON_IsObject(e)) return "must be an object";
    for (const cJSON *k = e->child; k; k = k->next) {
        static const char *const keys[] = {"min", "max", "centre", "radius", "mesh", "scale", "offset", "color", NULL};
        int ok = 0;
        for (const char *const *a = keys; *a; a++) ok |= !strcmp(*a, k->string);
        for (const cJSON *l = k->next; ok && l; l = l->next) ok = strcmp(k->string, l->string) != 0;
        if (!ok) return "has an unknown or repeated key (min, max, centre, radius, mesh, scale, offset, color)";
    }
    const cJSON *mn = cJSON_GetObjectItemCaseSensitive(e, "min"), *mx = cJSON_GetObjectItemCaseSensitive(e, "max");
    const cJSON *c = cJSON_GetObjectItemCaseSensitive(e, "centre"), *r = cJSON_GetObjectItemCaseSensitive(e, "radius");
    const cJSON *mesh = cJSON_GetObjectItemCaseSensitive(e, "mesh"),
                *col = cJSON_GetObjectItemCaseSensitive(e, "color");
    memset(o, 0, sizeof *o);
    memcpy(o->color, DEFAULT_COLOR, sizeof o->color);
    o->scale = 1;
    *mesh_file = NULL;
    if (((mn || mx) + (c || r) + !!mesh) != 1)
        return "needs one of \"min\" and \"max\" (a box), \"centre\" and \"radius\" (a sphere) or \"mesh\" (an OBJ file)";
    if (!mesh && (cJSON_GetObjectItemCaseSensitive(e, "scale") || cJSON_GetObjectItemCaseSensitive(e, "offset")))
        return "\"scale\" and \"offset\" place a \"mesh\" only";
    if (mesh) {
        o->kind = FS_OBSTACLE_MESH;
        if (!cJSON_IsString(mesh) || !mesh->valuestring[0]) return "\"mesh\" must be a file name";
        *mesh_file = mesh->valuestring;
        const char *why = parse_placement(e, o);
        if (why) return why;
    } else if (mn || mx) {
        o->kind = FS_OBSTACLE_BOX;
        if (!vec3(mn, o->lo) || !vec3(mx, o->hi)) return "\"min\" and \"max\" must be arrays of 3 numbers";
        for (int a = 0; a < 3; a++)
            if (!(o->lo[a] < o->hi[a])) return "\"min\" must be below \"max\" on every axis";
    } else {
        o->kind = FS_OBSTACLE_SPHERE;
        if (!vec3(c, o->c)) return "\"centre\" must be an array of 3 numbers";
        if (!cJSON_IsNumber(r) || !(r->valuedouble > 0) || r->valuedouble > 1e30)
            return "\"radius\" must be a positive number";
        o->radius = (float)r->valuedouble;
        for (int a = 0; a < 3; a++) {
            o->lo[a] = o->c[a] - o->radius;
            o->hi[a] = o->c[a] + o->radius;
        }
    }
    if (col) {
        if (!vec3(col, o->color)) return "\"color\" must be an array of 3 numbers";
        for (int a = 0; a < 3; a++)
            if (!(o->color[a] >= 0 && o->color[a] <= 1)) return "\"color\" entries must lie in [0, 1]";
    }
    return NULL;
}

/* Loads a mesh obstacle's file (relative to the folder of `path`) and sets its bounds. */
static int load_mesh(fs_obstacle *o, const char *path, int i, const char *file)
{
    char full[2048];
    if (fs_path_beside(path, file, full, sizeof full))
        return fs_fail(FS_ERR_INPUT, "%s: obstacles[%d]: mesh path too long", path, i);
    int rc = fs_mesh_solid_load(full, &o->mesh);
    if (rc) {
        char why[1024]; /* fs_fail writes the buffer fs_error_message reads */
        snprintf(why, sizeof why, "%s", fs_error_message());
        return fs_fail(rc, "%s: obstacles[%d]: %s", path, i, why);
    }
    float scale = o->scale, off[3] = {o->offset[0], o->offset[1], o->offset[2]}, zero[3] = {0, 0, 0};
    o->scale = 1;
    memset(o->offset, 0, sizeof o->offset);
    memcpy(o->lo, o->mesh->lo, sizeof o->lo);
    memcpy(o->hi, o->mesh->hi, sizeof o->hi);
    fs_obstacle_transform(o, scale, zero);
    fs_obstacle_transform(o, 1, off);
    return FS_OK;
}

int fs_obstacles_parse(const cJSON *array, const char *path, fs_obstacles *out)
{
    out->n = 0;
    if (!cJSON_IsArray(array)) return fs_fail(FS_ERR_INPUT, "%s: \"obstacles\" must be an array of objects", path);
    int n = cJSON_GetArraySize(array);
    if (n > FS_MAX_OBSTACLES) return fs_fail(FS_ERR_INPUT, "%s: %d obstacles: at most %d", path, n, FS_MAX_OBSTACLES);
    for (int i = 0; i < n; i++) {
        const char *file = NULL, *why = parse_one(cJSON_GetArrayItem(array, i), &out->o[i], &file);
        if (why) return fs_fail(FS_ERR_INPUT, "%s: obstacles[%d]: %s", path, i, why);
        int rc = file ? load_mesh(&out->o[i], path, i, file) : FS_OK;
        if (rc) return rc;
    }
    out->n = n;
    return FS_OK;
}

void fs_obstacle_transform(fs_obstacle *o, float scale, const float offset[3])
{
    for (int a = 0; a < 3; a++) {
        o->lo[a] = scale * o->lo[a] + offset[a];
        o->hi[a] = scale * o->hi[a] + offset[a];
        o->c[a] = scale * o->c[a] + offset[a];
        o->offset[a] = scale * o->offset[a] + offset[a];
    }
    o->radius *= scale;
    o->scale *= scale;
}

float fs_obstacle_distance(const fs_obstacle *o, const float p[3])
{
    if (o->kind == FS_OBSTACLE_MESH) {
        float q[3];
        for (int a = 0; a < 3; a++) q[a] = (p[a] - o->offset[a]) / o->scale;
        return o->scale * fs_mesh_solid_distance(o->mesh, q);
    }
    if (o->kind == FS_OBSTACLE_SPHERE) {
        float d[3] = {p[0] - o->c[0], p[1] - o->c[1], p[2] - o->c[2]};
        return fs_v3_len(d) - o->radius;
    }
    float out2 = 0, inside = -INFINITY;
    for (int a = 0; a < 3; a++) {
        float c = 0.5f * (o->lo[a] + o->hi[a]), h = 0.5f * (o->hi[a] - o->lo[a]);
        float q = fabsf(p[a] - c) - h; /* > 0 outside the slab of axis a */
        if (q > 0) out2 += q * q;
        if (q > inside) inside = q;
    }
    return out2 > 0 ? sqrtf(out2) : inside;
}

/* Slab test; t of the entry (or the exit, for a ray starting inside) and its face normal. */
static int hit_box(const fs_obstacle *o, const float org[3], const float dir[3], float tmin, float *t, float n[3])
{
    float t0 = -INFINITY, t1 = INFINITY;
    int a0 = 0, a1 = 0;
    for (int a = 0; a < 3; a++) {
        if (fabsf(dir[a]) < 1e-12f) {
            if (org[a] < o->lo[a] || org[a] > o->hi[a]) return 0;
            continue;
        }
        float inv = 1.0f / dir[a], u = (o->lo[a] - org[a]) * inv, v = (o->hi[a] - org[a]) * inv;
        if (u > v) {
            float s = u;
            u = v;
            v = s;
        }
        if (u > t0) {
            t0 = u;
            a0 = a;
        }
        if (v < t1) {
            t1 = v;
            a1 = a;
        }
    }
    if (t0 > t1) return 0;
    int a = t0 > tmin ? a0 : a1;
    *t = t0 > tmin ? t0 : t1;
    if (!(*t > tmin)) return 0;
    memset(n, 0, 3 * sizeof *n);
    n[a] = dir[a] > 0 ? -1.0f : 1.0f;
    if (t0 <= tmin) n[a] = -n[a]; /* leaving through the face: its outward side is ahead */
    return 1;
}

static int hit_sphere(const fs_obstacle *o, const float org[3], const float dir[3], float tmin, float *t, float n[3])
{
    float m[3] = {org[0] - o->c[0], org[1] - o->c[1], org[2] - o->c[2]};
    float b = m[0] * dir[0] + m[1] * dir[1] + m[2] * dir[2];
    float c = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - o->radius * o->radius;
    float disc = b * b - c;
    if (disc < 0) return 0;
    float s = sqrtf(disc), tt = -b - s;
    if (!(tt > tmin)) tt = -b + s;
    if (!(tt > tmin)) return 0;
    *t = tt;
    for (int a = 0; a < 3; a++) n[a] = (m[a] + tt * dir[a]) / o->radius;
    return 1;
}

/* The mesh in its own frame: the ray's origin moved there, distances scaled. */
static int hit_mesh(const fs_obstacle *o, const float org[3], const float dir[3], float tmin, float tmax, float *t,
                    float n[3])
{
    float q[3];
    for (int a = 0; a < 3; a++) q[a] = (org[a] - o->offset[a]) / o->scale;
    if (!fs_mesh_solid_hit(o->mesh, q, dir, tmin / o->scale, tmax / o->scale, t, n)) return 0;
    *t *= o->scale;
    return 1;
}

int fs_obstacles_hit(const fs_obstacles *ob, const float org[3], const float dir[3], float tmin, float tmax, float *t,
                     float n[3])
{
    int best = -1;
    for (int i = 0; i < ob->n; i++) {
        float ti, ni[3];
        const fs_obstacle *o = &ob->o[i];
        int hit = o->kind == FS_OBSTACLE_SPHERE ? hit_sphere(o, org, dir, tmin, &ti, ni)
            : o->kind == FS_OBSTACLE_MESH       ? hit_mesh(o, org, dir, tmin, tmax, &ti, ni)
                                                : hit_box(o, org, dir, tmin, &ti, ni);
        if (hit && ti < tmax) {
            tmax = ti;
            *t = ti;
            memcpy(n, ni, sizeof ni);
            best = i;
        }
    }
    return best;
}

void fs_obstacles_depth(const fs_obstacles *ob, const fs_camera *cam, int w, int h, float *depth)
{
    float right[3], up[3], fwd[3];
    fs_camera_basis(cam, right, up, fwd);
    float sx = (float)cam->width / w, sy = (float)cam->height / h;
#pragma omp parallel for schedule(static)
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float d[3], t, n[3];
            fs_camera_ray(cam, (x + 0.5f) * sx, (y + 0.5f) * sy, d);
            int i = fs_obstacles_hit(ob, cam->eye, d, 0.0f, INFINITY, &t, n);
            depth[(size_t)y * w + x] = i < 0 ? INFINITY : t * (d[0] * fwd[0] + d[1] * fwd[1] + d[2] * fwd[2]);
        }
}
