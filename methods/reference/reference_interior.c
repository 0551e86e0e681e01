/* Fine interior bounds of phi for the accelerated reference (README.md,
 * "Interior sub-cells"). The monotone-kernel bound of reference_bounds.c
 * cannot prove the inside of the fluid: it takes every particle at its
 * farthest point of the box, and those worst cases do not cancel (in a
 * lattice liquid phi ~ 1, its lower bound over a 2r box is ~0.04 and over an
 * r/2 box still ~0.56 < iso 0.6). A second-order Taylor bound keeps the
 * cancellation of the sums: about the centre c of a box with half-diagonal hd,
 *   phi(x) >= phi(c) - |grad phi(c)|_1 e/2 - M hd^2 / 2,
 * where M = sum_j V max over the box of the Hessian norm of particle j's
 * kernel, max(|W''|, |W'/d|), bounded above by 12 s (1 - d_min/H) / H^2 for
 * the cubic spline (s = 8/(pi H^3)). Only the curvature term is summed
 * without cancellation, and it shrinks as e^2: with e = H/8 = r/2 the bound
 * over the liquid is ~0.7. Each near cell gets FS_REF_FINE^3 such boxes, one
 * bit each (phi >= iso proven), built by gathering, with the inner loop over a
 * row of FS_REF_FINE boxes vectorised. A cell's proof is made once: up front
 * for every cell (interior=on, in parallel over blocks), or on demand by the
 * first ray that enters the cell inside the fluid (a claim per cell; a ray that
 * finds it claimed waits for it). Only the cubic spline (the default kernel)
 * has this level; for the others the accelerated path keeps the monotone
 * bounds only. */
#include "counters.h"
#include "fs_error.h"
#include "reference.h"
#include <math.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>

void fs_ref_interior_free(reference *R)
{
    free(R->fine);
    free(R->fine_state);
    R->fine = R->fine_state = NULL;
}

/* Candidate particles of one cell, relative to its corner (capacity cap). */
typedef struct fine_cand {
    float *x, *y, *z;
    int n, cap;
} fine_cand;

/* Constants of the bound: phi = kw sum shape, grad = kg sum wd (x - p), M = km sum (1 - d_near/H). */
typedef struct fine_k {
    float e, hd, H, kw, kg, km, iso;
} fine_k;

/* Proves the FS_REF_FINE boxes of the row at (y, z) inside or not, over the
 * candidates c; the sums of a row stay in registers. Sets bits of row `row`. */
#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx2", "default"))) /* one AVX2 vector a row */
#endif
static uint64_t
row_bits(const fine_cand *c, float y, float z, const fine_k *K, uint8_t *bits, int row)
{
    uint64_t reach = 0; /* candidates within reach of the row: FS_REF_FINE distances each */
    float ph[FS_REF_FINE] = {0}, gx[FS_REF_FINE] = {0}, gy[FS_REF_FINE] = {0}, gz[FS_REF_FINE] = {0};
    float m[FS_REF_FINE] = {0}, reach2 = (K->H + K->hd) * (K->H + K->hd), inv_h = 1.0f / K->H, e = K->e, hd = K->hd;
    for (int j = 0; j < c->n; j++) {
        float dy = y - c->y[j], dz = z - c->z[j], r2 = dy * dy + dz * dz, px = c->x[j];
        if (r2 >= reach2) continue;
        reach++;
#pragma omp simd
        for (int i = 0; i < FS_REF_FINE; i++) {
            float dx = ((float)i + 0.5f) * e - px, d = sqrtf(dx * dx + r2), q = d * inv_h;
            float t = fs_maxf(1.0f - q, 0.0f), near = fs_maxf(d - hd, 0.0f), inv_q = 1.0f / fs_maxf(q, 0.5f);
            float w_in = (6.0f * q - 6.0f) * q * q + 1.0f, w_out = 2.0f * t * t * t;
            /* W'/d in units of s / H^2: 18 q - 12 inside, -6 t^2 / q outside, 0 beyond the support
             * (both branches computed: a division inside a condition keeps the loop scalar) */
            float wd_in = 18.0f * q - 12.0f, wd_out = -6.0f * t * t * inv_q;
            float w = q <= 0.5f ? w_in : w_out, wd = q <= 0.5f ? wd_in : wd_out;
            ph[i] += w;
            gx[i] += wd * dx;
            gy[i] += wd * dy;
            gz[i] += wd * dz;
            m[i] += fs_maxf(1.0f - near * inv_h, 0.0f);
        }
    }
    for (int i = 0; i < FS_REF_FINE; i++) {
        float grad1 = K->kg * (fabsf(gx[i]) + fabsf(gy[i]) + fabsf(gz[i]));
        float lower = K->kw * ph[i] - grad1 * 0.5f * e - 0.5f * K->km * m[i] * hd * hd;
        int k = row * FS_REF_FINE + i;
        if (lower >= K->iso * 1.001f + 1e-4f) bits[k >> 3] |= (uint8_t)(1u << (k & 7)); /* margin over float error */
    }
    return (uint64_t)c->n + reach * FS_REF_FINE;
}

/* The interior bits of cell c into bits (FS_REF_FINE3 / 8 bytes); all and
 * slab are candidate buffers of R->max27 entries. Returns the particle
 * distances it computed (work counters). */
static uint64_t cell_interior(const reference *R, const int c[3], fine_cand *all, fine_cand *slab, uint8_t *bits)
{
    const fs_grid *g = R->g;
    const fs_field *f = &R->f;
    double s = 8.0 / FS_PI / ((double)f->H * f->H * f->H), H2 = (double)f->H * f->H;
    fine_k K = {g->cell / FS_REF_FINE,
                0,
                f->H,
                (float)(f->volume * s),
                (float)(f->volume * s / H2),
                (float)(f->volume * 12.0 * s / H2),
                f->iso};
    K.hd = 0.5f * K.e * sqrtf(3.0f);
    float corner[3], reach = K.H + K.hd;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = c[a] - 1;
        hi[a] = c[a] + 1;
        corner[a] = g->origin[a] + g->cell * (float)c[a];
    }
    uint32_t runs[FS_GRID_MAX_RUNS][2];
    int nr = fs_grid_box_runs(g, lo, hi, runs);
    all->n = 0;
    for (int r = 0; r < nr; r++)
        for (uint32_t q = runs[r][0]; q < runs[r][1] && all->n < all->cap; q++) {
            all->x[all->n] = R->sx[q] - corner[0];
            all->y[all->n] = R->sy[q] - corner[1];
            all->z[all->n] = R->sz[q] - corner[2];
            all->n++;
        }
    memset(bits, 0, FS_REF_FINE3 / 8);
    uint64_t visits = (uint64_t)all->n * (1 + FS_REF_FINE); /* gathered, then tested per slab */
    for (int k = 0; k < FS_REF_FINE; k++) {
        float z = ((float)k + 0.5f) * K.e;
        slab->n = 0;
        for (int j = 0; j < all->n; j++)
            if (fabsf(all->z[j] - z) < reach) {
                slab->x[slab->n] = all->x[j];
                slab->y[slab->n] = all->y[j];
                slab->z[slab->n] = all->z[j];
                slab->n++;
            }
        for (int j = 0; j < FS_REF_FINE; j++)
            visits += row_bits(slab, ((float)j + 0.5f) * K.e, z, &K, bits, k * FS_REF_FINE + j);
    }
    return visits;
}

/* Two candidate buffers of R->max27 entries over one scratch of fs_ref_proof_buf_size bytes. */
static void cand_bind(fine_cand *all, fine_cand *slab, void *buf, const reference *R)
{
    size_t cap = R->max27 ? R->max27 : 1;
    float *f = buf;
    *all = (fine_cand){f, f + cap, f + 2 * cap, 0, (int)cap};
    *slab = (fine_cand){f + 3 * cap, f + 4 * cap, f + 5 * cap, 0, (int)cap};
}

size_t fs_ref_proof_buf_size(const reference *R) { return 6 * (size_t)(R->max27 ? R->max27 : 1) * sizeof(float); }

/* Whether every coarse sub-cell of the cell is inside: by its own lower bound,
 * or because its fine sub-cells all are (then the cell is crossed whole). */
static int all_inside(const reference *R, uint32_t slot, const uint8_t *bits)
{
    int sub = R->sub, f = FS_REF_FINE / sub;
    size_t base = (size_t)slot * sub * sub * sub;
    for (int q = 0; q < sub * sub * sub; q++) {
        if (R->lo[base + q] >= FS_REF_Q) continue;
        int ci = q % sub, cj = q / sub % sub, ck = q / (sub * sub);
        for (int z = ck * f; z < ck * f + f; z++)
            for (int y = cj * f; y < cj * f + f; y++)
                for (int x = ci * f; x < ci * f + f; x++) {
                    int k = (z * FS_REF_FINE + y) * FS_REF_FINE + x;
                    if (!(bits[k >> 3] >> (k & 7) & 1)) return 0;
                }
    }
    return 1;
}

/* Makes cell c's proof (its entry's bits), counted in w; returns its state. */
static int prove(const reference *R, const int c[3], uint32_t slot, void *buf, ray_work *w)
{
    fine_cand all, slab;
    cand_bind(&all, &slab, buf, R);
    uint8_t *bits = R->fine + (size_t)slot * (FS_REF_FINE3 / 8);
    w->nbrs += cell_interior(R, c, &all, &slab, bits);
    w->evals += FS_REF_FINE3; /* one second-order bound (value, gradient, curvature at the centre) per fine box */
    return all_inside(R, slot, bits) ? FS_REF_PROOF_ALL_IN : FS_REF_PROOF_BITS;
}

int fs_ref_proof_ready(const reference *R, const int c[3], uint32_t slot, void *buf, ray_work *w)
{
    uint8_t *st = R->fine_state + slot;
    uint8_t s = __atomic_load_n(st, __ATOMIC_ACQUIRE), none = FS_REF_PROOF_NONE;
    if (s >= FS_REF_PROOF_BITS) return s;
    if (s == FS_REF_PROOF_NONE &&
        __atomic_compare_exchange_n(st, &none, FS_REF_PROOF_CLAIMED, 0, __ATOMIC_ACQUIRE, __ATOMIC_ACQUIRE)) {
        s = (uint8_t)prove(R, c, slot, buf, w);
        __atomic_store_n(st, s, __ATOMIC_RELEASE); /* the bits are written before the state says so */
        return s;
    }
    w->waits++; /* another thread is making it: its result is the same, so wait for it */
    while ((s = __atomic_load_n(st, __ATOMIC_ACQUIRE)) < FS_REF_PROOF_BITS) sched_yield();
    return s;
}

/* interior=on: every FS_REF_EDGE_IN cell's proof, in parallel over blocks (its bounds made). */
static int prove_all(reference *R)
{
    const fs_grid *g = R->g;
    long nb = (long)g->nblocks;
    ray_work total = {0};
    int failed = 0;
#pragma omp parallel
    {
        ray_work w = {0};
        void *buf = malloc(fs_ref_proof_buf_size(R));
#pragma omp for schedule(dynamic, 2)
        for (long b = 0; b < nb; b++)
            for (int l = 0; buf && l < FS_GRID_B3; l++) {
                uint32_t slot = (uint32_t)b * FS_GRID_B3 + (uint32_t)l;
                if (R->cell_cls[slot] != FS_REF_EDGE_IN) continue;
                int c[3] = {g->bkey[3 * b] * FS_GRID_B + l % FS_GRID_B,
                            g->bkey[3 * b + 1] * FS_GRID_B + l / FS_GRID_B % FS_GRID_B,
                            g->bkey[3 * b + 2] * FS_GRID_B + l / (FS_GRID_B * FS_GRID_B)};
                R->fine_state[slot] = (uint8_t)prove(R, c, slot, buf, &w);
            }
#pragma omp critical(fs_reference_interior)
        {
            failed |= !buf;
            fs_ref_work_add(&total, &w);
        }
        free(buf);
    }
    if (failed) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for the interior proofs' scratch");
    fs_count_add(FS_CNT_FIELD_EVALS, total.evals);
    fs_count_add(FS_CNT_NEIGHBOURS, total.nbrs);
    return FS_OK;
}

int fs_ref_interior_build(reference *R, int demand)
{
    fs_ref_interior_free(R);
    const fs_grid *g = R->g;
    if (R->aniso || R->f.kernel != FS_KERNEL_CUBIC || !R->sub || !R->thickness)
        return FS_OK; /* only thickness walks the inside */
    size_t n = g->ncells ? g->ncells : 1;
    R->fine = malloc(n * (FS_REF_FINE3 / 8)); /* a block's cells fill a page: pages no proof writes stay unmapped */
    R->fine_state = calloc(n, 1);
    if (!R->fine || !R->fine_state) {
        fs_ref_interior_free(R);
        return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for the interior proofs of %zu cells", n);
    }
    int rc = demand ? FS_OK : prove_all(R);
    if (rc) fs_ref_interior_free(R);
    return rc;
}
