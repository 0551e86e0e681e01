/* Block-sparse neighbour grid (grid.h). Cell and block coordinates are computed
 * in parallel; the block set, the histogram and the scatter stay serial so
 * particles keep their original order inside a cell, which makes every sum
 * over a cell (and so every image) reproducible whatever the thread count.
 * Clusters and the bulk box are in grid_cluster.c. */
#include "grid.h"
#include "fs_error.h"
#include "grid_internal.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Below this many particles a parallel loop costs more (thread wake-up) than it saves. */
#define FS_GRID_PARALLEL_MIN 100000
/* Cell coordinates stay below this (with room for +-radius sums and block
 * arithmetic in int32, and below fs_grid_coord's saturation at 1e9). */
#define FS_GRID_MAX_COORD (1 << 29)

void fs_grid_free(fs_grid *g)
{
    free(g->bkey);
    free(g->start);
    free(g->near);
    free(g->table);
    free(g->index);
    free(g->pos4);
    free(g->clusters);
    memset(g, 0, sizeof *g);
}

/* Bounding box of the positions; fails on a NaN/Inf position (it would make
 * floorf() undefined when cast to int). */
static int positions_box(const fs_particles *p, float lo[3], float hi[3])
{
    float x0 = INFINITY, y0 = INFINITY, z0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, z1 = -INFINITY;
    long bad = -1;
    long n = (long)p->n;
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) reduction(min : x0, y0, z0) reduction(max : x1, y1, z1, bad)
    for (long i = 0; i < n; i++) {
        float x = p->x[i], y = p->y[i], z = p->z[i];
        if (!isfinite(x) || !isfinite(y) || !isfinite(z)) {
            if (i > bad) bad = i;
            continue;
        }
        x0 = fminf(x0, x);
        y0 = fminf(y0, y);
        z0 = fminf(z0, z);
        x1 = fmaxf(x1, x);
        y1 = fmaxf(y1, y);
        z1 = fmaxf(z1, z);
    }
    if (bad >= 0) return fs_fail(FS_ERR_INPUT, "particles: particle %ld has a non-finite position", bad);
    lo[0] = x0;
    lo[1] = y0;
    lo[2] = z0;
    hi[0] = x1;
    hi[1] = y1;
    hi[2] = z1;
    return FS_OK;
}

/* Refuses a set whose far end lies too many cells from the origin, naming the
 * farthest particle along the offending axis. */
static int check_span(const fs_grid *g, const fs_particles *p, const float hi[3])
{
    for (int a = 0; a < 3; a++) {
        double cells = ((double)hi[a] - g->origin[a]) / g->cell;
        if (cells < FS_GRID_MAX_COORD) continue;
        const float *v = a == 0 ? p->x : (a == 1 ? p->y : p->z);
        size_t far = 0;
        while (far < p->n && v[far] != hi[a]) far++;
        return fs_fail(FS_ERR_INPUT,
                       "grid: particle %zu lies %g from the lowest particle along %c, more than 2^29 cells of %g: "
                       "drop the stray particles or raise the cell size",
                       far, (double)hi[a] - g->origin[a] - g->cell, "xyz"[a], g -> cell);
    }
    return FS_OK;
}

/* Per particle: its block's coordinates (bc, 3 ints) and its cell in the block (local). */
static void particle_keys(const fs_grid *g, const fs_particles *p, int32_t *bc, uint8_t *local)
{
    long n = (long)p->n;
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) schedule(static)
    for (long i = 0; i < n; i++) {
        int c[3] = {fs_grid_coord(g, 0, p->x[i]), fs_grid_coord(g, 1, p->y[i]), fs_grid_coord(g, 2, p->z[i])};
        int l[3];
        for (int a = 0; a < 3; a++) {
            bc[3 * i + a] = fs_grid_floordiv(c[a]);
            l[a] = c[a] - bc[3 * i + a] * FS_GRID_B;
        }
        local[i] = (uint8_t)((l[2] * FS_GRID_B + l[1]) * FS_GRID_B + l[0]);
    }
}

/* The occupied blocks in order of first appearance (serial, so deterministic):
 * *tb[i] = the block of particle i, set->mask[b] = its occupied cells. */
static int occupied_blocks(fs_grid_blockset *set, size_t n, const int32_t *bc, const uint8_t *local, uint32_t *tb)
{
    uint32_t last = FS_GRID_NONE;
    for (size_t i = 0; i < n; i++) {
        const int32_t *k = bc + 3 * i;
        if (last == FS_GRID_NONE || memcmp(set->key + 3 * (size_t)last, k, 3 * sizeof *k) != 0) {
            last = fs_grid_blockset_add(set, k[0], k[1], k[2]);
            if (last == FS_GRID_NONE) return 1;
        }
        tb[i] = last;
        set->mask[last] |= 1ull << local[i];
    }
    return 0;
}

/* Bits of the cells with local coordinate 0 (side -1) or B-1 (side +1) along axis a. */
static uint64_t face_mask(int a, int side)
{
    uint64_t m = 0;
    for (int l = 0; l < FS_GRID_B3; l++) {
        int c = a == 0 ? l % FS_GRID_B : (a == 1 ? l / FS_GRID_B % FS_GRID_B : l / (FS_GRID_B * FS_GRID_B));
        if (c == (side < 0 ? 0 : FS_GRID_B - 1)) m |= 1ull << l;
    }
    return m;
}

/* Adds every block that holds a cell next to an occupied cell: neighbour block
 * d of b is needed when b has an occupied cell on each face d points through. */
static int dilate(fs_grid_blockset *set)
{
    uint64_t face[3][2];
    for (int a = 0; a < 3; a++) {
        face[a][0] = face_mask(a, -1);
        face[a][1] = face_mask(a, +1);
    }
    size_t nocc = set->n;
    for (size_t b = 0; b < nocc; b++)
        for (int dk = -1; dk <= 1; dk++)
            for (int dj = -1; dj <= 1; dj++)
                for (int di = -1; di <= 1; di++) {
                    if (!di && !dj && !dk) continue;
                    uint64_t m = set->mask[b];
                    int d[3] = {di, dj, dk};
                    for (int a = 0; a < 3 && m; a++)
                        if (d[a]) m &= face[a][d[a] > 0];
                    if (!m) continue;
                    const int32_t *k = set->key + 3 * b;
                    if (fs_grid_blockset_add(set, k[0] + di, k[1] + dj, k[2] + dk) == FS_GRID_NONE) return 1;
                }
    return 0;
}

static int cmp_key(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    for (int c = 2; c >= 0; c--)
        if (a[c] != b[c]) return a[c] < b[c] ? -1 : 1;
    return 0;
}

/* Moves the blocks into the grid sorted by (bk, bj, bi) and builds its hash
 * table; remap[t] = the final index of set block t. */
static int final_blocks(fs_grid *g, const fs_grid_blockset *set, uint32_t *remap)
{
    size_t nb = set->n;
    int32_t *tagged = malloc((nb ? nb : 1) * 4 * sizeof *tagged); /* key + set index */
    g->bkey = malloc((nb ? nb : 1) * 3 * sizeof *g->bkey);
    size_t size = 1;
    while (size < 2 * nb) size *= 2;
    g->table = malloc(size * sizeof *g->table);
    if (!tagged || !g->bkey || !g->table) {
        free(tagged);
        return 1;
    }
    for (size_t b = 0; b < nb; b++) {
        memcpy(tagged + 4 * b, set->key + 3 * b, 3 * sizeof *tagged);
        tagged[4 * b + 3] = (int32_t)b;
    }
    qsort(tagged, nb, 4 * sizeof *tagged, cmp_key);
    g->nblocks = nb;
    g->table_mask = size - 1;
    memset(g->table, 0xff, size * sizeof *g->table);
    for (size_t b = 0; b < nb; b++) {
        const int32_t *k = tagged + 4 * b;
        memcpy(g->bkey + 3 * b, k, 3 * sizeof *k);
        remap[k[3]] = (uint32_t)b;
        uint32_t h = fs_grid_hash(k[0], k[1], k[2]) & (uint32_t)g->table_mask;
        while (g->table[h] != FS_GRID_NONE) h = (h + 1) & (uint32_t)g->table_mask;
        g->table[h] = (uint32_t)b;
    }
    free(tagged);
    return 0;
}

/* Stable counting sort of the particles by cell slot, then the sorted positions. */
static void sort_particles(fs_grid *g, const fs_particles *p, const uint32_t *slot)
{
    size_t n = p->n;
    for (size_t i = 0; i < n; i++) g->start[slot[i] + 1]++;
    for (size_t c = 0; c < g->ncells; c++) g->start[c + 1] += g->start[c];
    for (size_t i = 0; i < n; i++) g->index[g->start[slot[i]]++] = (uint32_t)i;
    memmove(g->start + 1, g->start, g->ncells * sizeof *g->start);
    g->start[0] = 0;
    long nl = (long)n;
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) schedule(static)
    for (long s = 0; s < nl; s++) {
        uint32_t i = g->index[s];
        float *q = g->pos4 + 4 * s;
        q[0] = p->x[i];
        q[1] = p->y[i];
        q[2] = p->z[i];
        memcpy(&q[3], &i, sizeof i);
    }
}

/* Near bits of block b: a cell's bit is set when one of its 27 cells holds a
 * particle. Each block owns its two words, so blocks run in parallel. */
static void near_block(fs_grid *g, size_t b)
{
    enum { W = FS_GRID_B + 2 };
    uint8_t occ[W * W * W];
    memset(occ, 0, sizeof occ);
    const int32_t *k = g->bkey + 3 * b;
    for (int dk = -1; dk <= 1; dk++)
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++) {
                uint32_t nb = fs_grid_block(g, k[0] + di, k[1] + dj, k[2] + dk);
                if (nb == FS_GRID_NONE) continue;
                const uint32_t *st = g->start + (size_t)nb * FS_GRID_B3;
                for (int l = 0; l < FS_GRID_B3; l++) {
                    if (st[l + 1] == st[l]) continue;
                    int x = l % FS_GRID_B + 1 + di * FS_GRID_B, y = l / FS_GRID_B % FS_GRID_B + 1 + dj * FS_GRID_B,
                        z = l / (FS_GRID_B * FS_GRID_B) + 1 + dk * FS_GRID_B;
                    if (x >= 0 && x < W && y >= 0 && y < W && z >= 0 && z < W) occ[(z * W + y) * W + x] = 1;
                }
            }
    uint64_t bits = 0;
    for (int l = 0; l < FS_GRID_B3; l++) {
        int x = l % FS_GRID_B + 1, y = l / FS_GRID_B % FS_GRID_B + 1, z = l / (FS_GRID_B * FS_GRID_B) + 1, any = 0;
        for (int zz = z - 1; zz <= z + 1 && !any; zz++)
            for (int yy = y - 1; yy <= y + 1 && !any; yy++)
                for (int xx = x - 1; xx <= x + 1; xx++) any |= occ[(zz * W + yy) * W + xx];
        if (any) bits |= 1ull << l;
    }
    g->near[2 * b] = (uint32_t)bits;
    g->near[2 * b + 1] = (uint32_t)(bits >> 32);
}

static void near_bits(fs_grid *g)
{
    long nb = (long)g->nblocks;
#pragma omp parallel for if (g->n > FS_GRID_PARALLEL_MIN) schedule(static)
    for (long b = 0; b < nb; b++) near_block(g, (size_t)b);
}

static void stored_range(fs_grid *g)
{
    for (int a = 0; a < 3; a++) {
        g->lo[a] = g->nblocks ? INT32_MAX : 0;
        g->hi[a] = g->nblocks ? INT32_MIN : -1;
    }
    for (size_t b = 0; b < g->nblocks; b++)
        for (int a = 0; a < 3; a++) {
            int c = g->bkey[3 * b + a] * FS_GRID_B;
            if (c < g->lo[a]) g->lo[a] = c;
            if (c + FS_GRID_B - 1 > g->hi[a]) g->hi[a] = c + FS_GRID_B - 1;
        }
}

/* The blocks and the per-particle cell slots (slot[i]); the block set is freed. */
static int build_blocks(fs_grid *g, const fs_particles *p, uint32_t *slot)
{
    size_t n = p->n;
    int32_t *bc = malloc((n ? n : 1) * 3 * sizeof *bc);
    uint8_t *local = malloc(n ? n : 1);
    fs_grid_blockset set;
    int bad = !bc || !local || fs_grid_blockset_init(&set, 64);
    if (!bad) {
        particle_keys(g, p, bc, local);
        bad = occupied_blocks(&set, n, bc, local, slot) || dilate(&set);
    }
    free(bc);
    uint32_t *remap = bad ? NULL : malloc((set.n ? set.n : 1) * sizeof *remap);
    bad = bad || !remap || set.n > UINT32_MAX / FS_GRID_B3 - 1 || final_blocks(g, &set, remap);
    if (!bad) {
        long nl = (long)n;
#pragma omp parallel for if (n > FS_GRID_PARALLEL_MIN) schedule(static)
        for (long i = 0; i < nl; i++) slot[i] = remap[slot[i]] * FS_GRID_B3 + local[i];
    }
    free(local);
    free(remap);
    if (set.key) fs_grid_blockset_free(&set);
    return bad;
}

int fs_grid_build(fs_grid *g, const fs_particles *p, float cell)
{
    memset(g, 0, sizeof *g);
    if (!(cell > 0) || !isfinite(cell))
        return fs_fail(FS_ERR_INPUT, "grid: cell size %g must be a positive number", cell);
    if (p->n >= UINT32_MAX)
        return fs_fail(FS_ERR_INPUT, "grid: %zu particles: too many (at most %u)", p->n, UINT32_MAX - 1);
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    if (p->n) {
        int rc = positions_box(p, lo, hi);
        if (rc) return rc;
    }
    /* One empty cell of margin below the lowest particle, as the dense grid had,
     * so cells (and every sum over them) are the same as before. */
    for (int a = 0; a < 3; a++) g->origin[a] = lo[a] - cell;
    g->cell = cell;
    g->n = p->n;
    int rc = check_span(g, p, hi);
    if (rc) {
        memset(g, 0, sizeof *g);
        return rc;
    }
    size_t n = p->n;
    uint32_t *slot = malloc((n ? n : 1) * sizeof *slot);
    if (!slot || build_blocks(g, p, slot)) {
        free(slot);
        fs_grid_free(g);
        return fs_fail(FS_ERR_RUNTIME, "grid: out of memory for %zu particles", n);
    }
    g->ncells = g->nblocks * FS_GRID_B3;
    g->start = calloc(g->ncells + 1, sizeof *g->start);
    g->near = calloc(g->ncells / 32 + 1, sizeof *g->near);
    g->index = malloc((n ? n : 1) * sizeof *g->index);
    g->pos4 = malloc((n ? n : 1) * 4 * sizeof *g->pos4);
    if (!g->start || !g->near || !g->index || !g->pos4) {
        free(slot);
        fs_grid_free(g);
        return fs_fail(FS_ERR_RUNTIME, "grid: out of memory for %zu particles", n);
    }
    sort_particles(g, p, slot);
    free(slot);
    near_bits(g);
    stored_range(g);
    if (fs_grid_clusters(g)) {
        fs_grid_free(g);
        return fs_fail(FS_ERR_RUNTIME, "grid: out of memory for the clusters of %zu particles", n);
    }
    return FS_OK;
}

/* Visits the particles within r2 of x in the cells of row (i0..i1, j, k). */
static size_t query_row(const fs_grid *g, int i0, int i1, int j, int k, const float x[3], float r2, fs_grid_visit fn,
                        void *user)
{
    uint32_t s0, s1;
    size_t tested = 0;
    for (int i = i0, e; i <= i1; i = e + 1) {
        e = fs_grid_row_run(g, i, i1, j, k, &s0, &s1);
        tested += s1 - s0;
        for (uint32_t s = s0; s < s1; s++) {
            const float *q = g->pos4 + 4 * (size_t)s;
            float dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
            float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 <= r2) fn(user, s, d2);
        }
    }
    return tested;
}

size_t fs_grid_query(const fs_grid *g, const float x[3], float radius, fs_grid_visit fn, void *user)
{
    if (!g->n || !(radius >= 0)) return 0;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = fs_grid_coord(g, a, x[a] - radius);
        hi[a] = fs_grid_coord(g, a, x[a] + radius);
        if (hi[a] < g->lo[a] || lo[a] > g->hi[a]) return 0; /* the ball misses every stored cell */
        if (lo[a] < g->lo[a]) lo[a] = g->lo[a];
        if (hi[a] > g->hi[a]) hi[a] = g->hi[a];
    }
    float r2 = radius * radius;
    size_t tested = 0;
    for (int k = lo[2]; k <= hi[2]; k++)
        for (int j = lo[1]; j <= hi[1]; j++) tested += query_row(g, lo[0], hi[0], j, k, x, r2, fn, user);
    return tested;
}

int fs_grid_fit(const fs_grid *given, const fs_particles *p, float cell, fs_grid *own, int *has_own,
                const fs_grid **out)
{
    if (*has_own) {
        fs_grid_free(own);
        *has_own = 0;
    }
    *out = given;
    if (given && given->cell >= cell && given->n == p->n) return FS_OK;
    int rc = fs_grid_build(own, p, cell);
    if (rc) return rc;
    *has_own = 1;
    *out = own;
    return FS_OK;
}

int fs_grid_box_runs(const fs_grid *g, const int lo[3], const int hi[3], uint32_t runs[][2])
{
    int n = 0;
    for (int bk = fs_grid_floordiv(lo[2]); bk <= fs_grid_floordiv(hi[2]); bk++)
        for (int bj = fs_grid_floordiv(lo[1]); bj <= fs_grid_floordiv(hi[1]); bj++)
            for (int bi = fs_grid_floordiv(lo[0]); bi <= fs_grid_floordiv(hi[0]); bi++) {
                uint32_t b = fs_grid_block(g, bi, bj, bk);
                if (b == FS_GRID_NONE) continue;
                int i0 = lo[0] - bi * FS_GRID_B, i1 = hi[0] - bi * FS_GRID_B;
                i0 = i0 < 0 ? 0 : i0;
                i1 = i1 > FS_GRID_B - 1 ? FS_GRID_B - 1 : i1;
                int j0 = lo[1] - bj * FS_GRID_B, j1 = hi[1] - bj * FS_GRID_B;
                j0 = j0 < 0 ? 0 : j0;
                j1 = j1 > FS_GRID_B - 1 ? FS_GRID_B - 1 : j1;
                int k0 = lo[2] - bk * FS_GRID_B, k1 = hi[2] - bk * FS_GRID_B;
                k0 = k0 < 0 ? 0 : k0;
                k1 = k1 > FS_GRID_B - 1 ? FS_GRID_B - 1 : k1;
                for (int k = k0; k <= k1; k++)
                    for (int j = j0; j <= j1; j++) {
                        uint32_t row = b * FS_GRID_B3 + (uint32_t)((k * FS_GRID_B + j) * FS_GRID_B);
                        uint32_t s0 = g->start[row + i0], s1 = g->start[row + i1 + 1];
                        if (s1 > s0) {
                            runs[n][0] = s0;
                            runs[n][1] = s1;
                            n++;
                        }
                    }
            }
    return n;
}
