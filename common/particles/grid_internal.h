/* Internals of the neighbour grid shared by grid.c, grid_blockset.c and
 * grid_cluster.c; not for use outside common/particles. */
#ifndef FS_GRID_INTERNAL_H
#define FS_GRID_INTERNAL_H
#include "grid.h"

/* A growing set of block coordinates (open addressing, load <= 0.5), with a
 * mask of occupied cells per block. Indices are in order of insertion. */
typedef struct fs_grid_blockset {
    int32_t *key;   /* 3 * cap */
    uint64_t *mask; /* cap */
    uint32_t *table;
    size_t n, cap, table_mask;
} fs_grid_blockset;

int fs_grid_blockset_init(fs_grid_blockset *s, size_t cap);
/* Index of the block (added with an empty mask when new); FS_GRID_NONE when out of memory. */
uint32_t fs_grid_blockset_add(fs_grid_blockset *s, int bi, int bj, int bk);
void fs_grid_blockset_free(fs_grid_blockset *s);

/* Fills g->clusters, g->nclusters and g->bulk_lo/hi from the built blocks. */
int fs_grid_clusters(fs_grid *g);
#endif
