/* The growing hash set of block coordinates that fs_grid_build fills before it
 * knows how many blocks there are (grid_internal.h). */
#include "grid_internal.h"
#include <stdlib.h>
#include <string.h>

static uint32_t *new_table(size_t size)
{
    uint32_t *t = malloc(size * sizeof *t);
    if (t) memset(t, 0xff, size * sizeof *t);
    return t;
}

int fs_grid_blockset_init(fs_grid_blockset *s, size_t cap)
{
    memset(s, 0, sizeof *s);
    s->cap = cap;
    s->key = malloc(3 * cap * sizeof *s->key);
    s->mask = calloc(cap, sizeof *s->mask);
    s->table = new_table(2 * cap);
    s->table_mask = 2 * cap - 1;
    if (s->key && s->mask && s->table) return 0;
    fs_grid_blockset_free(s);
    return 1;
}

void fs_grid_blockset_free(fs_grid_blockset *s)
{
    free(s->key);
    free(s->mask);
    free(s->table);
    memset(s, 0, sizeof *s);
}

/* Doubles the capacity and rehashes (cap is a power of two, the table twice that). */
static int grow(fs_grid_blockset *s)
{
    size_t cap = 2 * s->cap;
    int32_t *key = realloc(s->key, 3 * cap * sizeof *key);
    if (key) s->key = key;
    uint64_t *mask = realloc(s->mask, cap * sizeof *mask);
    if (mask) s->mask = mask;
    uint32_t *table = new_table(2 * cap);
    if (!key || !mask || !table) {
        free(table);
        return 1;
    }
    memset(s->mask + s->cap, 0, (cap - s->cap) * sizeof *mask);
    free(s->table);
    s->table = table;
    s->cap = cap;
    s->table_mask = 2 * cap - 1;
    for (size_t b = 0; b < s->n; b++) {
        const int32_t *k = s->key + 3 * b;
        uint32_t h = fs_grid_hash(k[0], k[1], k[2]) & (uint32_t)s->table_mask;
        while (table[h] != FS_GRID_NONE) h = (h + 1) & (uint32_t)s->table_mask;
        table[h] = (uint32_t)b;
    }
    return 0;
}

uint32_t fs_grid_blockset_add(fs_grid_blockset *s, int bi, int bj, int bk)
{
    uint32_t h = fs_grid_hash(bi, bj, bk) & (uint32_t)s->table_mask;
    for (;; h = (h + 1) & (uint32_t)s->table_mask) {
        uint32_t b = s->table[h];
        if (b == FS_GRID_NONE) break;
        const int32_t *k = s->key + 3 * (size_t)b;
        if (k[0] == bi && k[1] == bj && k[2] == bk) return b;
    }
    if (s->n == s->cap) {
        if (s->cap >= (size_t)1 << 30 || grow(s)) return FS_GRID_NONE;
        return fs_grid_blockset_add(s, bi, bj, bk);
    }
    uint32_t b = (uint32_t)s->n++;
    s->key[3 * (size_t)b] = bi;
    s->key[3 * (size_t)b + 1] = bj;
    s->key[3 * (size_t)b + 2] = bk;
    s->table[h] = b;
    return b;
}
