/* Internals of the reference ray caster shared by its files (README.md):
 * reference.c (method entry, upload, render), reference_walk.c (a ray's walk
 * through the sparse grid), reference_plain.c (accel=off: the per-cell march
 * as it always was), reference_fast.c (accel=on) and reference_bounds.c
 * (sub-cell bounds of phi). */
#ifndef FS_REFERENCE_H
#define FS_REFERENCE_H
#include "aniso_kernels.h"
#include "grid.h"
#include "kernel_shapes.h"
#include "kernels.h"
#include <stdint.h>

/* Sub-cell classes of reference_bounds.c: phi < iso on the whole sub-cell,
 * phi >= iso on the whole sub-cell, or neither proven. A whole cell's class
 * (R->cell_cls) is one of these, or FS_REF_EDGE_IN: neither proven, and some
 * coarse sub-cell may be inside (the cells an interior proof can help); or, while
 * its bounds are made on demand, FS_REF_CELL_NONE (not made yet) or
 * FS_REF_CELL_CLAIMED (being made by the thread that claimed it). */
enum { FS_REF_OUT = 0, FS_REF_IN = 1, FS_REF_EDGE = 2, FS_REF_EDGE_IN = 3 };
enum { FS_REF_CELL_CLAIMED = 0xfe, FS_REF_CELL_NONE = 0xff };

typedef struct reference {
    fs_field f;
    float step_min; /* scene units */
    int thickness, max_layers, accel;
    int supersample; /* N x N rays per pixel (1: the pixel centre) */
    int noted_small; /* the note of a radius under FS_REF_SMALL_R_PX was given */
    float centre[3]; /* the centre of the particles' bulk box (the grid's), for that note */
    int interior; /* reference.c's ref_interior (auto, on, off, demand): the fine interior bits (reference_interior.c) */
    int prepared; /* the bounds and interior decisions were taken for the current upload */
    size_t nnear; /* cell slots with a particle in their 27 neighbours */
    const fs_grid *g;
    uint32_t *count27; /* per cell slot: particles in the 27 cells around it */
    uint32_t max27;
    float lip_unit; /* V max|W'|: a cell's Lipschitz bound is lip_unit * count27 */
    int aniso;
    int zb;           /* field=zhu_bridson: reference_zb.c's march of Zhu & Bridson's phi */
    double zb_radius; /* zhu_bridson: the kernel radius R, scene units */
    fs_grid zgrid;    /* zhu_bridson: a grid of cell >= R when the given one's cells are smaller */
    int zgrid_own;
    fs_aniso_params ap;
    float reach;         /* largest distance at which a particle's kernel is nonzero: H (times the largest axis) */
    fs_aniso_kernels ak; /* anisotropic: the kernels, on a grid of their centres (cell >= reach) */
    float *inv;          /* anisotropic: ak.inv (A^-1 per sorted slot), NULL when isotropic */
    float *wscale;       /* anisotropic: ak.wscale (1 / det A per sorted slot) */
    float *sx, *sy, *sz; /* accel: sorted positions as structure of arrays */
    int sub;             /* accel: sub-cells per cell edge (0: no sub-cell bounds) */
    uint8_t *lo, *hi;    /* accel: per sub-cell, phi bounds quantised in units of iso / FS_REF_Q, rounded outward */
    uint8_t *cell_cls;   /* accel: per cell slot, its class (FS_REF_OUT ... FS_REF_CELL_NONE; atomic on demand) */
    uint8_t *fine;       /* accel: per cell slot, FS_REF_FINE^3 bits: phi >= iso proven on that fine sub-cell */
    uint8_t *fine_state; /* accel: per cell slot, FS_REF_PROOF_* (atomic: proofs on demand claim a cell) */
    uint64_t waits;      /* on demand: times a ray waited for the thread that claimed a cell, all renders */
} reference;

/* The state of a cell's interior proof (reference_interior.c): not made yet,
 * being made by the thread that claimed it, made (walk its fine bits), or made
 * and every coarse sub-cell proven inside (the whole cell is inside). */
enum { FS_REF_PROOF_NONE = 0, FS_REF_PROOF_CLAIMED = 1, FS_REF_PROOF_BITS = 2, FS_REF_PROOF_ALL_IN = 3 };

/* Fine sub-cells per cell edge for the interior bounds (reference_interior.c);
 * a multiple of every coarse count (1, 2, 4), and one vector row. */
#define FS_REF_FINE 8
#define FS_REF_FINE3 (FS_REF_FINE * FS_REF_FINE * FS_REF_FINE)

/* reference.supersample's largest N, and the radius in pixels below which a
 * render notes that the image aliases (reference.c, note_small_radius). */
#define FS_REF_MAX_SUPERSAMPLE 8
#define FS_REF_SMALL_R_PX 2

/* Quantisation of the sub-cell bounds: value v is stored as v / (iso / FS_REF_Q). */
#define FS_REF_Q 64

/* One ray's work (docs/DESIGN.md, "Work counters"), counted in the ray's
 * result and added up per thread; the sums over particles are not touched.
 * evals, samples and nbrs are counted on every render; the walk's counts
 * (crossings, cells ...) only in a counting render (fs_counting, read once a ray). */
typedef struct ray_work {
    uint64_t evals, samples, nbrs;
    uint64_t crossings;             /* sign changes of phi - iso located */
    uint64_t cells, marched;        /* near cells walked; those where phi was summed */
    uint64_t marched_in;            /* ... with the ray inside all along (no crossing) */
    uint64_t proven_in, proven_out; /* near cells crossed whole on proven bounds, by class */
    uint64_t refine_evals;          /* evals that refine a bracketed crossing */
    uint64_t inside_evals;          /* evals in the marched_in cells */
    uint64_t waits; /* proofs on demand: waits for the thread that claimed the cell (not a work count) */
} ray_work;

/* The work of one ray's two phases: before and with its first hit (the first-hit
 * march), and after it (the thickness march); and the cells' bounds and interior
 * proofs it made on demand. The counting render reports them as the stages "march",
 * "thickness", "bounds" and "interior" (README.md, "Work counters"). */
enum { FS_REF_FIRST = 0, FS_REF_AFTER = 1, FS_REF_BOUNDS = 2, FS_REF_PROOFS = 3, FS_REF_NWORK = 4 };

typedef struct ray_result {
    ray_work w[FS_REF_NWORK]; /* [hit]: the phase the ray is in; then what it made on demand */
    int hit;
    float t;    /* ray distance of the first hit */
    float n[3]; /* world normal, -grad phi normalised */
    float thick;
} ray_result;

/* The near particles of one cell stretch, relative to its start point o
 * (reference_fast.c gathers them): foot a and squared distance b from the ray
 * line (and, anisotropic only, the metric's k and the weight ws), and the
 * sorted slot. */
typedef struct near_soa {
    float *a, *b, *k, *ws, *keep;
    uint32_t *slot;
    float o[3];
    int n;
} near_soa;

/* The second-order inside step (reference_taylor.c, README.md step 6): only
 * for the isotropic cubic spline, whose curvature bound it uses. */
int fs_ref_taylor_applies(const reference *R);
/* phi at local t, and its derivative along the ray in *slope. */
float fs_ref_slope_sum(const reference *R, const near_soa *N, float t, float *slope);
/* An upper bound of |phi''| along the ray on local [u0, u1]. */
float fs_ref_curv_bound(const reference *R, const near_soa *N, float u0, float u1);
/* With g = phi - iso >= 0 and g1 its slope at local t, and M a curvature
 * bound ahead: *lo is the longest step on which phi >= iso is proven, *hi the
 * shortest after which phi < iso is (INFINITY when none); phi falls all along
 * [0, *hi], so at most one crossing lies before *hi. */
void fs_ref_taylor_steps(const reference *R, float g, float g1, float M, float *lo, float *hi);

/* The march state carried from cell to cell along one ray. */
typedef struct march {
    int started;  /* phi has been sampled once */
    int inside;   /* phi >= iso at the current point */
    int counting; /* the inside interval was entered from outside */
    int layers;
    float g;       /* phi - iso at the current point (or a bound of it with the same sign) */
    float t_enter; /* ray distance where the current inside interval began */
    float s_prev;
} march;

/* One stretch of a ray inside one stored cell: cell coordinates c, slot, and
 * ray distances [t0, t1]. The visitor returns 1 when the ray is finished. */
typedef int (*fs_ref_visit)(void *ctx, const int c[3], uint32_t slot, float t0, float t1);

/* Walks the ray o + t d (t >= 0) through the cells of R's grid that can see a
 * particle, in order, calling visit for each; cells whose block is not stored
 * and clusters the ray misses are skipped. *t_last gets where the walk ended. */
void fs_ref_walk(const reference *R, const float o[3], const float d[3], fs_ref_visit visit, void *ctx, float *t_last);

/* The march's state changes shared by both paths. */
void fs_ref_leave_fluid(march *m, ray_result *res, float t, const reference *R);
/* A crossing of the iso-surface at ray distance t, written once for every march:
 * entering (from outside) records the first hit, its normal the unit vector of
 * outward (read only then; -d where it is 0), and opens a thickness layer;
 * leaving closes it. 1 when the ray is finished (a first hit without thickness,
 * or the last layer). */
int fs_ref_cross(const reference *R, march *m, ray_result *res, float t, const float outward[3], const float d[3]);

/* dst += src, counter by counter. */
void fs_ref_work_add(ray_work *dst, const ray_work *src);

/* Counting only: one near cell a ray walks, counted into the phase the ray was in
 * when it entered (fs_ref_cell_begin before the visit, fs_ref_cell_end after it):
 * marched when phi was summed in it (marched_in when also no crossing and the ray
 * inside on entry), else proven in or out when the whole stretch was crossed on
 * proven bounds. */
typedef struct cell_mark {
    ray_work *w;
    uint64_t evals, crossings;
    int inside;
} cell_mark;
void fs_ref_cell_begin(ray_result *res, const march *m, cell_mark *c);
void fs_ref_cell_end(const cell_mark *c, const ray_result *res, const march *m, int proven);

/* accel=off: one ray, per-cell march of the original implementation. buf holds max27 entries. */
void fs_ref_cast_plain(const reference *R, const float o[3], const float d[3], void *buf, ray_result *res);
size_t fs_ref_plain_buf_size(const reference *R);
/* accel=on. */
void fs_ref_cast_fast(const reference *R, const float o[3], const float d[3], void *buf, ray_result *res);
size_t fs_ref_fast_buf_size(const reference *R);

/* field=zhu_bridson (reference_zb.c): one ray, whatever accel says. buf holds max27 entries. */
void fs_ref_cast_zb(const reference *R, const float o[3], const float d[3], void *buf, ray_result *res);
size_t fs_ref_zb_buf_size(const reference *R);

/* Makes room for R->lo/hi/cell_cls (R->sub set; frees them first), and, unless
 * demand, every near cell's bounds and class (in parallel, counted in the current
 * stage). With demand they are made by the march (fs_ref_cell_ready). */
int fs_ref_bounds_build(reference *R, int demand);
void fs_ref_bounds_free(reference *R);
/* The class of near cell c (slot), its bounds made now when no thread has made them
 * (claimed once; a thread that finds them claimed waits for them, counted in w->waits),
 * their work counted in w. A function of the cell alone. */
int fs_ref_cell_ready(const reference *R, const int c[3], uint32_t slot, ray_work *w);
/* Makes room for R->fine/fine_state (after fs_ref_bounds_build; frees them first),
 * and, unless demand, every FS_REF_EDGE_IN cell's proof (in parallel, counted in the
 * current stage: needs every cell's bounds). With demand the proofs are made by the
 * march (fs_ref_proof_ready). Nothing is made where it does not apply. */
int fs_ref_interior_build(reference *R, int demand);
/* Bytes of one thread's scratch for fs_ref_proof_ready. */
size_t fs_ref_proof_buf_size(const reference *R);
/* The interior proof of FS_REF_EDGE_IN cell c (slot), made now when no thread has
 * made it (claimed once; a thread that finds it claimed waits for it, counted in
 * w->waits), its work counted in w. The proof is a function of the cell alone, so
 * the image does not depend on which ray made it. Returns FS_REF_PROOF_BITS or
 * FS_REF_PROOF_ALL_IN. buf: fs_ref_proof_buf_size bytes. */
int fs_ref_proof_ready(const reference *R, const int c[3], uint32_t slot, void *buf, ray_work *w);
void fs_ref_interior_free(reference *R);
#endif
