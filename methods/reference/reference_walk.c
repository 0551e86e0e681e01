/* A ray's walk through the block-sparse grid (reference.h). The ray is first
 * clipped to the boxes of the grid's clusters, so a stray particle thousands of
 * metres away costs one box test instead of a walk across the empty space to
 * it; inside a box a 3D-DDA visits the cells, and cells whose block is not
 * stored (no particle within a cell of them: phi = 0) are passed without a
 * call, one call with FS_GRID_NONE marking the start of each such run. */
#include "reference.h"
#include <math.h>
#include <string.h>

/* Boxes tested per ray; the clusters beyond these share one box. */
#define FS_REF_MAX_BOXES 16

typedef struct cell_box {
    int lo[3], hi[3];
} cell_box;
typedef struct span {
    float te, tx;
    int box;
} span;

/* Entry and exit distances of the ray in a box of cells; 0 when it misses. */
static int clip_box(const fs_grid *g, const cell_box *b, const float o[3], const float d[3], float *te, float *tx)
{
    float t0 = 0, t1 = INFINITY;
    for (int a = 0; a < 3; a++) {
        float lo = g->origin[a] + g->cell * (float)b->lo[a], hi = g->origin[a] + g->cell * (float)(b->hi[a] + 1);
        if (d[a] == 0) {
            if (o[a] < lo || o[a] > hi) return 0;
            continue;
        }
        float u = (lo - o[a]) / d[a], v = (hi - o[a]) / d[a];
        if (u > v) {
            float w = u;
            u = v;
            v = w;
        }
        t0 = fs_maxf(t0, u);
        t1 = fs_minf(t1, v);
    }
    *te = t0;
    *tx = t1;
    return t0 < t1;
}

/* The boxes of the clusters: the largest FS_REF_MAX_BOXES - 1, and one box around the rest. */
static int cluster_boxes(const fs_grid *g, cell_box *out)
{
    int n = g->nclusters, k = n < FS_REF_MAX_BOXES ? n : FS_REF_MAX_BOXES - 1;
    for (int i = 0; i < k; i++) {
        memcpy(out[i].lo, g->clusters[i].lo, sizeof out[i].lo);
        memcpy(out[i].hi, g->clusters[i].hi, sizeof out[i].hi);
    }
    if (n <= k) return k;
    cell_box rest = {{g->clusters[k].lo[0], g->clusters[k].lo[1], g->clusters[k].lo[2]},
                     {g->clusters[k].hi[0], g->clusters[k].hi[1], g->clusters[k].hi[2]}};
    for (int i = k + 1; i < n; i++)
        for (int a = 0; a < 3; a++) {
            if (g->clusters[i].lo[a] < rest.lo[a]) rest.lo[a] = g->clusters[i].lo[a];
            if (g->clusters[i].hi[a] > rest.hi[a]) rest.hi[a] = g->clusters[i].hi[a];
        }
    out[k] = rest;
    return k + 1;
}

typedef struct dda {
    int c[3], step[3];
    float tmax[3], tdelta[3];
} dda;

static void dda_start(const fs_grid *g, const cell_box *b, const float o[3], const float d[3], float t, dda *w)
{
    for (int a = 0; a < 3; a++) {
        int c = fs_grid_coord(g, a, o[a] + t * d[a]);
        w->c[a] = c < b->lo[a] ? b->lo[a] : (c > b->hi[a] ? b->hi[a] : c);
        float face = g->origin[a] + g->cell * (float)(w->c[a] + (d[a] > 0));
        if (d[a] != 0) {
            w->step[a] = d[a] > 0 ? 1 : -1;
            w->tmax[a] = (face - o[a]) / d[a];
            w->tdelta[a] = g->cell / fabsf(d[a]);
        } else {
            w->step[a] = 0;
            w->tmax[a] = w->tdelta[a] = INFINITY;
        }
    }
}

/* Walks [te, tx] of one box; returns 1 when the visitor finished the ray. */
static int walk_box(const reference *R, const cell_box *b, const float o[3], const float d[3], float te, float tx,
                    fs_ref_visit visit, void *ctx)
{
    const fs_grid *g = R->g;
    dda w;
    dda_start(g, b, o, d, te, &w);
    int bkey[3] = {INT32_MIN, 0, 0}, far = 0;
    uint32_t blk = FS_GRID_NONE;
    for (float t = te;;) {
        float t_out = fs_minf(fs_minf(w.tmax[0], w.tmax[1]), fs_minf(w.tmax[2], tx));
        if (t_out < t) t_out = t;
        int bk[3] = {fs_grid_floordiv(w.c[0]), fs_grid_floordiv(w.c[1]), fs_grid_floordiv(w.c[2])};
        if (bk[0] != bkey[0] || bk[1] != bkey[1] || bk[2] != bkey[2]) {
            memcpy(bkey, bk, sizeof bkey);
            blk = fs_grid_block(g, bk[0], bk[1], bk[2]);
        }
        uint32_t slot = FS_GRID_NONE;
        if (blk != FS_GRID_NONE) {
            int li = w.c[0] - bk[0] * FS_GRID_B, lj = w.c[1] - bk[1] * FS_GRID_B, lk = w.c[2] - bk[2] * FS_GRID_B;
            slot = blk * FS_GRID_B3 + (uint32_t)((lk * FS_GRID_B + lj) * FS_GRID_B + li);
            if (!(g->near[slot >> 5] >> (slot & 31) & 1u)) slot = FS_GRID_NONE;
        }
        if (slot != FS_GRID_NONE) {
            far = 0;
            if (t_out > t && visit(ctx, w.c, slot, t, t_out)) return 1;
        } else if (!far) {
            far = 1;
            if (visit(ctx, w.c, FS_GRID_NONE, t, t_out)) return 1;
        }
        if (t_out >= tx) return 0;
        int a = w.tmax[0] < w.tmax[1] ? (w.tmax[0] < w.tmax[2] ? 0 : 2) : (w.tmax[1] < w.tmax[2] ? 1 : 2);
        w.c[a] += w.step[a];
        if (w.c[a] < b->lo[a] || w.c[a] > b->hi[a]) return 0;
        w.tmax[a] += w.tdelta[a];
        t = t_out;
    }
}

void fs_ref_walk(const reference *R, const float o[3], const float d[3], fs_ref_visit visit, void *ctx, float *t_last)
{
    const fs_grid *g = R->g;
    cell_box boxes[FS_REF_MAX_BOXES];
    span sp[FS_REF_MAX_BOXES];
    int nb = cluster_boxes(g, boxes), ns = 0;
    *t_last = 0;
    for (int i = 0; i < nb; i++) {
        float te, tx;
        if (!clip_box(g, &boxes[i], o, d, &te, &tx)) continue;
        int k = ns++; /* insertion by entry distance */
        while (k > 0 && sp[k - 1].te > te) {
            sp[k] = sp[k - 1];
            k--;
        }
        sp[k] = (span){te, tx, i};
    }
    /* Two clusters' boxes may overlap; the walk of the first already visited
     * every cell of the overlap (lookups are global), so the later starts where
     * the earlier ended. */
    float done = 0;
    for (int i = 0; i < ns; i++) {
        float te = sp[i].te > done ? sp[i].te : done;
        if (te >= sp[i].tx) continue;
        if (i > 0 && visit(ctx, NULL, FS_GRID_NONE, done, te)) {
            *t_last = te;
            return;
        }
        if (walk_box(R, &boxes[sp[i].box], o, d, te, sp[i].tx, visit, ctx)) {
            *t_last = sp[i].tx;
            return;
        }
        done = sp[i].tx;
    }
    *t_last = done;
}

void fs_ref_leave_fluid(march *m, ray_result *res, float t, const reference *R)
{
    if (m->inside && m->counting) res->thick += t - m->t_enter;
    m->inside = m->counting = 0;
    m->g = -R->f.iso;
    m->started = 1;
}

int fs_ref_cross(const reference *R, march *m, ray_result *res, float t, const float outward[3], const float d[3])
{
    if (!m->inside) {
        if (!res->hit) {
            float l = sqrtf(outward[0] * outward[0] + outward[1] * outward[1] + outward[2] * outward[2]);
            for (int a = 0; a < 3; a++) res->n[a] = l > 0 ? outward[a] / l : -d[a];
            res->hit = 1;
            res->t = t;
            if (!R->thickness) return 1;
        }
        m->t_enter = t;
        m->counting = 1;
        m->layers++;
    } else {
        if (m->counting) res->thick += t - m->t_enter;
        m->counting = 0;
        if (m->layers >= R->max_layers) return 1;
    }
    m->inside = !m->inside;
    m->s_prev = R->step_min;
    return 0;
}

void fs_ref_work_add(ray_work *dst, const ray_work *src)
{
    dst->evals += src->evals;
    dst->samples += src->samples;
    dst->nbrs += src->nbrs;
    dst->crossings += src->crossings;
    dst->cells += src->cells;
    dst->marched += src->marched;
    dst->marched_in += src->marched_in;
    dst->proven_in += src->proven_in;
    dst->proven_out += src->proven_out;
    dst->refine_evals += src->refine_evals;
    dst->inside_evals += src->inside_evals;
    dst->waits += src->waits;
}

void fs_ref_cell_begin(ray_result *res, const march *m, cell_mark *c)
{
    c->w = &res->w[res->hit];
    c->evals = res->w[0].evals + res->w[1].evals;
    c->crossings = res->w[0].crossings + res->w[1].crossings;
    c->inside = m->started && m->inside;
}

void fs_ref_cell_end(const cell_mark *c, const ray_result *res, const march *m, int proven)
{
    c->w->cells++;
    uint64_t evals = res->w[0].evals + res->w[1].evals - c->evals;
    if (evals) {
        int in = c->inside && res->w[0].crossings + res->w[1].crossings == c->crossings;
        c->w->marched++;
        c->w->marched_in += in;
        c->w->inside_evals += in ? evals : 0;
    } else if (proven) {
        if (m->inside) c->w->proven_in++;
        else c->w->proven_out++;
    }
}
