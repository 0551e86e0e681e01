/* Block-sparse neighbour grid built by counting sort (docs/DESIGN.md, Neighbour
 * grid). Space is cut into cells of edge `cell`; cells are grouped into blocks
 * of FS_GRID_B^3 cells, and only the blocks that hold a particle, or touch a
 * cell next to one, are stored, found through a hash of their block
 * coordinates. Memory follows the particles, not the bounding box, so a few
 * particles thousands of metres away cost a few blocks.
 *
 *   stored block b covers cells (bkey[3b..3b+2] * FS_GRID_B + local);
 *   cell slot    = b * FS_GRID_B3 + (lk * FS_GRID_B + lj) * FS_GRID_B + li
 *   particles of a cell slot c are pos4[start[c] .. start[c+1]) (sorted order);
 *   index[s] is the original particle index of sorted slot s.
 * Inside a block a row of cells (li = 0..B-1 at fixed lj, lk) is one run of
 * slots. The same arrays are uploaded as SSBOs (gl_grid.h), so CPU code and
 * shaders walk one layout. A cell with no stored block is empty and has no
 * particle in its 27 neighbours ("far": with cell >= the support, phi = 0 there). */
#ifndef FS_GRID_H
#define FS_GRID_H
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_GRID_B 4
#define FS_GRID_B3 (FS_GRID_B * FS_GRID_B * FS_GRID_B)
#define FS_GRID_NONE UINT32_MAX

/* A connected group of stored blocks (26-neighbours): an axis-aligned box of
 * cell coordinates lo..hi (inclusive) and the particles in it. */
typedef struct fs_grid_cluster {
    int lo[3], hi[3];
    size_t n;
} fs_grid_cluster;

typedef struct fs_grid {
    float origin[3];  /* corner of cell (0,0,0); cell coordinates may be negative */
    float cell;       /* cell edge length; at least the largest support a pass uses */
    int lo[3], hi[3]; /* range of the stored cells' coordinates (inclusive) */
    size_t n;         /* particle count */
    size_t nblocks;   /* stored blocks */
    size_t ncells;    /* nblocks * FS_GRID_B3: cell slots */
    int32_t *bkey;    /* 3 * nblocks: block coordinates of stored block b */
    uint32_t *start;  /* ncells + 1 prefix sums over cell slots */
    uint32_t *near;   /* ncells / 32 + 1 bits: one of the 27 cells around the slot holds a particle */
    uint32_t *table;  /* hash slots (a power of two): stored block index, or FS_GRID_NONE */
    size_t table_mask;
    uint32_t *index;           /* n: sorted slot -> original particle */
    float *pos4;               /* 4n: sorted positions, w = original index as float bits */
    fs_grid_cluster *clusters; /* nclusters, largest first */
    int nclusters;
    float bulk_lo[3], bulk_hi[3]; /* robust bounds: the box of the clusters that make the bulk */
} fs_grid;

/* The bulk: the largest cluster and every cluster with at least 1% of the
 * particles make the core; any other cluster whose box lies within one core
 * extent (the core box's longest side, in cells) of the core box joins it, so
 * spray thrown off the body stays in the bulk while strays far away do not.
 * bulk_lo/hi is the box of the positions of the bulk clusters' particles (the
 * bounding box when nothing is far). */

/* Refuses (FS_ERR_INPUT) a non-finite position, and a set spanning more than
 * 2^29 cells on an axis (a particle so far away that cell coordinates would
 * overflow), naming the particle. origin is the lowest particle minus one cell. */
int fs_grid_build(fs_grid *g, const fs_particles *p, float cell);
void fs_grid_free(fs_grid *g);
/* *out = given when it was built on p with cells of at least `cell`; else a grid
 * built into own (*has_own = 1; the caller frees it). Frees a previous own first. */
int fs_grid_fit(const fs_grid *given, const fs_particles *p, float cell, fs_grid *own, int *has_own,
                const fs_grid **out);

static inline int fs_grid_clampi(int v, int hi) { return v < 0 ? 0 : (v > hi ? hi : v); }
/* Cell coordinate of x along axis a (saturated to +-1e9). */
static inline int fs_grid_coord(const fs_grid *g, int a, float x)
{
    float t = (x - g->origin[a]) / g->cell;
    return t < -1e9f ? -1000000000 : (t > 1e9f ? 1000000000 : (int)floorf(t));
}
static inline int fs_grid_floordiv(int v) { return v >= 0 ? v / FS_GRID_B : -((-v + FS_GRID_B - 1) / FS_GRID_B); }
static inline uint32_t fs_grid_hash(int bi, int bj, int bk)
{
    return ((uint32_t)bi * 73856093u) ^ ((uint32_t)bj * 19349663u) ^ ((uint32_t)bk * 83492791u);
}
/* Stored block index of block coordinates (bi, bj, bk), or FS_GRID_NONE. */
static inline uint32_t fs_grid_block(const fs_grid *g, int bi, int bj, int bk)
{
    if (!g->table) return FS_GRID_NONE;
    for (uint32_t h = fs_grid_hash(bi, bj, bk) & (uint32_t)g->table_mask;; h = (h + 1) & (uint32_t)g->table_mask) {
        uint32_t b = g->table[h];
        if (b == FS_GRID_NONE) return FS_GRID_NONE;
        const int32_t *k = g->bkey + 3 * (size_t)b;
        if (k[0] == bi && k[1] == bj && k[2] == bk) return b;
    }
}
/* Cell slot of cell (i, j, k), or FS_GRID_NONE when its block is not stored. */
static inline uint32_t fs_grid_slot(const fs_grid *g, int i, int j, int k)
{
    int bi = fs_grid_floordiv(i), bj = fs_grid_floordiv(j), bk = fs_grid_floordiv(k);
    uint32_t b = fs_grid_block(g, bi, bj, bk);
    if (b == FS_GRID_NONE) return b;
    int li = i - bi * FS_GRID_B, lj = j - bj * FS_GRID_B, lk = k - bk * FS_GRID_B;
    return b * FS_GRID_B3 + (uint32_t)((lk * FS_GRID_B + lj) * FS_GRID_B + li);
}
/* Sorted slots [*s0, *s1) of the particles in cell (i, j, k) (empty when not stored). */
static inline void fs_grid_cell_run(const fs_grid *g, int i, int j, int k, uint32_t *s0, uint32_t *s1)
{
    uint32_t c = fs_grid_slot(g, i, j, k);
    if (c == FS_GRID_NONE) {
        *s0 = *s1 = 0;
        return;
    }
    *s0 = g->start[c];
    *s1 = g->start[c + 1];
}
/* Sorted slots [*s0, *s1) of the cells i0..e of row (j, k), where e <= i1 is
 * the last of them in i0's block; returns e. Walk a row of cells as
 *   for (int i = i0, e; i <= i1; i = e + 1) {
 *       e = fs_grid_row_run(g, i, i1, j, k, &s0, &s1);
 *       for (uint32_t s = s0; s < s1; s++) ...
 *   }
 * which visits the particles in the same order as cell by cell. */
static inline int fs_grid_row_run(const fs_grid *g, int i0, int i1, int j, int k, uint32_t *s0, uint32_t *s1)
{
    int bi = fs_grid_floordiv(i0), e = bi * FS_GRID_B + FS_GRID_B - 1;
    if (e > i1) e = i1;
    uint32_t c = fs_grid_slot(g, i0, j, k);
    if (c == FS_GRID_NONE) {
        *s0 = *s1 = 0;
        return e;
    }
    *s0 = g->start[c];
    *s1 = g->start[c + (uint32_t)(e - i0) + 1];
    return e;
}
/* The particles of the cells lo..hi (inclusive) as runs of sorted slots, in the order of the
 * nested loops k, j, then i (so sums over them do not change with the walk):
 *   fs_grid_box b; fs_grid_box_begin(&b, g, lo, hi);   (or fs_grid_box_around: 27 cells)
 *   for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);) for (uint32_t s = s0; s < s1; s++) ... */
typedef struct fs_grid_box {
    const fs_grid *g;
    int lo[3], hi[3], i, j, k;
} fs_grid_box;
static inline void fs_grid_box_begin(fs_grid_box *b, const fs_grid *g, const int lo[3], const int hi[3])
{
    b->g = g;
    for (int a = 0; a < 3; a++) b->lo[a] = lo[a], b->hi[a] = hi[a];
    b->i = lo[0], b->j = lo[1], b->k = lo[2];
}
/* The 27 cells around the cell of point x: every particle within one cell size of x. */
static inline void fs_grid_box_around(fs_grid_box *b, const fs_grid *g, const float x[3])
{
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) lo[a] = fs_grid_coord(g, a, x[a]) - 1, hi[a] = lo[a] + 2;
    fs_grid_box_begin(b, g, lo, hi);
}
/* The next run [*s0, *s1) (possibly empty); 0 when the box is done. */
static inline int fs_grid_box_next(fs_grid_box *b, uint32_t *s0, uint32_t *s1)
{
    while (b->k <= b->hi[2]) {
        if (b->i <= b->hi[0]) {
            b->i = fs_grid_row_run(b->g, b->i, b->hi[0], b->j, b->k, s0, s1) + 1;
            return 1;
        }
        b->i = b->lo[0];
        if (++b->j > b->hi[1]) b->j = b->lo[1], b->k++;
    }
    return 0;
}
/* 1 when a particle lies in one of the 27 cells around cell (i, j, k). */
static inline int fs_grid_near_occupied(const fs_grid *g, int i, int j, int k)
{
    uint32_t c = fs_grid_slot(g, i, j, k);
    return c != FS_GRID_NONE && (g->near[c >> 5] >> (c & 31) & 1u);
}

/* Runs of sorted slots [runs[i][0], runs[i][1]) of the particles in the cells
 * lo..hi (inclusive, at most 4 cells an axis: at most 2 blocks an axis and
 * FS_GRID_MAX_RUNS runs), with one hash lookup per block. Returns the count. */
#define FS_GRID_MAX_RUNS 32
int fs_grid_box_runs(const fs_grid *g, const int lo[3], const int hi[3], uint32_t runs[][2]);

/* Calls fn(user, sorted_slot, dist2) for every particle within radius of x.
 * radius may exceed the cell size (more cells are visited). Returns the
 * particles whose distance it computed (for the work counters). */
typedef void (*fs_grid_visit)(void *user, uint32_t slot, float dist2);
size_t fs_grid_query(const fs_grid *g, const float x[3], float radius, fs_grid_visit fn, void *user);

#ifdef __cplusplus
}
#endif
#endif
