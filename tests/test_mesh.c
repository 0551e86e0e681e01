/* mesh (marching cubes of the scene's field, rasterised): the mesh of a ball
 * of particles is closed, wound outward, its vertices on the iso-surface and
 * its normals outward; its volume matches the field's inside; Taubin keeps
 * the volume where Laplacian shrinks it; the render of the bundled dam break
 * against the reference (depth, normals, thickness); the anisotropic field;
 * the memory refusal; inside leaves made tiles change no vertex. */
#include "fs_error.h"
#include "fs_test.h"
#include "test_gl_context.h"
#include "grid.h"
#include "mesh/mesh_build.h"
#include "mesh/mesh_sample.h"
#include "mesh/mesh_smooth.h"
#include "mesh/mesh_vdb.h"
#include "method.h"
#include "metrics.h"
#include "field_eval.h"
#include "scene.h"
#include "test_render.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Every undirected edge is shared by exactly two triangles. */
static int edges_not_twice(const fs_trimesh *m)
{
    uint64_t *e = malloc(m->nt * 3 * sizeof *e);
    for (size_t t = 0; t < m->nt; t++)
        for (int c = 0; c < 3; c++) {
            uint64_t a = m->tri[3 * t + c], b = m->tri[3 * t + (c + 1) % 3];
            e[3 * t + c] = a < b ? a << 32 | b : b << 32 | a;
        }
    qsort(e, m->nt * 3, sizeof *e, cmp_u64);
    int bad = 0;
    for (size_t i = 0; i < m->nt * 3;) {
        size_t j = i;
        while (j < m->nt * 3 && e[j] == e[i]) j++;
        bad += j - i != 2;
        i = j;
    }
    free(e);
    return bad;
}

/* A ball of particles on the 2r lattice, radius 6 spacings, centred at c. */
static void ball(fs_particles *p, float r, const float c[3])
{
    int R = 6, n = 0;
    fs_particles_alloc(p, (size_t)(2 * R + 1) * (2 * R + 1) * (2 * R + 1), 0);
    for (int i = -R; i <= R; i++)
        for (int j = -R; j <= R; j++)
            for (int k = -R; k <= R; k++)
                if (i * i + j * j + k * k <= R * R) {
                    p->x[n] = c[0] + 2 * r * i, p->y[n] = c[1] + 2 * r * j, p->z[n] = c[2] + 2 * r * k;
                    n++;
                }
    p->n = (size_t)n;
    p->radius = r;
    fs_particles_bounds(p);
}

/* The volume where phi >= iso, counted on a lattice of spacing h. */
static double inside_volume(const fs_field_eval *e, const fs_particles *p, float h)
{
    double v = 0;
    float pad = e->f.H;
    for (float x = p->bmin[0] - pad; x <= p->bmax[0] + pad; x += h)
        for (float y = p->bmin[1] - pad; y <= p->bmax[1] + pad; y += h)
            for (float z = p->bmin[2] - pad; z <= p->bmax[2] + pad; z += h) {
                float phi, g[3], q[3] = {x, y, z};
                fs_field_eval_at(e, q, &phi, g);
                v += phi >= e->f.iso;
            }
    return v * h * h * h;
}

static void ball_mesh(void)
{
    float r = 0.025f, c[3] = {0.3f, 0.7f, -0.2f};
    fs_particles p;
    ball(&p, r, c);
    fs_field f = {r, 0.8f * 8 * r * r * r, FS_KERNEL_CUBIC, 4 * r, 0.6f};
    fs_grid g;
    CHECK(fs_grid_build(&g, &p, f.H) == FS_OK, "grid: %s", fs_error_message());
    fs_mesh_opts o = {.cube = 0.5 * r};
    fs_trimesh m;
    fs_stages st = {0};
    CHECK(fs_mesh_build(&p, &g, &f, &o, &m, &st) == FS_OK, "ball: %s", fs_error_message());
    const char *want[] = {"field", "mesh", "normals", NULL}, *miss = fs_test_missing_stage(&st, want);
    CHECK(miss == NULL, "ball: no stage %s", miss);
    CHECK(m.nt > 1000 && m.nv > 500, "ball: %zu triangles, %zu vertices", m.nt, m.nv);
    int open_edges = edges_not_twice(&m);
    CHECK(open_edges == 0, "ball: %d edges not shared by exactly two triangles", open_edges);
    double vol = fs_trimesh_volume6(&m) / 6;
    fs_field_eval e = {f, &g, NULL};
    double want_v = inside_volume(&e, &p, 0.25f * r);
    printf("ball: %zu vertices, %zu triangles, volume %.6g, field inside %.6g\n", m.nv, m.nt, vol, want_v);
    CHECK(fabs(vol / want_v - 1) < 0.01, "ball: mesh volume %g against the field's %g", vol, want_v);
    int off = 0, inward = 0, bad_n = 0;
    double worst = 0;
    for (size_t v = 0; v < m.nv; v++) {
        const float *x = m.pos + 3 * v, *n = m.nrm + 3 * v;
        float phi, gr[3];
        fs_field_eval_at(&e, x, &phi, gr);
        if (fabsf(phi - f.iso) > worst) worst = fabsf(phi - f.iso);
        off += fabsf(phi - f.iso) > 0.05f;
        inward += n[0] * (x[0] - c[0]) + n[1] * (x[1] - c[1]) + n[2] * (x[2] - c[2]) <= 0;
        bad_n += fabsf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1) > 1e-4f;
    }
    printf("ball: worst |phi - iso| at a vertex %.4f\n", worst);
    CHECK(off == 0, "ball: %d vertices with |phi - iso| > 0.05 (worst %.4f)", off, worst);
    CHECK(inward == 0 && bad_n == 0, "ball: %d normals not outward, %d not unit", inward, bad_n);
    /* smoothing: Taubin keeps the volume, Laplacian shrinks it */
    fs_trimesh t;
    fs_mesh_opts ot = o, ol = o;
    ot.smooth = FS_MESH_SMOOTH_TAUBIN, ot.smooth_iters = 20;
    ol.smooth = FS_MESH_SMOOTH_LAPLACIAN, ol.smooth_iters = 20;
    CHECK(fs_mesh_build(&p, &g, &f, &ot, &t, NULL) == FS_OK, "taubin: %s", fs_error_message());
    double vt = fs_trimesh_volume6(&t) / 6;
    fs_trimesh_free(&t);
    CHECK(fs_mesh_build(&p, &g, &f, &ol, &t, NULL) == FS_OK, "laplacian: %s", fs_error_message());
    double vl = fs_trimesh_volume6(&t) / 6;
    fs_trimesh_free(&t);
    printf("ball: volume after 20 steps: Taubin %.6g, Laplacian %.6g (unsmoothed %.6g)\n", vt, vl, vol);
    CHECK(fabs(vt / vol - 1) < 0.01 && vl < 0.98 * vol, "smoothing: Taubin %g, Laplacian %g of %g", vt, vl, vol);
    /* the memory refusal: before allocating, naming a cube that fits */
    fs_mesh_opts om = o;
    om.mem_limit = 1e6;
    int rc = fs_mesh_build(&p, &g, &f, &om, &t, NULL);
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "use cube >="), "memory refusal: rc %d, %s", rc,
          fs_error_message());
    fs_trimesh_free(&m);
    fs_grid_free(&g);
    fs_particles_free(&p);
}

static fs_metrics measure(const char *what, const fs_gbuffer *a, const fs_gbuffer *b, float r)
{
    fs_metrics m;
    memset(&m, 0, sizeof m);
    CHECK(fs_metrics_compute(a, NULL, b, NULL, r, &m) == FS_OK, "metrics: %s", fs_error_message());
    printf("%s: IoU %.4f, depth bias %.3f r, p95 %.3f r, normal mean %.2f deg (interior %.2f)\n", what, m.mask_iou,
           m.depth_bias_r, m.depth_p95_r, m.normal_mean_deg, m.interior_normal_mean_deg);
    return m;
}

/* Mean |thickness difference| over pixels both cover, in r. */
static double thickness_gap(const fs_gbuffer *a, const fs_gbuffer *b, float r)
{
    double s = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)a->w * a->h; i++)
        if (a->coverage[i] && b->coverage[i]) s += fabs(a->thickness[i] - b->thickness[i]), n++;
    return n ? s / n / r : INFINITY;
}

static void dam_break(void)
{
    fs_particles p;
    static fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) {
        CHECK(0, "dam: %s", fs_error_message());
        return;
    }
    fs_gbuffer me, ref;
    fs_gbuffer_alloc(&me, s.camera.width, s.camera.height);
    fs_gbuffer_alloc(&ref, s.camera.width, s.camera.height);
    fs_stages st = {0};
    CHECK(fs_test_render("mesh", NULL, &p, f, &s.camera, &me, &st) == FS_OK, "mesh: %s", fs_error_message());
    const char *want[] = {"upload", "raster", "thickness", NULL}, *miss = fs_test_missing_stage(&st, want);
    CHECK(miss == NULL, "dam: no stage %s", miss);
    CHECK(fs_test_render("reference", NULL, &p, f, &s.camera, &ref, NULL) == FS_OK, "reference: %s",
          fs_error_message());
    fs_metrics m = measure("dam mesh vs reference", &me, &ref, f.r);
    CHECK(m.mask_iou >= 0.98 && m.depth_p95_r <= 0.1 && m.interior_normal_mean_deg <= 2,
          "dam: IoU %.4f (>= 0.98), depth p95 %.3f r (<= 0.1), interior normal %.2f deg (<= 2)", m.mask_iou,
          m.depth_p95_r, m.interior_normal_mean_deg);
    double tg = thickness_gap(&me, &ref, f.r);
    printf("dam: mean |thickness - reference's| %.4f r\n", tg);
    CHECK(tg < 0.1, "dam: thickness differs from the reference's by %.4f r on average", tg);
    const char *off[] = {"thickness=off", NULL};
    CHECK(fs_test_render("mesh", off, &p, f, &s.camera, &me, NULL) == FS_OK, "thickness off: %s", fs_error_message());
    int nonzero = 0;
    for (size_t i = 0; i < (size_t)me.w * me.h; i++) nonzero += me.thickness[i] != 0;
    CHECK(nonzero == 0, "thickness=off: %d pixels with thickness", nonzero);
    /* the anisotropic field against the anisotropic reference */
    const char *an[] = {"field=anisotropic", NULL};
    CHECK(fs_test_render("mesh", an, &p, f, &s.camera, &me, NULL) == FS_OK, "aniso mesh: %s", fs_error_message());
    CHECK(fs_test_render("reference", an, &p, f, &s.camera, &ref, NULL) == FS_OK, "aniso ref: %s", fs_error_message());
    m = measure("dam anisotropic mesh vs anisotropic reference", &me, &ref, f.r);
    CHECK(m.mask_iou >= 0.97 && m.interior_normal_mean_deg <= 3, "aniso: IoU %.4f, interior normal %.2f deg",
          m.mask_iou, m.interior_normal_mean_deg);
    fs_gbuffer_free(&me);
    fs_gbuffer_free(&ref);
    fs_particles_free(&p);
}

/* The mesh of p's volume, every leaf kept or inside leaves made tiles; *kept, *leaves. */
static int volume_mesh(const fs_particles *p, const fs_grid *g, const fs_field *f, double cube, int keep_all,
                       fs_trimesh *m, size_t *kept, size_t *leaves)
{
    size_t need = 0;
    fs_mesh_volume *v = fs_mesh_volume_create(p->x, p->y, p->z, p->n, cube, f->H, f->iso, keep_all, 0, &need);
    fs_mesh_work w = {0, 0};
    int rc = v ? fs_mesh_sample(v, cube, f, g, NULL, &w) : FS_ERR_RUNTIME;
    if (!rc) rc = fs_mesh_volume_mesh(v, f->iso, m);
    if (v) *kept = fs_mesh_volume_kept(v), *leaves = fs_mesh_volume_leaves(v);
    if (v) fs_mesh_volume_free(v);
    return rc;
}

/* On the dam break, the leaves inside the liquid become tiles, and the mesh is
 * the same to the bit as with every leaf kept. */
static void interior_tiles(void)
{
    fs_particles p;
    static fs_scene s;
    fs_field f;
    if (fs_test_load_dam(&p, &s, &f)) {
        CHECK(0, "dam: %s", fs_error_message());
        return;
    }
    fs_grid g;
    CHECK(fs_grid_build(&g, &p, f.H) == FS_OK, "grid: %s", fs_error_message());
    fs_trimesh a, b;
    size_t ka, kb, la, lb;
    double cube = 0.5 * f.r;
    CHECK(volume_mesh(&p, &g, &f, cube, 0, &a, &ka, &la) == FS_OK, "tiles: %s", fs_error_message());
    CHECK(volume_mesh(&p, &g, &f, cube, 1, &b, &kb, &lb) == FS_OK, "all leaves: %s", fs_error_message());
    printf("interior tiles: %zu of %zu leaves kept (all kept: %zu); %zu and %zu vertices\n", ka, la, kb, a.nv, b.nv);
    CHECK(la == lb && kb == lb && ka < 0.9 * la, "interior tiles: kept %zu of %zu (all: %zu of %zu)", ka, la, kb, lb);
    int same = a.nv == b.nv && a.nt == b.nt && !memcmp(a.pos, b.pos, 3 * a.nv * sizeof *a.pos) &&
        !memcmp(a.tri, b.tri, 3 * a.nt * sizeof *a.tri);
    CHECK(same, "interior tiles: the mesh changed (%zu/%zu vertices, %zu/%zu triangles)", a.nv, b.nv, a.nt, b.nt);
    fs_trimesh_free(&a);
    fs_trimesh_free(&b);
    fs_grid_free(&g);
    fs_particles_free(&p);
}

int main(void)
{
    ball_mesh();
    interior_tiles();
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    dam_break();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
