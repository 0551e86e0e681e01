/* Sub-cell bounds of phi for the accelerated reference (README.md, "Sub-cell
 * bounds"). Each near cell is cut into sub^3 sub-cells; every kernel decreases
 * with distance, so over a sub-cell particle j contributes at most V W(d_near)
 * and at least V W(d_far), its nearest and farthest distances to the box.
 * Summed, they bound phi on the whole closed sub-cell. The sums are stored
 * in units of iso / FS_REF_Q, the upper rounded up and the lower down (with a
 * margin far above the float error of the sums), so the classes they give are
 * proven: hi < FS_REF_Q means phi < iso everywhere, lo >= FS_REF_Q phi >= iso.
 * Built by gathering, per cell: up front in parallel over blocks, or on demand by
 * the first ray that walks the cell (a claim per cell; a ray that finds it claimed
 * waits for it). Either way a cell's bounds are a function of the cell alone. */
#include "counters.h"
#include "fs_error.h"
#include "reference.h"
#include <math.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>

void fs_ref_bounds_free(reference *R)
{
    free(R->lo);
    free(R->hi);
    free(R->cell_cls);
    R->lo = R->hi = R->cell_cls = NULL;
}

/* Sub-cells per cell edge: about 2r on a side, 1, 2 or 4 (divisors of
 * FS_REF_FINE, so a fine sub-cell lies in one coarse one), and none for the
 * anisotropic field, whose metric distances this box bound does not cover. */
static int sub_count(const reference *R)
{
    if (R->aniso) return 0;
    float s = R->g->cell / (2.0f * R->f.r);
    return s < 1.5f ? 1 : (s < 3.0f ? 2 : 4);
}

/* Nearest and farthest squared distances from p to the box [b0, b0 + e]^3. */
static void box_dist2(const float p[3], const float b0[3], float e, float *near2, float *far2)
{
    float n2 = 0, f2 = 0;
    for (int a = 0; a < 3; a++) {
        float u = p[a] - b0[a], v = b0[a] + e - p[a];
        float dn = u < 0 ? -u : (v < 0 ? -v : 0), df = u > v ? u : v;
        n2 += dn * dn;
        f2 += df * df;
    }
    *near2 = n2;
    *far2 = f2;
}

/* Cubic spline W / (8 / (pi H^3)) at q = d / H, without branches (vectorises). */
static inline float cubic_shape(float q)
{
    float t = q < 1.0f ? 1.0f - q : 0.0f;
    return q <= 0.5f ? (6.0f * q - 6.0f) * q * q + 1.0f : 2.0f * t * t * t;
}

/* Adds particle p to the sums of the sub-cells with corners b[0..2][q], edge e:
 * the cubic spline in a vectorised loop, other kernels one by one. */
static void add_bounds(const fs_field *f, const float p[3], float b[3][64], int nsub, float e, float *up, float *dn)
{
    float H = f->H, H2 = H * H, inv_h = 1.0f / H, cs = (float)(8.0 / FS_PI) / (H * H * H);
    int cubic = f->kernel == FS_KERNEL_CUBIC;
#pragma omp simd
    for (int q = 0; q < nsub; q++) {
        float n2 = 0, f2 = 0;
        for (int a = 0; a < 3; a++) {
            float u = p[a] - b[a][q], v = b[a][q] + e - p[a];
            float dn_a = u < 0 ? -u : (v < 0 ? -v : 0.0f), df_a = u > v ? u : v;
            n2 += dn_a * dn_a;
            f2 += df_a * df_a;
        }
        if (cubic) {
            up[q] += n2 < H2 ? cs * cubic_shape(sqrtf(n2) * inv_h) : 0.0f;
            dn[q] += f2 < H2 ? cs * cubic_shape(sqrtf(f2) * inv_h) : 0.0f;
        } else {
            if (n2 < H2) up[q] += fs_kernel_w(f->kernel, sqrtf(n2), H);
            if (f2 < H2) dn[q] += fs_kernel_w(f->kernel, sqrtf(f2), H);
        }
    }
}

/* Bounds of the sub-cells of cell c, slot `slot`; returns the particle-box
 * distances it computed (work counters: one per particle for the cell, one
 * per sub-cell for each particle that reaches it). */
static uint64_t cell_bounds(const reference *R, const int c[3], uint32_t slot, float *up, float *dn)
{
    uint64_t visits = 0;
    const fs_grid *g = R->g;
    const fs_field *f = &R->f;
    int sub = R->sub, nsub = sub * sub * sub, lo[3], hi[3];
    float e = g->cell / (float)sub, H2 = f->H * f->H, corner[3], b[3][64];
    for (int a = 0; a < 3; a++) {
        lo[a] = c[a] - 1;
        hi[a] = c[a] + 1;
        corner[a] = g->origin[a] + g->cell * (float)c[a];
    }
    for (int q = 0; q < nsub; q++) {
        b[0][q] = corner[0] + e * (float)(q % sub);
        b[1][q] = corner[1] + e * (float)(q / sub % sub);
        b[2][q] = corner[2] + e * (float)(q / (sub * sub));
    }
    memset(up, 0, (size_t)nsub * sizeof *up);
    memset(dn, 0, (size_t)nsub * sizeof *dn);
    uint32_t runs[FS_GRID_MAX_RUNS][2];
    int nr = fs_grid_box_runs(g, lo, hi, runs);
    for (int r = 0; r < nr; r++)
        for (uint32_t s = runs[r][0]; s < runs[r][1]; s++) {
            float p[3] = {R->sx[s], R->sy[s], R->sz[s]}, n2, f2;
            box_dist2(p, corner, g->cell, &n2, &f2);
            visits++;
            if (n2 < H2) {
                add_bounds(f, p, b, nsub, e, up, dn);
                visits += (uint64_t)nsub;
            } /* else it cannot reach the cell */
        }
    float q = f->iso / FS_REF_Q;
    size_t base = (size_t)slot * (size_t)nsub;
    for (int k = 0; k < nsub; k++) {
        float u = ceilf(up[k] * f->volume / q + 0.01f), l = floorf(dn[k] * f->volume / q - 0.01f);
        R->hi[base + k] = (uint8_t)(u > 255 ? 255 : (u < 0 ? 0 : u));
        R->lo[base + k] = (uint8_t)(l > 255 ? 255 : (l < 0 ? 0 : l));
    }
    return visits;
}

/* The class of cell slot from its sub-cells' bounds (reference.h, FS_REF_EDGE_IN). */
static uint8_t cell_class(const reference *R, size_t slot)
{
    size_t nsub = (size_t)R->sub * R->sub * R->sub;
    int in = 1, out = 1, may_in = 0;
    for (size_t q = slot * nsub; q < (slot + 1) * nsub; q++) {
        in &= R->lo[q] >= FS_REF_Q;
        out &= R->hi[q] < FS_REF_Q;
        may_in |= R->hi[q] >= FS_REF_Q && R->lo[q] < FS_REF_Q;
    }
    return (uint8_t)(in ? FS_REF_IN : out ? FS_REF_OUT : may_in ? FS_REF_EDGE_IN : FS_REF_EDGE);
}

/* Cell c's bounds and class, their work counted in w (one bound of phi, upper and
 * lower in one pass, per sub-cell). */
static uint8_t make_cell(const reference *R, const int c[3], uint32_t slot, ray_work *w)
{
    float up[64], dn[64];
    w->nbrs += cell_bounds(R, c, slot, up, dn);
    w->evals += (uint64_t)R->sub * R->sub * R->sub;
    return cell_class(R, slot);
}

int fs_ref_cell_ready(const reference *R, const int c[3], uint32_t slot, ray_work *w)
{
    uint8_t *st = R->cell_cls + slot;
    uint8_t s = __atomic_load_n(st, __ATOMIC_ACQUIRE), none = FS_REF_CELL_NONE;
    if (s < FS_REF_CELL_CLAIMED) return s;
    if (s == FS_REF_CELL_NONE &&
        __atomic_compare_exchange_n(st, &none, FS_REF_CELL_CLAIMED, 0, __ATOMIC_ACQUIRE, __ATOMIC_ACQUIRE)) {
        s = make_cell(R, c, slot, w);
        __atomic_store_n(st, s, __ATOMIC_RELEASE); /* the bounds are written before the class says so */
        return s;
    }
    w->waits++; /* another thread is making them: the same bounds, so wait for them */
    while ((s = __atomic_load_n(st, __ATOMIC_ACQUIRE)) >= FS_REF_CELL_CLAIMED) sched_yield();
    return s;
}

/* Every near cell's bounds, in parallel over blocks, counted in the current stage. */
static void make_all(reference *R)
{
    const fs_grid *g = R->g;
    long nb = (long)g->nblocks;
    uint64_t evals = 0, nbrs = 0;
#pragma omp parallel reduction(+ : evals, nbrs)
    {
        ray_work w = {0};
#pragma omp for schedule(dynamic, 4)
        for (long b = 0; b < nb; b++)
            for (int l = 0; l < FS_GRID_B3; l++) {
                uint32_t slot = (uint32_t)b * FS_GRID_B3 + (uint32_t)l;
                if (!R->count27[slot]) continue;
                int c[3] = {g->bkey[3 * b] * FS_GRID_B + l % FS_GRID_B,
                            g->bkey[3 * b + 1] * FS_GRID_B + l / FS_GRID_B % FS_GRID_B,
                            g->bkey[3 * b + 2] * FS_GRID_B + l / (FS_GRID_B * FS_GRID_B)};
                R->cell_cls[slot] = make_cell(R, c, slot, &w);
            }
        evals += w.evals;
        nbrs += w.nbrs;
    }
    fs_count_add(FS_CNT_FIELD_EVALS, evals);
    fs_count_add(FS_CNT_NEIGHBOURS, nbrs);
}

int fs_ref_bounds_build(reference *R, int demand)
{
    fs_ref_bounds_free(R);
    const fs_grid *g = R->g;
    R->sub = sub_count(R);
    if (!R->sub) return FS_OK;
    size_t nsub = (size_t)R->sub * R->sub * R->sub, total = g->ncells * nsub;
    R->lo = malloc(total ? total : 1); /* a cell's are written when its bounds are made */
    R->hi = malloc(total ? total : 1);
    R->cell_cls = malloc(g->ncells ? g->ncells : 1);
    if (!R->lo || !R->hi || !R->cell_cls) {
        fs_ref_bounds_free(R);
        return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %zu sub-cell bounds", total);
    }
    /* cells no particle sees are outside; the others' bounds are made now or on demand */
    for (size_t c = 0; c < g->ncells; c++) R->cell_cls[c] = R->count27[c] ? FS_REF_CELL_NONE : FS_REF_OUT;
    if (!demand) make_all(R);
    return FS_OK;
}
