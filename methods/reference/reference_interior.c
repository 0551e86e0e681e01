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
 * bit each (phi >= iso proven), built by gathering, in parallel over blocks,
 * with the inner loop over a row of FS_REF_FINE boxes vectorised. Only the
 * cubic spline (the default kernel) has this level; for the others the
 * accelerated path keeps the monotone bounds only. */
#include "fs_error.h"
#include "reference.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void fs_ref_interior_free(reference *R)
{
    free(R->fine_off);
    free(R->fine);
    R->fine_off = NULL;
    R->fine = NULL;
    R->nfine = 0;
}

typedef struct fine_acc {
    float phi[FS_REF_FINE3], gx[FS_REF_FINE3], gy[FS_REF_FINE3], gz[FS_REF_FINE3], m[FS_REF_FINE3];
} fine_acc;

/* Adds one particle at p (relative to the cell's corner) to the boxes within reach. */
static void add_particle(fine_acc *A, const float p[3], float e, float H, float hd)
{
    float reach = H + hd, inv_h = 1.0f / H;
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) { /* boxes whose centre (i + 0.5) e lies within reach of p */
        lo[a] = (int)ceilf((p[a] - reach) / e - 0.5f);
        hi[a] = (int)floorf((p[a] + reach) / e - 0.5f);
        lo[a] = lo[a] < 0 ? 0 : lo[a];
        hi[a] = hi[a] > FS_REF_FINE - 1 ? FS_REF_FINE - 1 : hi[a];
    }
    for (int k = lo[2]; k <= hi[2]; k++)
        for (int j = lo[1]; j <= hi[1]; j++) {
            float dy = ((float)j + 0.5f) * e - p[1], dz = ((float)k + 0.5f) * e - p[2], r2 = dy * dy + dz * dz;
            if (r2 >= reach * reach) continue;
            int row = (k * FS_REF_FINE + j) * FS_REF_FINE;
            float *phi = A->phi + row, *gx = A->gx + row, *gy = A->gy + row, *gz = A->gz + row, *m = A->m + row;
#pragma omp simd
            for (int i = 0; i < FS_REF_FINE; i++) {
                float dx = ((float)i + 0.5f) * e - p[0], d = sqrtf(dx * dx + r2), q = d * inv_h;
                float t = fmaxf(1.0f - q, 0.0f);
                float w = q <= 0.5f ? (6.0f * q - 6.0f) * q * q + 1.0f : 2.0f * t * t * t;
                /* W'/d / (s / H^2): 18 q - 12 inside, -6 t^2 / q outside (0 beyond the support) */
                float wd = q <= 0.5f ? 18.0f * q - 12.0f : -6.0f * t * t / fmaxf(q, 0.5f);
                phi[i] += w;
                gx[i] += wd * dx;
                gy[i] += wd * dy;
                gz[i] += wd * dz;
                m[i] += fmaxf(1.0f - fmaxf(d - hd, 0.0f) * inv_h, 0.0f);
            }
        }
}

/* The interior bits of the cell c (slot) into bits (FS_REF_FINE3 / 8 bytes). */
static void cell_interior(const reference *R, const int c[3], fine_acc *A, uint8_t *bits)
{
    const fs_grid *g = R->g;
    const fs_field *f = &R->f;
    float e = g->cell / FS_REF_FINE, hd = 0.5f * e * sqrtf(3.0f), H = f->H, corner[3];
    int lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = c[a] - 1;
        hi[a] = c[a] + 1;
        corner[a] = g->origin[a] + g->cell * (float)c[a];
    }
    memset(A, 0, sizeof *A);
    uint32_t runs[FS_REF_MAX_RUNS][2];
    int nr = fs_ref_runs(g, lo, hi, runs);
    for (int r = 0; r < nr; r++)
        for (uint32_t s = runs[r][0]; s < runs[r][1]; s++) {
            float p[3] = {R->sx[s] - corner[0], R->sy[s] - corner[1], R->sz[s] - corner[2]};
            add_particle(A, p, e, H, hd);
        }
    double s = 8.0 / FS_PI / ((double)H * H * H), V = f->volume;
    float cw = (float)(V * s), cg = (float)(V * s / ((double)H * H)), cm = (float)(V * 12.0 * s / ((double)H * H));
    memset(bits, 0, FS_REF_FINE3 / 8);
    for (int k = 0; k < FS_REF_FINE3; k++) {
        float grad1 = cg * (fabsf(A->gx[k]) + fabsf(A->gy[k]) + fabsf(A->gz[k]));
        float lower = cw * A->phi[k] - grad1 * 0.5f * e - 0.5f * cm * A->m[k] * hd * hd;
        if (lower >= f->iso * 1.001f + 1e-4f) bits[k >> 3] |= (uint8_t)(1u << (k & 7)); /* margin over float error */
    }
}

/* Cells worth the fine level: some coarse sub-cell of theirs may be inside. */
static int wants_fine(const reference *R, uint32_t slot)
{
    if (!R->count27[slot]) return 0;
    size_t n = (size_t)R->sub * R->sub * R->sub, base = (size_t)slot * n;
    for (size_t k = 0; k < n; k++)
        if (R->hi[base + k] >= FS_REF_Q && R->lo[base + k] < FS_REF_Q) return 1;
    return 0;
}

int fs_ref_interior_build(reference *R)
{
    fs_ref_interior_free(R);
    const fs_grid *g = R->g;
    if (R->aniso || R->f.kernel != FS_KERNEL_CUBIC || !R->sub) return FS_OK;
    R->fine_off = malloc((g->ncells ? g->ncells : 1) * sizeof *R->fine_off);
    if (!R->fine_off) return fs_fail(FS_ERR_RUNTIME, "reference: out of memory for %zu cells", g->ncells);
    size_t n = 0;
    for (size_t c = 0; c < g->ncells; c++) R->fine_off[c] = wants_fine(R, (uint32_t)c) ? (uint32_t)n++ : FS_GRID_NONE;
    R->nfine = n;
    R->fine = malloc((n ? n : 1) * (FS_REF_FINE3 / 8));
    if (!R->fine) { fs_ref_interior_free(R); return fs_fail(FS_ERR_RUNTIME, "reference: out of memory"); }
    long nb = (long)g->nblocks;
#pragma omp parallel
    {
        fine_acc *A = malloc(sizeof *A);
#pragma omp for schedule(dynamic, 2)
        for (long b = 0; b < nb; b++)
            for (int l = 0; l < FS_GRID_B3 && A; l++) {
                uint32_t slot = (uint32_t)b * FS_GRID_B3 + (uint32_t)l, off = R->fine_off[slot];
                if (off == FS_GRID_NONE) continue;
                int c[3] = {g->bkey[3 * b] * FS_GRID_B + l % FS_GRID_B,
                            g->bkey[3 * b + 1] * FS_GRID_B + l / FS_GRID_B % FS_GRID_B,
                            g->bkey[3 * b + 2] * FS_GRID_B + l / (FS_GRID_B * FS_GRID_B)};
                cell_interior(R, c, A, R->fine + (size_t)off * (FS_REF_FINE3 / 8));
            }
        if (!A) memset(R->fine, 0, n * (FS_REF_FINE3 / 8)); /* nothing proven: still exact */
        free(A);
    }
    return FS_OK;
}
