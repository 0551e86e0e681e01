/* The field sampler (mesh_sample.h). The leaves of one slab are filled in
 * parallel, each by its own thread, so no sum is shared. For one leaf, every particle whose
 * support reaches the leaf's box is splatted: its support is the ellipsoid
 * d^T M d < H^2 (M = A^-T A^-1; the identity when isotropic), added row by
 * row along z over the rows that it meets, each row of 8 voxels one vector
 * loop. */
#include "mesh_sample.h"
#include "fs_error.h"
#include "kernel_shapes.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One particle's kernel: centre, metric M (row-major, symmetric) and its
 * bounding half-extents. */
typedef struct splat {
    float c[3], M[9], e[3];
} splat;

static void splat_of(splat *s, const float *pos, const float *inv, float H)
{
    for (int a = 0; a < 3; a++) s->c[a] = pos[a];
    if (!inv) {
        memset(s->M, 0, sizeof s->M);
        s->M[0] = s->M[4] = s->M[8] = 1;
        s->e[0] = s->e[1] = s->e[2] = H;
        return;
    }
    for (int r = 0; r < 3; r++) /* inv is symmetric: M = inv inv */
        for (int q = 0; q < 3; q++)
            s->M[3 * r + q] = inv[3 * r] * inv[q] + inv[3 * r + 1] * inv[3 + q] + inv[3 * r + 2] * inv[6 + q];
    /* half-extent along a: H sqrt((M^-1)_aa), from the cofactors of M */
    const float *M = s->M;
    float c0 = M[4] * M[8] - M[5] * M[7], c1 = M[0] * M[8] - M[2] * M[6], c2 = M[0] * M[4] - M[1] * M[3];
    float det = M[0] * c0 - M[1] * (M[3] * M[8] - M[5] * M[6]) + M[2] * (M[3] * M[7] - M[4] * M[6]);
    float cof[3] = {c0, c1, c2};
    for (int a = 0; a < 3; a++) s->e[a] = H * sqrtf(fmaxf(cof[a] / det, 0.0f)) * 1.0001f;
}

/* row[0..8) += w shape(sqrt(c + dz (2 b + m22 dz)) / H), dz = z0 + cube k: a
 * whole leaf row in one vector loop (voxels outside the support add 0, the
 * shapes being 0 for q >= 1), cheaper than finding the row's ends. */
#define FS_MESH_ROW(SHAPE)                                                                                             \
    _Pragma("omp simd") for (int k = 0; k < FS_MESH_LEAF; k++)                                                         \
    {                                                                                                                  \
        float dz = z0 + cube * (float)k, q = fs_maxf(c + dz * (2 * b + m22 * dz), 0.0f);                               \
        row[k] += w * SHAPE(sqrtf(q) * inv_h);                                                                         \
    }

static inline __attribute__((always_inline)) void add_row(float *restrict row, float z0, float cube, float c, float b,
                                                          float m22, float w, float inv_h, fs_kernel k)
{
    switch (k) {
    case FS_KERNEL_POLY6: FS_MESH_ROW(fs_shape_poly6) break;
    case FS_KERNEL_SPIKY: FS_MESH_ROW(fs_shape_spiky) break;
    case FS_KERNEL_WYVILL: FS_MESH_ROW(fs_shape_wyvill) break;
    default: FS_MESH_ROW(fs_shape_cubic) break;
    }
}

/* Adds splat s onto leaf buf (origin o, voxel size cube; wc: the kernel's
 * constant times V / det A): every row of the leaf that the support meets.
 * Returns the terms added (voxels of those rows). */
static inline __attribute__((always_inline)) uint64_t add_splat(float *buf, const int o[3], float cube, const splat *s,
                                                                const fs_field *f, float wc)
{
    int lo[2], hi[2];
    for (int a = 0; a < 3; a++) {
        int l = (int)ceilf((s->c[a] - s->e[a]) / cube) - o[a], h = (int)floorf((s->c[a] + s->e[a]) / cube) - o[a];
        if (l < 0) l = 0;
        if (h > FS_MESH_LEAF - 1) h = FS_MESH_LEAF - 1;
        if (l > h) return 0;
        if (a < 2) lo[a] = l, hi[a] = h;
    }
    const float *M = s->M, H = f->H, H2 = H * H, z0 = (float)o[2] * cube - s->c[2];
    uint64_t terms = 0;
    for (int i = lo[0]; i <= hi[0]; i++) {
        float dx = (float)(o[0] + i) * cube - s->c[0];
        for (int j = lo[1]; j <= hi[1]; j++) {
            float dy = (float)(o[1] + j) * cube - s->c[1];
            /* d^T M d = c + 2 b dz + M22 dz^2; its minimum over dz is c - b^2 / M22 */
            float b = M[2] * dx + M[5] * dy, c = M[0] * dx * dx + 2 * M[1] * dx * dy + M[4] * dy * dy;
            if (c - b * b / M[8] >= H2) continue;
            add_row(buf + (i * FS_MESH_LEAF + j) * FS_MESH_LEAF, z0, cube, c, b, M[8], wc, 1.0f / H, f->kernel);
            terms += FS_MESH_LEAF;
        }
    }
    return terms;
}

/* Fills one leaf: every particle of the cells that the leaf's box grown by
 * reach touches. One build for AVX2 machines, one for any x86-64. */
#if defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx2", "default")))
#endif
static uint64_t
fill_leaf(float *buf, const int o[3], float cube, const fs_field *f, const fs_grid *g, const fs_aniso_kernels *ak)
{
    float reach = ak ? ak->reach : f->H; /* buf starts at 0: fs_mesh_volume_slab's zeros */
    int c0[3], c1[3];
    for (int a = 0; a < 3; a++) {
        c0[a] = fs_grid_coord(g, a, (float)o[a] * cube - reach);
        c1[a] = fs_grid_coord(g, a, (float)(o[a] + FS_MESH_LEAF - 1) * cube + reach);
    }
    uint64_t terms = 0;
    float wc = fs_kernel_shape_c(f) * f->volume;
    splat s;
    fs_grid_box b;
    fs_grid_box_begin(&b, g, c0, c1);
    for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);)
        for (uint32_t sl = s0; sl < s1; sl++) {
            splat_of(&s, g->pos4 + 4 * (size_t)sl, ak ? ak->inv + 9 * (size_t)sl : NULL, f->H);
            terms += add_splat(buf, o, cube, &s, f, wc * (ak ? ak->wscale[sl] : 1.0f));
        }
    return terms;
}

int fs_mesh_sample(fs_mesh_volume *v, double cube, const fs_field *f, const fs_grid *g, const fs_aniso_kernels *ak,
                   fs_mesh_work *w)
{
    if (ak) g = &ak->grid;
    uint64_t terms = 0;
    size_t slabs = fs_mesh_volume_slabs(v);
    for (size_t s = 0; s < slabs; s++) {
        size_t n;
        const int *org;
        float *buf = fs_mesh_volume_slab(v, s, &n, &org);
        if (!buf) return fs_error_code(); /* fs_fail set: over the memory limit, or out of memory */
        long nl = (long)n;
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : terms)
        for (long i = 0; i < nl; i++)
            terms += fill_leaf(buf + (size_t)i * FS_MESH_LEAF3, org + 3 * i, (float)cube, f, g, ak);
        int rc = fs_mesh_volume_slab_done(v, s);
        if (rc) return rc;
    }
    w->voxels += (uint64_t)fs_mesh_volume_leaves(v) * FS_MESH_LEAF3;
    w->terms += terms;
    return FS_OK;
}

/* field=zhu_bridson: one leaf's voxels get R - phi (phi of zhu_bridson.h), or 0
 * where no particle lies within R, so that values above iso = R are inside and
 * the volume's background (0) is outside. The leaf's candidates (the particles
 * within R of its box) are gathered once. Returns the terms summed. */
static uint64_t fill_leaf_zb(float *buf, const int o[3], float cube, double R, double r, const fs_grid *g, float **cand,
                             size_t *cap)
{
    int c0[3], c1[3];
    float lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = (float)o[a] * cube, hi[a] = (float)(o[a] + FS_MESH_LEAF - 1) * cube;
        c0[a] = fs_grid_coord(g, a, lo[a] - (float)R);
        c1[a] = fs_grid_coord(g, a, hi[a] + (float)R);
    }
    size_t n = 0;
    fs_grid_box b;
    fs_grid_box_begin(&b, g, c0, c1);
    for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);)
        for (uint32_t sl = s0; sl < s1; sl++) {
            const float *p = g->pos4 + 4 * (size_t)sl;
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                double e = p[a] < lo[a] ? lo[a] - p[a] : (p[a] > hi[a] ? p[a] - hi[a] : 0);
                d2 += e * e;
            }
            if (d2 >= R * R) continue;
            if (n == *cap) {
                size_t nc = *cap ? 2 * *cap : 1024;
                float *q = realloc(*cand, nc * 3 * sizeof *q);
                if (!q) return UINT64_MAX;
                *cand = q, *cap = nc;
            }
            for (int a = 0; a < 3; a++) (*cand)[3 * n + a] = p[a];
            n++;
        }
    uint64_t terms = 0;
    double inv_r2 = 1 / (R * R);
    for (int x = 0; x < FS_MESH_LEAF; x++)
        for (int y = 0; y < FS_MESH_LEAF; y++)
            for (int z = 0; z < FS_MESH_LEAF; z++) {
                double v[3] = {(double)(o[0] + x) * cube, (double)(o[1] + y) * cube, (double)(o[2] + z) * cube};
                fs_zb_sum s;
                memset(&s, 0, sizeof s);
                for (size_t i = 0; i < n; i++)
                    fs_zb_add(&s, (*cand)[3 * i] - v[0], (*cand)[3 * i + 1] - v[1], (*cand)[3 * i + 2] - v[2], inv_r2,
                              0);
                buf[(x * FS_MESH_LEAF + y) * FS_MESH_LEAF + z] =
                    s.K > 0 ? (float)(R - fs_zb_phi(&s, R, r, NULL)) : 0.0f;
                terms += s.terms;
            }
    return terms;
}

int fs_mesh_sample_zb(fs_mesh_volume *v, double cube, double R, double r, const fs_grid *g, fs_mesh_work *w)
{
    uint64_t terms = 0;
    int oom = 0;
    size_t slabs = fs_mesh_volume_slabs(v);
    for (size_t s = 0; s < slabs; s++) {
        size_t n;
        const int *org;
        float *buf = fs_mesh_volume_slab(v, s, &n, &org);
        if (!buf) return fs_error_code();
        long nl = (long)n;
#pragma omp parallel reduction(+ : terms) reduction(| : oom)
        {
            float *cand = NULL;
            size_t cap = 0;
#pragma omp for schedule(dynamic, 4)
            for (long i = 0; i < nl; i++) {
                uint64_t t = oom
                    ? 0
                    : fill_leaf_zb(buf + (size_t)i * FS_MESH_LEAF3, org + 3 * i, (float)cube, R, r, g, &cand, &cap);
                if (t == UINT64_MAX) oom = 1;
                else terms += t;
            }
            free(cand);
        }
        if (oom) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the zhu_bridson candidates");
        int rc = fs_mesh_volume_slab_done(v, s);
        if (rc) return rc;
    }
    w->voxels += (uint64_t)fs_mesh_volume_leaves(v) * FS_MESH_LEAF3;
    w->terms += terms;
    return FS_OK;
}
