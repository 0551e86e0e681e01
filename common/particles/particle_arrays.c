/* The file's other per-particle arrays (particle_arrays.h). */
#include "particle_arrays.h"
#include "fs_error.h"
#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

size_t fs_array_type_size(fs_array_type t) { return t == FS_ARRAY_F64 ? 8 : 4; }

const char *fs_array_type_name(fs_array_type t)
{
    static const char *const names[] = {"float32", "float64", "int32", "uint32"};
    return (unsigned)t < 4 ? names[t] : "?";
}

int fs_particles_add_array(fs_particles *p, const char *name, int ncomp, fs_array_type type, fs_point_array **out)
{
    if (p->narrays >= FS_MAX_POINT_ARRAYS)
        return fs_fail(FS_ERR_INPUT, "more than %d point arrays (at '%.63s')", FS_MAX_POINT_ARRAYS, name);
    if (ncomp < 1 || ncomp > FS_MAX_ARRAY_COMPONENTS)
        return fs_fail(FS_ERR_INPUT, "point array '%.63s' has %d components (1 to %d)", name, ncomp,
                       FS_MAX_ARRAY_COMPONENTS);
    size_t each = (size_t)ncomp * fs_array_type_size(type);
    void *data = p->n > SIZE_MAX / each ? NULL : calloc(p->n ? p->n : 1, each);
    fs_point_array *list = data ? realloc(p->arrays, (size_t)(p->narrays + 1) * sizeof *list) : NULL;
    if (!list) {
        free(data);
        return fs_fail(FS_ERR_RUNTIME, "out of memory for point array '%.63s' of %zu particles", name, p->n);
    }
    p->arrays = list;
    fs_point_array *a = &list[p->narrays++];
    snprintf(a->name, sizeof a->name, "%s", name);
    a->ncomp = ncomp, a->type = type, a->data = data;
    *out = a;
    return FS_OK;
}

double fs_point_array_get(const fs_point_array *a, size_t k)
{
    switch (a->type) {
    case FS_ARRAY_F32: return ((const float *)a->data)[k];
    case FS_ARRAY_F64: return ((const double *)a->data)[k];
    case FS_ARRAY_I32: return ((const int32_t *)a->data)[k];
    default: return ((const uint32_t *)a->data)[k];
    }
}

/* v rounded and clamped to [lo, hi]; NaN as 0. */
static double to_int(double v, double lo, double hi)
{
    v = isnan(v) ? 0 : nearbyint(v);
    return v < lo ? lo : v > hi ? hi : v;
}

void fs_point_array_set(fs_point_array *a, size_t k, double v)
{
    switch (a->type) {
    case FS_ARRAY_F32: ((float *)a->data)[k] = (float)v; break;
    case FS_ARRAY_F64: ((double *)a->data)[k] = v; break;
    case FS_ARRAY_I32: ((int32_t *)a->data)[k] = (int32_t)to_int(v, INT32_MIN, INT32_MAX); break;
    default: ((uint32_t *)a->data)[k] = (uint32_t)to_int(v, 0, UINT32_MAX); break;
    }
}

const fs_point_array *fs_particles_array(const fs_particles *p, const char *name)
{
    for (int i = 0; i < p->narrays; i++)
        if (!strcmp(p->arrays[i].name, name)) return &p->arrays[i];
    return NULL;
}

void fs_array_safe_name(const char *name, char out[64])
{
    snprintf(out, 64, "%s", name[0] ? name : "array");
    for (char *c = out; *c; c++)
        if (isspace((unsigned char)*c) || iscntrl((unsigned char)*c)) *c = '_';
}
