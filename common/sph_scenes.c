/* The built-in SPH scenes. Each is defined at a reference scale (metres) and
 * scaled as a whole so its fluid holds about the requested particle count at
 * the fixed radius r: more particles means a bigger tank, not finer ones.
 * Fluid starts on a lattice of spacing 2r; the box is wrapped in two layers of
 * boundary particles on the same lattice (Akinci et al. 2012). */
#include "fs_error.h"
#include "kernels.h"
#include "sph_internal.h"
#include <math.h>
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
    float box[3];        /* container size at scale 1 */
    int nreg;
    region reg[2];
    int nspouts;
    float fill;          /* spouts: fraction of the particles in the initial pool */
    size_t default_n;
    int ncolors;
} scene_def;

static const scene_def scenes[] = {
    /* A 1 m cube of water at one end of a 2.4 m tank (8000 particles at r = 0.025). */
    {"dam_break", {2.4f, 1.6f, 1.0f}, 1, {{{0, 0, 0}, {1.0f, 1.0f, 1.0f}, {0}, 0, 0}}, 0, 1, 8000, 1},
    /* Two columns at both ends meet in the middle. */
    {"double_dam_break", {2.4f, 1.6f, 1.0f}, 2,
     {{{0, 0, 0}, {0.5f, 1.0f, 1.0f}, {0}, 0, 0}, {{1.9f, 0, 0}, {2.4f, 1.0f, 1.0f}, {0}, 0, 1}}, 0, 1, 8000, 2},
    /* A ball of 0.3 m radius 0.6 m above a 0.25 m deep pool. */
    {"drop", {1.6f, 1.6f, 1.6f}, 2,
     {{{0, 0, 0}, {1.6f, 0.25f, 1.6f}, {0}, 0, 0}, {{0}, {0}, {0.8f, 1.0f, 0.8f}, 0.3f, 1}}, 0, 1, 6000, 2},
    /* Four nozzles in the corners, 1.2 m up, pour inwards into a shallow pool. */
    {"spouts", {1.6f, 1.6f, 1.6f}, 1, {{{0, 0, 0}, {1.6f, 0.15f, 1.6f}, {0}, 0, 0}}, 4, 0.35f, 12000, 5},
    /* Water at rest filling the floor half way up: density and depth checks. */
    {"pool", {1.0f, 1.0f, 1.0f}, 1, {{{0, 0, 0}, {1.0f, 0.5f, 1.0f}, {0}, 0, 0}}, 0, 1, 4000, 1},
};

static const float palette[8][3] = {{0.20f, 0.45f, 0.90f}, {0.90f, 0.20f, 0.15f}, {0.20f, 0.80f, 0.25f},
                                    {0.95f, 0.85f, 0.20f}, {0.80f, 0.30f, 0.85f}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};

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
        if (!(*f[i] = calloc(n, sizeof(float)))) return fs_fail(FS_ERR_RUNTIME, "sph: out of memory for %zu particles", n);
    if (!(s->phase = calloc(n, sizeof *s->phase)))
        return fs_fail(FS_ERR_RUNTIME, "sph: out of memory for %zu particles", n);
    return FS_OK;
}

int fs_sph_scene_build(fs_sph *s, const char *name, size_t particles)
{
    const scene_def *d = NULL;
    for (size_t i = 0; i < sizeof scenes / sizeof *scenes; i++)
        if (!strcmp(scenes[i].name, name)) d = &scenes[i];
    if (!d) return fs_fail(FS_ERR_INPUT, "%s: unknown scene (dam_break, double_dam_break, drop, spouts, pool)", name);
    if (!particles) particles = d->default_n;
    float r = s->prm.r, dx = 2 * r;
    /* Scale so that the fluid volume at rest holds `particles` lattice sites. */
    double vol = 0;
    for (int i = 0; i < d->nreg; i++) vol += region_volume(&d->reg[i]);
    vol /= d->fill;
    float sc = (float)cbrt((double)particles * dx * dx * dx / vol);
    int nc[3];
    for (int a = 0; a < 3; a++) {
        nc[a] = (int)lroundf(d->box[a] * sc / dx);
        if (nc[a] < 4) nc[a] = 4;
        s->box_lo[a] = 0;
        s->box_hi[a] = nc[a] * dx;
    }
    if ((double)nc[0] * nc[1] * nc[2] > 4e8) return fs_fail(FS_ERR_INPUT, "%s: %zu particles: too many", name, particles);
    /* Count the fluid lattice sites and the boundary shell. */
    size_t nfluid = 0, nb = 0;
    for (int k = -2; k < nc[2] + 2; k++)
        for (int j = -2; j < nc[1] + 2; j++)
            for (int i = -2; i < nc[0] + 2; i++) {
                int inside = i >= 0 && j >= 0 && k >= 0 && i < nc[0] && j < nc[1] && k < nc[2];
                if (!inside) { nb++; continue; }
                float p[3] = {r + i * dx, r + j * dx, r + k * dx};
                for (int g = 0; g < d->nreg; g++)
                    if (in_region(&d->reg[g], sc, p)) { nfluid++; break; }
            }
    size_t cap = nfluid;
    if (d->nspouts) cap = nfluid + (size_t)((double)particles * (1 - d->fill));
    int rc = fs_sph_alloc(s, nb, cap);
    if (rc) return rc;
    size_t b = 0, f = nb;
    float top = 0;
    for (int k = -2; k < nc[2] + 2; k++)
        for (int j = -2; j < nc[1] + 2; j++)
            for (int i = -2; i < nc[0] + 2; i++) {
                int inside = i >= 0 && j >= 0 && k >= 0 && i < nc[0] && j < nc[1] && k < nc[2];
                float p[3] = {r + i * dx, r + j * dx, r + k * dx};
                size_t o;
                if (!inside) {
                    o = b++;
                    s->phase[o] = -1;
                    s->m[o] = s->mass; /* Psi_b: see below */
                } else {
                    int g = 0;
                    while (g < d->nreg && !in_region(&d->reg[g], sc, p)) g++;
                    if (g == d->nreg) continue;
                    o = f++;
                    s->phase[o] = d->reg[g].phase;
                    s->m[o] = s->mass;
                    if (p[1] > top) top = p[1];
                }
                s->x[o] = p[0]; s->y[o] = p[1]; s->z[o] = p[2];
            }
    s->nf = nfluid;
    s->ncolors = d->ncolors;
    memcpy(s->colors, palette, sizeof palette);
    /* Spouts: corners at 1.2 m, pointing at the middle and a little down. */
    s->nspouts = d->nspouts;
    float vexp = sqrtf(2 * s->prm.gravity * top);
    for (int q = 0; q < d->nspouts; q++) {
        fs_sph_spout *sp = &s->spout[q];
        float cx = (q & 1) ? 1.3f : 0.3f, cz = (q & 2) ? 1.3f : 0.3f;
        sp->pos[0] = cx * sc; sp->pos[1] = 1.2f * sc; sp->pos[2] = cz * sc;
        float dir[3] = {0.8f - cx, -0.3f, 0.8f - cz}, l = sqrtf(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        for (int a = 0; a < 3; a++) sp->dir[a] = dir[a] / l;
        sp->speed = 2.0f;
        sp->width = (int)lroundf(3 * sc);
        if (sp->width < 2) sp->width = 2;
        sp->phase = q + 1;
        sp->next = 0;
        float v = sp->speed + sqrtf(2 * s->prm.gravity * sp->pos[1]);
        if (v > vexp) vexp = v;
    }
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
