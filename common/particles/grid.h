/* Uniform neighbour grid built by counting sort. The same arrays are uploaded
 * as SSBOs (see gl_grid.h), so CPU code and shaders walk one layout:
 *   cell id   = (k * dim[1] + j) * dim[0] + i
 *   particles of cell c are pos4[start[c] .. start[c+1]) (sorted order),
 *   index[s] is the original particle index of sorted slot s. */
#ifndef FS_GRID_H
#define FS_GRID_H
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_grid {
    float origin[3];  /* corner of cell (0,0,0) */
    float cell;       /* cell edge length; at least the largest support a pass uses */
    int dim[3];
    size_t ncells;
    size_t n;         /* particle count */
    uint32_t *start;  /* ncells + 1 prefix sums */
    uint32_t *index;  /* n: sorted slot -> original particle */
    float *pos4;      /* 4n: sorted positions, w = original index as float bits */
} fs_grid;

/* Grids larger than this many cells are refused (FS_ERR_INPUT) rather than
 * exhausting memory on a scene with far-flung spray. */
#define FS_GRID_MAX_CELLS ((size_t)1 << 27)

int fs_grid_build(fs_grid *g, const fs_particles *p, float cell);
void fs_grid_free(fs_grid *g);
/* *out = given when it was built on p with cells of at least `cell`; else a grid
 * built into own (*has_own = 1; the caller frees it). Frees a previous own first. */
int fs_grid_fit(const fs_grid *given, const fs_particles *p, float cell, fs_grid *own, int *has_own,
                const fs_grid **out);

static inline int fs_grid_clampi(int v, int hi) { return v < 0 ? 0 : (v > hi ? hi : v); }
/* Cell coordinate of x along axis a, not clamped. */
static inline int fs_grid_coord(const fs_grid *g, int a, float x)
{
    float t = (x - g->origin[a]) / g->cell;
    return t < -1e9f ? -1000000000 : (t > 1e9f ? 1000000000 : (int)floorf(t));
}
static inline size_t fs_grid_cell_id(const fs_grid *g, int i, int j, int k)
{
    return ((size_t)k * g->dim[1] + j) * g->dim[0] + i;
}

/* Calls fn(user, sorted_slot, dist2) for every particle within radius of x.
 * radius may exceed the cell size (more cells are visited). */
typedef void (*fs_grid_visit)(void *user, uint32_t slot, float dist2);
void fs_grid_query(const fs_grid *g, const float x[3], float radius, fs_grid_visit fn, void *user);

#ifdef __cplusplus
}
#endif
#endif
