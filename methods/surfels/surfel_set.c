#include "surfel_set.h"
#include "fs_error.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int fs_surfel_push(fs_surfel_set *set, const float pos[3], const float normal[3], float radius)
{
    if (set->n == set->cap) {
        size_t cap = set->cap ? 2 * set->cap : 1024;
        if (cap > SIZE_MAX / sizeof *set->s) return fs_fail(FS_ERR_RUNTIME, "out of memory: %zu surfels", cap);
        fs_surfel *s = realloc(set->s, cap * sizeof *s);
        if (!s) return fs_fail(FS_ERR_RUNTIME, "out of memory: %zu surfels", cap);
        set->s = s;
        set->cap = cap;
    }
    fs_surfel *e = &set->s[set->n++];
    memcpy(e->pos, pos, sizeof e->pos);
    memcpy(e->normal, normal, sizeof e->normal);
    e->radius = radius;
    e->pad = 0.0f;
    return FS_OK;
}

void fs_surfel_set_free(fs_surfel_set *set)
{
    free(set->s);
    memset(set, 0, sizeof *set);
}
