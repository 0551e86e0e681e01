/* The built-in SPH scenes. Each is defined at a reference scale (metres) and
 * scaled as a whole so its fluid holds about the requested particle count at
 * the fixed radius r: more particles means a bigger tank, not finer ones.
 * Fluid starts on a lattice of spacing 2r; the box is wrapped in two layers of
 * boundary particles on the same lattice (Akinci et al. 2012), and a JSON
 * scene's obstacles are lined with two layers inside their surface. */
#include "fs_error.h"
#include "kernels.h"
#include "obstacles.h"
#include "sph_internal.h"
#include "vec3.h"
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const fs_sph_scene_names[] = {"dam_break", "double_dam_break", "drop", "spouts", "pool", NULL};

typedef struct region {
    float lo[3], hi[3]; /* box, or ... */
    float c[3], rad;    /* ... a sphere when rad > 0 */
    int phase;
} region;

typedef struct scene_def {
    const char *name;
    float box[3]; /* container size at scale 1 */
    int nreg;
    region reg[8];
    int nspouts;
    float fill; /* spouts: fraction of the particles in the initial pool */
    size_t default_n;
    int ncolors;
} scene_def;

static const scene_def scenes[] = {
    /* A 1 m cube of water at one end of a 2.4 m tank (8000 particles at r = 0.025). */
    {"dam_break", {2.4f, 1.6f, 1.0f}, 1, {{{0, 0, 0}, {1.0f, 1.0f, 1.0f}, {0}, 0, 0}}, 0, 1, 8000, 1},
    /* Two columns at both ends meet in the middle. */
    {"double_dam_break",
     {2.4f, 1.6f, 1.0f},
     2,
     {{{0, 0, 0}, {0.5f, 1.0f, 1.0f}, {0}, 0, 0}, {{1.9f, 0, 0}, {2.4f, 1.0f, 1.0f}, {0}, 0, 1}},
     0,
     1,
     8000,
     2},
    /* A ball of 0.3 m radius 0.6 m above a 0.25 m deep pool. */
    {"drop",
     {1.6f, 1.6f, 1.6f},
     2,
     {{{0, 0, 0}, {1.6f, 0.25f, 1.6f}, {0}, 0, 0}, {{0}, {0}, {0.8f, 1.0f, 0.8f}, 0.3f, 1}},
     0,
     1,
     6000,
     2},
    /* Four nozzles in the corners, 1.2 m up, pour inwards into a shallow pool. */
    {"spouts", {1.6f, 1.6f, 1.6f}, 1, {{{0, 0, 0}, {1.6f, 0.15f, 1.6f}, {0}, 0, 0}}, 4, 0.35f, 12000, 5},
    /* Water at rest filling the floor half way up: density and depth checks. */
    {"pool", {1.0f, 1.0f, 1.0f}, 1, {{{0, 0, 0}, {1.0f, 0.5f, 1.0f}, {0}, 0, 0}}, 0, 1, 4000, 1},
};

static const float palette[8][3] = {{0.20f, 0.45f, 0.90f},
                                    {0.90f, 0.20f, 0.15f},
                                    {0.20f, 0.80f, 0.25f},
                                    {0.95f, 0.85f, 0.20f},
                                    {0.80f, 0.30f, 0.85f},
                                    {1, 1, 1},
                                    {1, 1, 1},
                                    {1, 1, 1}};

static double region_volume(const region *g)
{
    if (g->rad > 0) return 4.0 / 3.0 * FS_PI * g->rad * g->rad * g->rad;
    return (double)(g->hi[0] - g->lo[0]) * (g->hi[1] - g->lo[1]) * (g->hi[2] - g->lo[2]);
}

static int in_region(const region *g, float s, const float p[3])
{
    if (g->rad > 0) {
        float dx = p[0] - g->c[0] * s, dy = p[1] - g->c[1] * s, dz = p[2] - g->c[2] * s, R = g->rad * s;
        return dx * dx + dy * dy + dz * dz <= R * R;
    }
    for (int a = 0; a < 3; a++)
        if (p[a] < g->lo[a] * s || p[a] >= g->hi[a] * s) return 0;
    return 1;
}

int fs_sph_alloc(fs_sph *s, size_t nb, size_t cap)
{
    size_t n = nb + cap;
    s->nb = nb;
    s->cap = cap;
    float **f[] = {&s->x, &s->y, &s->z, &s->vx, &s->vy, &s->vz, &s->m};
    for (size_t i = 0; i < sizeof f / sizeof *f; i++)
        if (!(*f[i] = calloc(n, sizeof(float))))
            return fs_fail(FS_ERR_RUNTIME, "sph: out of memory for %zu particles", n);
    if (!(s->phase = calloc(n, sizeof *s->phase)))
        return fs_fail(FS_ERR_RUNTIME, "sph: out of memory for %zu particles", n);
    return FS_OK;
}

/* Reads `n` positive (or any, when !positive) numbers of a JSON array. */
static int json_vec(const cJSON *a, int n, float *out, int positive)
{
    if (!cJSON_IsArray(a) || cJSON_GetArraySize(a) != n) return 0;
    for (int i = 0; i < n; i++) {
        const cJSON *v = cJSON_GetArrayItem(a, i);
        if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble) || (positive && !(v->valuedouble > 0))) return 0;
        out[i] = (float)v->valuedouble;
    }
    return 1;
}

/* Fluid region g of a scene file into q: a box {"min", "max"} (min < max) or a
 * ball {"centre", "radius" > 0}, optional "color" 0..4 (d counts the colours). */
static int json_region(const cJSON *g, region *q, scene_def *d, const char *path, int k)
{
    const cJSON *mn = cJSON_GetObjectItem(g, "min"), *mx = cJSON_GetObjectItem(g, "max"),
                *c = cJSON_GetObjectItem(g, "centre"), *rad = cJSON_GetObjectItem(g, "radius"),
                *col = cJSON_GetObjectItem(g, "color");
    int ok = mn ? json_vec(mn, 3, q->lo, 0) && json_vec(mx, 3, q->hi, 0) && !c && !rad
                : json_vec(c, 3, q->c, 0) && cJSON_IsNumber(rad) && rad->valuedouble > 0 && !mx;
    for (int a = 0; ok && mn && a < 3; a++) ok = q->lo[a] < q->hi[a];
    if (rad) q->rad = (float)rad->valuedouble;
    if (col) {
        ok = ok && cJSON_IsNumber(col) && col->valuedouble >= 0 && col->valuedouble <= 4 &&
            col->valuedouble == (int)col->valuedouble;
        q->phase = ok ? (int)col->valuedouble : 0;
        if (q->phase + 1 > d->ncolors) d->ncolors = q->phase + 1;
    }
    if (ok) return FS_OK;
    return fs_fail(FS_ERR_INPUT,
                   "%s: fluid region %d: expected {\"min\", \"max\"} (min < max) or "
                   "{\"centre\", \"radius\" > 0}, optional \"color\" 0..4",
                   path, k);
}

/* One key of a scene file into d (and its obstacles into ob). */
static int json_key(const cJSON *it, scene_def *d, fs_obstacles *ob, const char *path)
{
    if (!strcmp(it->string, "box"))
        return json_vec(it, 3, d->box, 1) ? FS_OK : fs_fail(FS_ERR_INPUT, "%s: box: expected [x, y, z] > 0", path);
    if (!strcmp(it->string, "obstacles")) return fs_obstacles_parse(it, path, ob);
    if (strcmp(it->string, "fluid") || !cJSON_IsArray(it))
        return fs_fail(FS_ERR_INPUT, "%s: unknown or malformed key '%s' (box, fluid, obstacles)", path, it->string);
    const cJSON *g;
    int rc = FS_OK;
    cJSON_ArrayForEach(g, it)
    {
        if (d->nreg == 8) return fs_fail(FS_ERR_INPUT, "%s: fluid: at most 8 regions", path);
        int k = d->nreg++;
        if ((rc = json_region(g, &d->reg[k], d, path, k))) break;
    }
    return rc;
}

/* The scene file's JSON object (NULL with fs_fail set). */
static cJSON *json_load(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fs_fail(FS_ERR_INPUT, "%s: cannot read the scene file", path);
        return NULL;
    }
    char *text = malloc(1 << 20);
    size_t len = text ? fread(text, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    if (!text) {
        fs_fail(FS_ERR_RUNTIME, "sph: out of memory");
        return NULL;
    }
    text[len] = 0;
    cJSON *root = cJSON_Parse(text);
    free(text);
    if (root && cJSON_IsObject(root)) return root;
    cJSON_Delete(root);
    fs_fail(FS_ERR_INPUT, "%s: malformed JSON", path);
    return NULL;
}

/* A scene file: {"box": [x, y, z], "fluid": [{"min": [..], "max": [..], "color": 0},
 * {"centre": [..], "radius": R, "color": 1}, ...], "obstacles": [..] (obstacles.h)}
 * in metres; particles 0 means the lattice at exactly that size, otherwise the
 * whole scene is scaled like the built-ins. */
static int json_scene(const char *path, scene_def *d, fs_obstacles *ob, float r)
{
    cJSON *root = json_load(path);
    if (!root) return fs_error_code();
    memset(d, 0, sizeof *d);
    d->name = path;
    d->fill = 1;
    int rc = FS_OK;
    const cJSON *it;
    cJSON_ArrayForEach(it, root)
    {
        if ((rc = json_key(it, d, ob, path))) break;
    }
    cJSON_Delete(root);
    if (rc) return rc;
    if (!(d->box[0] > 0) || !d->nreg) return fs_fail(FS_ERR_INPUT, "%s: needs \"box\" and \"fluid\"", path);
    double vol = 0;
    for (int i = 0; i < d->nreg; i++) vol += region_volume(&d->reg[i]);
    double dx = 2.0 * r;
    d->default_n = (size_t)fmax(64, vol / (dx * dx * dx));
    if (d->ncolors < 1) d->ncolors = 1;
    return FS_OK;
}

/* The scene by name: a .json file (parsed into js, its obstacles into
 * s->obstacles at scale 1) or a built-in one. */
static int find_scene(fs_sph *s, const char *name, scene_def *js, const scene_def **d)
{
    *d = NULL;
    size_t len = strlen(name);
    if (len > 5 && !strcmp(name + len - 5, ".json")) {
        int rc = json_scene(name, js, &s->obstacles, s->prm.r);
        if (rc) return rc;
        *d = js;
    }
    for (size_t i = 0; !*d && i < sizeof scenes / sizeof *scenes; i++)
        if (!strcmp(scenes[i].name, name)) *d = &scenes[i];
    if (!*d)
        return fs_fail(FS_ERR_INPUT, "%s: unknown scene (dam_break, double_dam_break, drop, spouts, pool, or a .json)",
                       name);
    return FS_OK;
}

/* The scene scaled by sc on the lattice of spacing dx = 2r: nc[a] sites along
 * axis a inside the box, two more layers of boundary around it. */
typedef struct lattice {
    float r, dx, sc;
    int nc[3];
} lattice;

/* Scales the scene so that its fluid volume at rest holds `particles` lattice
 * sites, or by sc when sc > 0; sets the box. */
static int scale_tank(fs_sph *s, const scene_def *d, const char *name, size_t particles, float sc, lattice *l)
{
    l->r = s->prm.r;
    l->dx = 2 * l->r;
    const float dx = l->dx;
    double vol = 0;
    for (int i = 0; i < d->nreg; i++) vol += region_volume(&d->reg[i]);
    vol /= d->fill;
    l->sc = sc > 0 ? sc : (float)cbrt((double)particles * dx * dx * dx / vol);
    for (int a = 0; a < 3; a++) {
        l->nc[a] = (int)lroundf(d->box[a] * l->sc / dx);
        if (l->nc[a] < 4) l->nc[a] = 4;
        s->box_lo[a] = 0;
        s->box_hi[a] = l->nc[a] * dx;
    }
    if ((double)l->nc[0] * l->nc[1] * l->nc[2] > 4e8)
        return fs_fail(FS_ERR_INPUT, "%s: %zu particles: too many", name, particles);
    return FS_OK;
}

/* Lattice site (i, j, k): its position p; whether it lies inside the box. */
static int lattice_site(const lattice *l, int i, int j, int k, float p[3])
{
    p[0] = l->r + i * l->dx;
    p[1] = l->r + j * l->dx;
    p[2] = l->r + k * l->dx;
    return i >= 0 && j >= 0 && k >= 0 && i < l->nc[0] && j < l->nc[1] && k < l->nc[2];
}

/* The first fluid region holding p, d->nreg if none. */
static int region_of(const scene_def *d, float sc, const float p[3])
{
    int g = 0;
    while (g < d->nreg && !in_region(&d->reg[g], sc, p)) g++;
    return g;
}

/* Scales the obstacles by sc, into the frame of the fluid regions. */
static void scale_obstacles(fs_obstacles *ob, float sc)
{
    static const float none[3] = {0, 0, 0};
    for (int i = 0; i < ob->n; i++) fs_obstacle_transform(&ob->o[i], sc, none);
}

enum { SITE_NONE = -2, SITE_BOUNDARY = -1 }; /* site_of's answers besides a fluid region */

/* 0 outside the obstacles; inside, a site is boundary as deep as the walls'
 * shell reaches (2 spacings, the support H = 4r), empty deeper. The distance
 * is 1-Lipschitz, so every site within H of a fluid site is fluid or boundary:
 * the completed lattice that makes Psi_b = m exact (fs_sph_scene_build). */
static int obstacle_site(const fs_obstacles *ob, float dx, const float p[3])
{
    float dist = INFINITY; /* the deepest of them: never deeper than in their union */
    for (int i = 0; i < ob->n; i++) {
        const fs_obstacle *o = &ob->o[i];
        int outside = 0; /* beyond its bounds: not inside it, and a mesh's distance is costly */
        for (int a = 0; a < 3; a++) outside |= p[a] < o->lo[a] || p[a] > o->hi[a];
        if (!outside) dist = fminf(dist, fs_obstacle_distance(o, p));
    }
    return dist >= 0 ? 0 : dist >= -2 * dx ? SITE_BOUNDARY : SITE_NONE;
}

/* What lattice site (i, j, k), at p, holds: boundary (the walls' shell or an
 * obstacle's), nothing, or the fluid of region g >= 0. */
static int site_of(const fs_sph *s, const scene_def *d, const lattice *l, int i, int j, int k, float p[3])
{
    if (!lattice_site(l, i, j, k, p)) return SITE_BOUNDARY;
    int o = obstacle_site(&s->obstacles, l->dx, p);
    if (o) return o;
    int g = region_of(d, l->sc, p);
    return g < d->nreg ? g : SITE_NONE;
}

/* Counts the fluid lattice sites and the boundary particles. */
static void count_sites(const fs_sph *s, const scene_def *d, const lattice *l, size_t *nfluid, size_t *nb)
{
    *nfluid = *nb = 0;
    for (int k = -2; k < l->nc[2] + 2; k++)
        for (int j = -2; j < l->nc[1] + 2; j++)
            for (int i = -2; i < l->nc[0] + 2; i++) {
                float p[3];
                int g = site_of(s, d, l, i, j, k, p);
                if (g == SITE_BOUNDARY) (*nb)++;
                else if (g >= 0) (*nfluid)++;
            }
}

/* Places the boundary particles at [0, nb) and the fluid after them; returns
 * the height of the highest fluid particle. */
static float place_particles(fs_sph *s, const scene_def *d, const lattice *l)
{
    size_t b = 0, f = s->nb;
    float top = 0;
    for (int k = -2; k < l->nc[2] + 2; k++)
        for (int j = -2; j < l->nc[1] + 2; j++)
            for (int i = -2; i < l->nc[0] + 2; i++) {
                float p[3];
                size_t o;
                int g = site_of(s, d, l, i, j, k, p);
                if (g == SITE_NONE) continue;
                if (g == SITE_BOUNDARY) {
                    o = b++;
                    s->phase[o] = -1;
                    s->m[o] = s->mass; /* Psi_b: see fs_sph_scene_build */
                } else {
                    o = f++;
                    s->phase[o] = d->reg[g].phase;
                    s->m[o] = s->mass;
                    if (p[1] > top) top = p[1];
                }
                s->x[o] = p[0];
                s->y[o] = p[1];
                s->z[o] = p[2];
            }
    return top;
}

/* Spouts: corners at 1.2 m, pointing at the middle and a little down. Returns
 * the largest expected speed: the fall from `top` or a spout's jet. */
static float place_spouts(fs_sph *s, const scene_def *d, float sc, float top)
{
    s->nspouts = d->nspouts;
    float vexp = sqrtf(2 * s->prm.gravity * top);
    for (int q = 0; q < d->nspouts; q++) {
        fs_sph_spout *sp = &s->spout[q];
        float cx = (q & 1) ? 1.3f : 0.3f, cz = (q & 2) ? 1.3f : 0.3f;
        sp->pos[0] = cx * sc;
        sp->pos[1] = 1.2f * sc;
        sp->pos[2] = cz * sc;
        float dir[3] = {0.8f - cx, -0.3f, 0.8f - cz}, l = fs_v3_len(dir);
        for (int a = 0; a < 3; a++) sp->dir[a] = dir[a] / l;
        sp->speed = 2.0f;
        sp->width = (int)lroundf(3 * sc);
        if (sp->width < 2) sp->width = 2;
        sp->phase = q + 1;
        sp->next = 0;
        float v = sp->speed + sqrtf(2 * s->prm.gravity * sp->pos[1]);
        if (v > vexp) vexp = v;
    }
    return vexp;
}

int fs_sph_scene_build(fs_sph *s, const char *name, size_t particles)
{
    const scene_def *d;
    scene_def js;
    lattice l;
    int rc = find_scene(s, name, &js, &d);
    if (rc) return rc;
    /* A JSON scene at its own size is at scale exactly 1 (not the cube root of
     * the floored default_n), so that a rendering scene's obstacle coordinates
     * coincide with the simulated solid. */
    float sc = !particles && d == &js ? 1.0f : 0.0f;
    if (!particles) particles = d->default_n;
    if ((rc = scale_tank(s, d, name, particles, sc, &l))) return rc;
    scale_obstacles(&s->obstacles, l.sc);
    size_t nfluid, nb;
    count_sites(s, d, &l, &nfluid, &nb);
    if (!nfluid) return fs_fail(FS_ERR_INPUT, "%s: no fluid inside the box", name);
    size_t cap = nfluid;
    if (d->nspouts) cap = nfluid + (size_t)((double)particles * (1 - d->fill));
    if ((rc = fs_sph_alloc(s, nb, cap))) return rc;
    float top = place_particles(s, d, &l);
    s->nf = nfluid;
    s->ncolors = d->ncolors;
    memcpy(s->colors, palette, sizeof palette);
    float vexp = place_spouts(s, d, l.sc, top);
    /* Weakly compressible: a sound speed 10x the largest expected speed keeps
     * density variations near 1% (Mach 0.1). */
    if (!(s->prm.c > 0)) s->prm.c = 10 * vexp;
    /* Akinci's Psi_b = rho0 / sum_k W_bk (k: boundary neighbours) corrects for
     * walls sampled thinner than the support. This shell continues the fluid
     * lattice as deep as the support reaches (2 layers at H = 4r), so the sum
     * over the completed lattice gives Psi_b = m and a fluid particle at rest
     * next to a wall or in a corner reads exactly rho0. (The shell-only sum
     * over-counts: +5% density at walls, +7% in corners, measured.) */
    return FS_OK;
}

const fs_obstacles *fs_sph_obstacles(const fs_sph *s) { return &s->obstacles; }
