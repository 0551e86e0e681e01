/* Particle set storage: allocation, bounds and validation (stats live in particle_stats.c). */
#include "particles.h"
#include "fs_error.h"
#include "memory.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* calloc that never returns NULL for a zero count, so "allocated" means non-NULL. */
static void *zalloc(size_t n, size_t elem)
{
    if (n && elem > SIZE_MAX / n) return NULL;
    return calloc(n ? n : 1, elem);
}

int fs_particles_alloc(fs_particles *p, size_t n, unsigned fields)
{
    memset(p, 0, sizeof *p);
    /* refused up front: a header can declare (and a sparse file back) more than fits */
    int per =
        3 + (fields & FS_HAS_VELOCITY ? 3 : 0) + (fields & FS_HAS_COLOR ? 3 : 0) + (fields & FS_HAS_PHASE ? 1 : 0);
    char what[64];
    snprintf(what, sizeof what, "%zu particles", n);
    int rc = fs_memory_check((double)n * per * 4, what);
    if (rc) return rc;
    p->n = n;
    p->x = zalloc(n, sizeof(float));
    p->y = zalloc(n, sizeof(float));
    p->z = zalloc(n, sizeof(float));
    int ok = p->x && p->y && p->z;
    if (fields & FS_HAS_VELOCITY) {
        p->vx = zalloc(n, sizeof(float));
        p->vy = zalloc(n, sizeof(float));
        p->vz = zalloc(n, sizeof(float));
        ok = ok && p->vx && p->vy && p->vz;
    }
    if (fields & FS_HAS_COLOR) {
        p->color = n > SIZE_MAX / 3 ? NULL : zalloc(3 * n, sizeof(float));
        ok = ok && p->color;
    }
    if (fields & FS_HAS_PHASE) {
        p->phase = zalloc(n, sizeof(int32_t));
        ok = ok && p->phase;
    }
    if (!ok) {
        fs_particles_free(p);
        return fs_fail(FS_ERR_RUNTIME, "out of memory allocating %zu particles", n);
    }
    return FS_OK;
}

void fs_particles_free(fs_particles *p)
{
    if (!p) return;
    free(p->x);
    free(p->y);
    free(p->z);
    free(p->vx);
    free(p->vy);
    free(p->vz);
    free(p->color);
    free(p->phase);
    for (int i = 0; i < p->narrays; i++) free(p->arrays[i].data);
    free(p->arrays);
    memset(p, 0, sizeof *p);
}

unsigned fs_particles_fields(const fs_particles *p)
{
    unsigned f = 0;
    if (p->vx && p->vy && p->vz) f |= FS_HAS_VELOCITY;
    if (p->color) f |= FS_HAS_COLOR;
    if (p->phase) f |= FS_HAS_PHASE;
    return f;
}

void fs_particles_bounds(fs_particles *p)
{
    if (p->n == 0) {
        for (int k = 0; k < 3; k++) p->bmin[k] = p->bmax[k] = 0.0f;
        return;
    }
    float lo[3] = {p->x[0], p->y[0], p->z[0]}, hi[3] = {p->x[0], p->y[0], p->z[0]};
    for (size_t i = 1; i < p->n; i++) {
        float v[3] = {p->x[i], p->y[i], p->z[i]};
        for (int k = 0; k < 3; k++) {
            if (v[k] < lo[k]) lo[k] = v[k];
            if (v[k] > hi[k]) hi[k] = v[k];
        }
    }
    memcpy(p->bmin, lo, sizeof lo);
    memcpy(p->bmax, hi, sizeof hi);
}

int fs_particles_validate(const fs_particles *p, const char *name)
{
    if (p->n == 0 || !p->x) return fs_fail(FS_ERR_INPUT, "%s: no particles", name);
    /* the range a scene's "radius" takes; 0 means the file gives none */
    if (!(p->radius == 0 || (p->radius >= 1e-9f && p->radius <= 1e9f)))
        return fs_fail(FS_ERR_INPUT, "%s: the file's particle radius %g lies outside [1e-09, 1e+09]", name, p->radius);
    for (size_t i = 0; i < p->n; i++)
        if (!isfinite(p->x[i]) || !isfinite(p->y[i]) || !isfinite(p->z[i]))
            return fs_fail(FS_ERR_INPUT, "%s: particle %zu has a non-finite position", name, i);
    return FS_OK;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

void fs_particles_core_bounds_in(const fs_particles *p, float frac, const float in_lo[3], const float in_hi[3],
                                 float lo[3], float hi[3])
{
    size_t m = p->n < 65536 ? p->n : 65536, k = 0;
    float *v = m ? malloc(m * sizeof *v) : NULL;
    size_t *pick = m ? malloc(m * sizeof *pick) : NULL;
    const float *axis[3] = {p->x, p->y, p->z};
    for (size_t i = 0; v && pick && i < m; i++) {
        size_t j = i * (p->n / m);
        int in = 1;
        for (int a = 0; a < 3; a++) in &= axis[a][j] >= in_lo[a] && axis[a][j] <= in_hi[a];
        if (in) pick[k++] = j;
    }
    for (int a = 0; a < 3; a++) {
        lo[a] = in_lo[a];
        hi[a] = in_hi[a];
        if (!k) continue;
        for (size_t i = 0; i < k; i++) v[i] = axis[a][pick[i]];
        qsort(v, k, sizeof *v, cmp_float);
        lo[a] = v[(size_t)(frac * (k - 1))];
        hi[a] = v[(size_t)((1 - frac) * (k - 1))];
    }
    free(v);
    free(pick);
}
