/* The mesh pipeline (mesh_build.h). */
#include "mesh_build.h"
#include "aniso_kernels.h"
#include "counters.h"
#include "field_eval.h"
#include "fs_error.h"
#include "memory.h"
#include "mesh_sample.h"
#include "mesh_attributes.h"
#include "mesh_collapse.h"
#include "mesh_normals.h"
#include "mesh_smooth.h"
#include "mesh_vdb.h"
#include "mesh_weights.h"
#include "vec3.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void stage(fs_stages *st, const char *name, double t0)
{
    if (st) fs_stages_add(st, name, fs_now_ms() - t0);
}

/* Refuses a volume whose bookkeeping would not fit: its leaves lie in the cells
 * whose 27 neighbours hold a particle (g's cell >= the reach), and a cell meets
 * at most (ceil(cell / leaf) + 1)^3 leaves. The voxels kept are checked slab by
 * slab while sampling (mesh_vdb.h). */
static int check_memory(const fs_grid *g, double cube, double limit)
{
    size_t near = 0;
    for (size_t w = 0; w < g->ncells / 32 + 1; w++) near += (size_t)__builtin_popcount(g->near[w]);
    double per_cell = ceil(g->cell / (FS_MESH_LEAF * cube)) + 1;
    double est = (double)near * per_cell * per_cell * per_cell * FS_MESH_INDEX_BYTES;
    if (est <= limit) return FS_OK;
    double fit = cube * cbrt(est / limit) * 1.05;
    return fs_fail(
        FS_ERR_INPUT,
        "mesh: cube %g needs about %.3g GB for its sample volume, %.3g GB are available: use cube >= %.3g (scene units)",
        cube, est / 1e9, limit / 1e9, fit);
}

/* Where a vertex's normal comes from the field: the SPH field's -grad phi, or
 * field=zhu_bridson's grad phi (zg set). */
typedef struct normal_src {
    const fs_field_eval *e;
    const fs_grid *zg;
    double R, r;
} normal_src;

/* The field's outward unit normal at x (0 where the gradient vanishes); returns
 * the particle terms summed. */
static size_t field_normal_at(const normal_src *s, const float *x, float n[3])
{
    float g[3], sign = s->zg ? 1.0f : -1.0f;
    size_t terms;
    if (s->zg) {
        double phi;
        terms = fs_zb_eval(s->zg, s->R, s->r, x, &phi, g);
    } else {
        float phi;
        terms = fs_field_eval_at(s->e, x, &phi, g);
    }
    float len = fs_v3_len(g);
    for (int a = 0; a < 3; a++) n[a] = len > 0 ? sign * g[a] / len : 0;
    return terms;
}

/* fs_mesh_field_normal over a normal_src, for the repair of degenerate normals. */
static int field_normal(const void *ctx, const float *x, float n[3])
{
    field_normal_at(ctx, x, n);
    return n[0] != 0 || n[1] != 0 || n[2] != 0;
}

/* The field's normal at each vertex (0 where the gradient vanishes, repaired
 * after: fs_mesh_normals_repair). */
static int vertex_normals(fs_trimesh *m, const normal_src *s, fs_mesh_work *w)
{
    m->nrm = malloc((m->nv ? m->nv : 1) * 3 * sizeof *m->nrm);
    if (!m->nrm) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for %zu normals", m->nv);
    long nv = (long)m->nv;
    uint64_t terms = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : terms)
    for (long v = 0; v < nv; v++) terms += field_normal_at(s, m->pos + 3 * v, m->nrm + 3 * v);
    w->voxels += (uint64_t)m->nv;
    w->terms += terms;
    return FS_OK;
}

/* The smoothing; weighted: splashsurf's weights from the unsmoothed vertices
 * (its order), their particle terms counted as neighbours visited. */
static int smooth(fs_trimesh *m, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o)
{
    if (o->smooth != FS_MESH_SMOOTH_WEIGHTED) return fs_mesh_smooth(m, o->smooth, o->smooth_iters, NULL);
    float *wt = malloc((m->nv ? m->nv : 1) * sizeof *wt);
    if (!wt) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for the smoothing weights");
    uint64_t terms = 0;
    int rc = fs_mesh_weights(m, g, f, o->weights_norm > 0 ? o->weights_norm : FS_MESH_WEIGHTS_NORM, wt, &terms);
    fs_count_add(FS_CNT_NEIGHBOURS, terms);
    if (!rc) rc = fs_mesh_smooth(m, o->smooth, o->smooth_iters, wt);
    free(wt);
    return rc;
}

/* field=zhu_bridson: R - phi on the volume (meshed at iso = R: phi = 0), over a
 * grid of cell >= R. */
static int sample_zb(const fs_particles *p, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o, double R,
                     fs_mesh_volume **vol, fs_mesh_work *w)
{
    double limit = o->mem_limit > 0 ? o->mem_limit : (double)fs_memory_available();
    size_t need = 0;
    int rc = check_memory(g, o->cube, limit);
    if (rc) return rc;
    *vol = fs_mesh_volume_create(p->x, p->y, p->z, p->n, o->cube, R, R, o->keep_all, limit, &need);
    if (!*vol && need)
        return fs_fail(FS_ERR_INPUT,
                       "mesh: cube %g needs %zu leaves (%.3g GB), %.3g GB are available: use cube >= %.3g", o->cube,
                       need, (double)need * FS_MESH_INDEX_BYTES / 1e9, limit / 1e9,
                       o->cube * cbrt((double)need * FS_MESH_INDEX_BYTES / limit) * 1.05);
    if (!*vol) return FS_ERR_RUNTIME;
    return fs_mesh_sample_zb(*vol, o->cube, R, f->r, g, w);
}

/* The sample volume and its values. */
static int sample(const fs_particles *p, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o,
                  const fs_aniso_kernels *ak, fs_mesh_volume **vol, fs_mesh_work *w)
{
    const fs_grid *cg = ak ? &ak->grid : g;
    double reach = ak ? ak->reach : f->H, limit = o->mem_limit > 0 ? o->mem_limit : (double)fs_memory_available();
    size_t need = 0;
    int rc = check_memory(cg, o->cube, limit);
    if (rc) return rc;
    /* the volume is found from the kernel centres (the particles, when isotropic) */
    const float *x = p->x, *y = p->y, *z = p->z;
    float *cx = NULL;
    if (ak) {
        size_t n = cg->n;
        cx = malloc((n ? n : 1) * 3 * sizeof *cx);
        if (!cx) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory");
        for (size_t s = 0; s < n; s++)
            for (int a = 0; a < 3; a++) cx[a * n + s] = cg->pos4[4 * s + a];
        x = cx, y = cx + n, z = cx + 2 * n;
    }
    *vol = fs_mesh_volume_create(x, y, z, cg->n, o->cube, reach, f->iso, o->keep_all, limit, &need);
    free(cx);
    if (!*vol && need)
        return fs_fail(FS_ERR_INPUT,
                       "mesh: cube %g needs %zu leaves (%.3g GB), %.3g GB are available: use cube >= %.3g", o->cube,
                       need, (double)need * FS_MESH_INDEX_BYTES / 1e9, limit / 1e9,
                       o->cube * cbrt((double)need * FS_MESH_INDEX_BYTES / limit) * 1.05);
    if (!*vol) return FS_ERR_RUNTIME;
    return fs_mesh_sample(*vol, o->cube, f, g, ak, w);
}

/* What the field stage leaves for the later ones: the anisotropic kernels
 * and field=zhu_bridson's grid (zg, owned when zg_own). */
typedef struct built_field {
    fs_aniso_kernels ak;
    fs_grid zg;
    const fs_grid *zgp;
    int zg_own;
    double zr; /* zhu_bridson's R */
} built_field;

/* Stages "field" and "mesh": the sampled volume meshed at iso, wound outward;
 * unsmoothed, its degenerate faces (if any) collapsed there. */
static int field_and_mesh(const fs_particles *p, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o,
                          built_field *b, fs_trimesh *out, fs_stages *st)
{
    fs_mesh_volume *vol = NULL;
    fs_mesh_work w = {0, 0};
    double t0 = fs_now_ms();
    b->zr = o->zb_radius > 0 ? o->zb_radius : FS_ZB_RADIUS * f->r;
    b->zgp = g;
    int rc = o->aniso ? fs_aniso_kernels_build(&b->ak, p, g, &o->ap, f->H) : FS_OK;
    if (!rc && o->zb) rc = fs_grid_fit(g, p, (float)b->zr, &b->zg, &b->zg_own, &b->zgp);
    if (!rc)
        rc = o->zb ? sample_zb(p, b->zgp, f, o, b->zr, &vol, &w)
                   : sample(p, g, f, o, o->aniso ? &b->ak : NULL, &vol, &w);
    fs_count_add(FS_CNT_FIELD_EVALS, w.voxels);
    fs_count_add(FS_CNT_NEIGHBOURS, w.terms);
    if (!rc) stage(st, "field", t0);
    double t1 = fs_now_ms();
    if (!rc) rc = fs_mesh_volume_mesh(vol, o->zb ? b->zr : f->iso, out);
    fs_mesh_volume_free(vol);
    if (!rc && fs_trimesh_volume6(out) < 0) fs_trimesh_flip(out); /* wound outward, whatever the library does */
    int smoothed = o->smooth && o->smooth_iters > 0;
    if (!rc && !smoothed) rc = fs_mesh_collapse_degenerate(out, FS_MESH_DEGENERATE_CUBE * o->cube, NULL);
    if (!rc) stage(st, "mesh", t1);
    return rc;
}

/* Stage "normals": the field's, or splashsurf's smoothed face normals
 * (weighted); then every one that is not unit repaired. */
static int normals(fs_trimesh *m, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o, const built_field *b,
                   fs_stages *st)
{
    double t0 = fs_now_ms();
    fs_field_eval e = {*f, g, o->aniso ? &b->ak : NULL};
    normal_src src = {&e, o->zb ? b->zgp : NULL, b->zr, f->r};
    fs_mesh_work w = {0, 0};
    int rc = o->smooth == FS_MESH_SMOOTH_WEIGHTED ? fs_mesh_normals_smoothed(m, o->normal_iters)
                                                  : vertex_normals(m, &src, &w);
    fs_count_add(FS_CNT_FIELD_EVALS, w.voxels);
    fs_count_add(FS_CNT_NEIGHBOURS, w.terms);
    if (!rc) rc = fs_mesh_normals_repair(m, field_normal, &src, NULL);
    if (!rc) stage(st, "normals", t0);
    return rc;
}

int fs_mesh_build(const fs_particles *p, const fs_grid *g, const fs_field *f, const fs_mesh_opts *o, fs_trimesh *out,
                  fs_stages *st)
{
    memset(out, 0, sizeof *out);
    built_field b;
    memset(&b, 0, sizeof b);
    int rc = field_and_mesh(p, g, f, o, &b, out, st);
    double t0 = fs_now_ms();
    if (!rc && o->smooth && o->smooth_iters > 0) {
        rc = smooth(out, g, f, o);
        if (!rc) rc = fs_mesh_collapse_degenerate(out, FS_MESH_DEGENERATE_CUBE * o->cube, NULL);
        if (!rc) stage(st, "smooth", t0);
    }
    if (!rc) rc = normals(out, g, f, o, &b, st);
    double t1 = fs_now_ms();
    if (!rc && o->attributes) {
        rc = fs_mesh_attributes(out, p, g, f);
        if (!rc) stage(st, "attributes", t1);
    }
    fs_aniso_kernels_free(&b.ak);
    if (b.zg_own) fs_grid_free(&b.zg);
    if (rc) fs_trimesh_free(out);
    return rc;
}
