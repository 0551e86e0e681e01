/* Clusters of the neighbour grid and its bulk box (grid.h, docs/DESIGN.md
 * "Neighbour grid"): connected components of the stored blocks, and the rule
 * that tells the body of the fluid from far strays. */
#include "grid_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint32_t find(uint32_t *parent, uint32_t b)
{
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
}

/* parent[] of a union-find over the blocks, 26-neighbours joined. */
static void join_neighbours(const fs_grid *g, uint32_t *parent)
{
    for (size_t b = 0; b < g->nblocks; b++) parent[b] = (uint32_t)b;
    for (size_t b = 0; b < g->nblocks; b++) {
        const int32_t *k = g->bkey + 3 * b;
        for (int d = 14; d < 27; d++) { /* the 13 offsets after (0,0,0): each pair once */
            int di = d % 3 - 1, dj = d / 3 % 3 - 1, dk = d / 9 - 1;
            uint32_t nb = fs_grid_block(g, k[0] + di, k[1] + dj, k[2] + dk);
            if (nb == FS_GRID_NONE) continue;
            uint32_t ra = find(parent, (uint32_t)b), rb = find(parent, nb);
            if (ra != rb) parent[ra > rb ? ra : rb] = ra < rb ? ra : rb;
        }
    }
}

static int cmp_cluster(const void *pa, const void *pb)
{
    const fs_grid_cluster *a = pa, *b = pb;
    if (a->n != b->n) return a->n > b->n ? -1 : 1;
    for (int c = 2; c >= 0; c--)
        if (a->lo[c] != b->lo[c]) return a->lo[c] < b->lo[c] ? -1 : 1;
    return 0;
}

static size_t block_count(const fs_grid *g, size_t b)
{
    return g->start[(b + 1) * FS_GRID_B3] - g->start[b * FS_GRID_B3];
}

/* Largest gap (in cells) between box c and box (lo, hi) over the axes; 0 when they overlap. */
static int box_gap(const fs_grid_cluster *c, const int lo[3], const int hi[3])
{
    int gap = 0;
    for (int a = 0; a < 3; a++) {
        int d = c->lo[a] > hi[a] ? c->lo[a] - hi[a] - 1 : (lo[a] > c->hi[a] ? lo[a] - c->hi[a] - 1 : 0);
        if (d > gap) gap = d;
    }
    return gap;
}

/* in_bulk[c]: the largest cluster and every one with >= 1% of the particles
 * make the core; a cluster within one core extent (its longest side) of the
 * core box also joins, so spray thrown off the body stays in the bulk. */
static void bulk_clusters(const fs_grid *g, char *in_bulk)
{
    int lo[3], hi[3];
    memcpy(lo, g->clusters[0].lo, sizeof lo);
    memcpy(hi, g->clusters[0].hi, sizeof hi);
    for (int c = 0; c < g->nclusters; c++) {
        in_bulk[c] = c == 0 || g->clusters[c].n * 100 >= g->n;
        if (!in_bulk[c]) continue;
        for (int a = 0; a < 3; a++) {
            if (g->clusters[c].lo[a] < lo[a]) lo[a] = g->clusters[c].lo[a];
            if (g->clusters[c].hi[a] > hi[a]) hi[a] = g->clusters[c].hi[a];
        }
    }
    int extent = 0;
    for (int a = 0; a < 3; a++)
        if (hi[a] - lo[a] + 1 > extent) extent = hi[a] - lo[a] + 1;
    for (int c = 0; c < g->nclusters; c++)
        if (!in_bulk[c] && box_gap(&g->clusters[c], lo, hi) <= extent) in_bulk[c] = 1;
}

/* bulk_lo/hi: the box of the positions of the particles in bulk clusters. */
static void bulk_box(fs_grid *g, const uint32_t *label, const int *rank, const char *in_bulk)
{
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t b = 0; b < g->nblocks; b++) {
        if (!in_bulk[rank[label[b]]]) continue;
        for (uint32_t s = g->start[b * FS_GRID_B3]; s < g->start[(b + 1) * FS_GRID_B3]; s++)
            for (int a = 0; a < 3; a++) {
                float v = g->pos4[4 * (size_t)s + a];
                if (v < lo[a]) lo[a] = v;
                if (v > hi[a]) hi[a] = v;
            }
    }
    memcpy(g->bulk_lo, lo, sizeof lo);
    memcpy(g->bulk_hi, hi, sizeof hi);
}

/* Cluster records indexed by root label (label[b] = dense cluster id of block b). */
static fs_grid_cluster *collect(const fs_grid *g, const uint32_t *parent, uint32_t *label, int *count)
{
    int nc = 0;
    for (size_t b = 0; b < g->nblocks; b++)
        if (parent[b] == b) label[b] = (uint32_t)nc++;
    fs_grid_cluster *cl = calloc(nc ? (size_t)nc : 1, sizeof *cl);
    if (!cl) return NULL;
    for (int c = 0; c < nc; c++)
        for (int a = 0; a < 3; a++) {
            cl[c].lo[a] = INT32_MAX;
            cl[c].hi[a] = INT32_MIN;
        }
    for (size_t b = 0; b < g->nblocks; b++) {
        label[b] = label[find((uint32_t *)parent, (uint32_t)b)];
        fs_grid_cluster *c = cl + label[b];
        c->n += block_count(g, b);
        for (int a = 0; a < 3; a++) {
            int v = g->bkey[3 * b + a] * FS_GRID_B;
            if (v < c->lo[a]) c->lo[a] = v;
            if (v + FS_GRID_B - 1 > c->hi[a]) c->hi[a] = v + FS_GRID_B - 1;
        }
    }
    *count = nc;
    return cl;
}

int fs_grid_clusters(fs_grid *g)
{
    for (int a = 0; a < 3; a++) g->bulk_lo[a] = g->bulk_hi[a] = 0;
    g->nclusters = 0;
    if (!g->nblocks) return 0;
    uint32_t *parent = malloc(g->nblocks * sizeof *parent), *label = malloc(g->nblocks * sizeof *label);
    fs_grid_cluster *cl = NULL;
    int nc = 0, *rank = NULL;
    char *in_bulk = NULL;
    if (parent && label) {
        join_neighbours(g, parent);
        cl = collect(g, parent, label, &nc);
    }
    if (cl) {
        rank = malloc((size_t)nc * sizeof *rank);
        in_bulk = malloc((size_t)nc);
    }
    if (!rank || !in_bulk) {
        free(parent);
        free(label);
        free(cl);
        free(rank);
        free(in_bulk);
        return 1;
    }
    /* Sort, remembering where each label went. */
    for (int c = 0; c < nc; c++) cl[c].n = cl[c].n * (size_t)nc + (size_t)c; /* tag; undone below */
    qsort(cl, (size_t)nc, sizeof *cl, cmp_cluster);
    for (int c = 0; c < nc; c++) {
        rank[cl[c].n % (size_t)nc] = c;
        cl[c].n /= (size_t)nc;
    }
    g->clusters = cl;
    g->nclusters = nc;
    bulk_clusters(g, in_bulk);
    bulk_box(g, label, rank, in_bulk);
    free(parent);
    free(label);
    free(rank);
    free(in_bulk);
    return 0;
}
