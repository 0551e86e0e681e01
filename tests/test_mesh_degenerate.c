/* After any smoothing, on any field, the mesh has no zero-length normal and no
 * face of zero area (methods/mesh/README.md, "Deviations"): smoothing shrinks
 * droplets to points and lines, whose faces are then collapsed
 * (mesh_collapse.h) and whose normals are repaired (mesh_normals.h).
 *  - The crop of the DualSPHysics frame (experiments/data/dualsphysics/, r =
 *    0.00365) with splashsurf's recipe (weighted, 25 steps) on the isotropic,
 *    anisotropic and Zhu & Bridson fields, and with Laplacian smoothing: every
 *    normal unit, every face of positive area (in float, as a reader computes
 *    it), every vertex used, and under 2% of the unsmoothed mesh's faces gone.
 *    Before the fix, weighted on the isotropic field left 28 normals of
 *    (0, 0, 0) and 52 faces of zero area there.
 *  - Small meshes: a tetrahedron shrunk to a point goes whole and leaves the
 *    other one untouched; a near-zero edge in a fan is merged at its midpoint;
 *    a zero normal takes its faces' mean, else the field's, else its largest
 *    face's. */
#include "fs_error.h"
#include "fs_test.h"
#include "grid.h"
#include "kernels.h"
#include "particle_io.h"
#include "mesh/mesh_build.h"
#include "mesh/mesh_collapse.h"
#include "mesh/mesh_normals.h"
#include "mesh/mesh_smooth.h"
#include "mesh/trimesh.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CROP FS_TEST_DATA "/dualsphysics/dambreak200k_t0.300_crop902.vtk"
#define R_ 0.00365f /* the frame's dp / 2 (its README) */

/* Counts of what must not be: non-unit normals, faces of zero float area,
 * vertices no face uses, corner indices out of range. */
typedef struct flaws {
    size_t normals, faces, unused, bad_index;
} flaws;

static flaws flaws_of(const fs_trimesh *m)
{
    flaws f = {0, 0, 0, 0};
    char *used = calloc(m->nv + 1, 1);
    for (size_t v = 0; v < m->nv; v++) {
        const float *n = m->nrm + 3 * v;
        f.normals += !(fabsf(sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) < 1e-4f);
    }
    for (size_t t = 0; t < m->nt; t++) {
        const uint32_t *c = m->tri + 3 * t;
        if (c[0] >= m->nv || c[1] >= m->nv || c[2] >= m->nv) {
            f.bad_index++;
            continue;
        }
        const float *a = m->pos + 3 * (size_t)c[0], *b = m->pos + 3 * (size_t)c[1], *d = m->pos + 3 * (size_t)c[2];
        float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        float x[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        f.faces += !(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] > 0);
        used[c[0]] = used[c[1]] = used[c[2]] = 1;
    }
    for (size_t v = 0; v < m->nv; v++) f.unused += !used[v];
    free(used);
    return f;
}

static fs_trimesh build(const fs_particles *p, const fs_grid *g, fs_mesh_opts o, const char *what)
{
    fs_field f = {R_, 8 * R_ * R_ * R_, FS_KERNEL_CUBIC, 4 * R_, 0.6f};
    fs_trimesh m;
    o.cube = 0.5 * R_;
    o.zb_radius = 4 * R_;
    int rc = fs_mesh_build(p, g, &f, &o, &m, NULL);
    CHECK(rc == FS_OK && m.nt > 0, "%s: %s", what, fs_error_message());
    return m;
}

/* The crop with each smoothing and field: sound, and little removed. */
static void crop(void)
{
    fs_particles p;
    fs_grid g;
    int rc = fs_particles_read(&p, CROP, NULL);
    CHECK(rc == FS_OK && p.n == 902, "%s: %s", CROP, fs_error_message());
    if (rc) return;
    if (fs_grid_build(&g, &p, 4 * R_)) return;
    fs_trimesh raw = build(&p, &g, (fs_mesh_opts){0}, "unsmoothed");
    int W = FS_MESH_SMOOTH_WEIGHTED;
    struct {
        const char *what;
        fs_mesh_opts o;
    } cases[] = {
        {"weighted, isotropic", {.smooth = W, .smooth_iters = 25, .normal_iters = 10}},
        {"weighted, anisotropic", {.smooth = W, .smooth_iters = 25, .normal_iters = 10, .aniso = 1}},
        {"weighted, zhu_bridson", {.smooth = W, .smooth_iters = 25, .normal_iters = 10, .zb = 1}},
        {"laplacian, isotropic", {.smooth = FS_MESH_SMOOTH_LAPLACIAN, .smooth_iters = 25}},
    };
    fs_aniso_defaults(&cases[1].o.ap, FS_KERNEL_CUBIC, R_);
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        fs_trimesh m = build(&p, &g, cases[i].o, cases[i].what);
        flaws f = flaws_of(&m);
        CHECK(!f.normals && !f.faces && !f.unused && !f.bad_index,
              "%s: %zu normals not unit, %zu faces of zero area, %zu vertices unused, %zu bad indices", cases[i].what,
              f.normals, f.faces, f.unused, f.bad_index);
        if (!cases[i].o.aniso && !cases[i].o.zb)
            CHECK(m.nt >= 0.98 * raw.nt, "%s: %zu faces left of the unsmoothed %zu", cases[i].what, m.nt, raw.nt);
        printf("%s: %zu vertices, %zu faces (unsmoothed %zu)\n", cases[i].what, m.nv, m.nt, raw.nt);
        fs_trimesh_free(&m);
    }
    fs_trimesh_free(&raw);
    fs_grid_free(&g);
    fs_particles_free(&p);
}

/* A mesh of nv vertices and nt faces copied from pos and tri (no normals). */
static fs_trimesh small_mesh(const float *pos, size_t nv, const uint32_t *tri, size_t nt)
{
    fs_trimesh m = {nv, nt, malloc(nv * 3 * sizeof(float)), NULL, malloc(nt * 3 * sizeof(uint32_t)), NULL, NULL};
    memcpy(m.pos, pos, nv * 3 * sizeof(float));
    memcpy(m.tri, tri, nt * 3 * sizeof(uint32_t));
    return m;
}

/* Two tetrahedra, the first shrunk to a point: it goes whole, the second stays
 * as it was; a fan of four faces round a centre with one rim vertex 1e-6 from
 * the centre: that pair merges at its midpoint and its two faces go. */
static void collapse(void)
{
    const float pos[] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f,
                         0,    0,    0,    1,    0,    0,    0,    1,    0,    0,    0,    1};
    const uint32_t tet[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 4, 6, 5, 4, 5, 7, 4, 7, 6, 5, 6, 7};
    fs_trimesh m = small_mesh(pos, 8, tet, 8);
    size_t gone = 0;
    CHECK(fs_mesh_collapse_degenerate(&m, 1e-3, &gone) == FS_OK, "%s", fs_error_message());
    CHECK(m.nv == 4 && m.nt == 4 && gone == 4, "point tetrahedron: %zu vertices, %zu faces left, %zu gone", m.nv, m.nt,
          gone);
    CHECK(m.nv == 4 && !memcmp(m.pos, pos + 12, 12 * sizeof(float)) && !memcmp(m.tri, tet, 12 * sizeof(uint32_t)),
          "the sound tetrahedron changed");
    fs_trimesh_free(&m);
    const float fan[] = {0, 0, 0, 1e-6f, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0, 1, 1, 0};
    const uint32_t ft[] = {0, 1, 5, 0, 5, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1};
    m = small_mesh(fan, 6, ft, 5);
    CHECK(fs_mesh_collapse_degenerate(&m, 1e-3, &gone) == FS_OK, "%s", fs_error_message());
    CHECK(m.nv == 5 && m.nt == 3 && gone == 2, "fan: %zu vertices, %zu faces, %zu gone (want 5, 3, 2)", m.nv, m.nt,
          gone);
    CHECK(m.pos[0] == 0.5e-6f && m.pos[1] == 0, "fan: merged at (%g, %g), want the midpoint", m.pos[0], m.pos[1]);
    fs_trimesh_free(&m);
}

/* The field's normal of the repair test: -z, or nothing when off. */
static int field_down(const void *ctx, const float *x, float n[3])
{
    (void)x;
    n[0] = n[1] = 0, n[2] = -1;
    return *(const int *)ctx;
}

/* Vertex 0's normal, zero: its faces' mean (+z) when they agree; when they
 * cancel (+2z, -z, -z) the field's (-z), else the largest face's (+z). */
static void repair(void)
{
    const float pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0};
    const uint32_t agree[] = {0, 1, 2, 0, 1, 3, 0, 1, 2}, cancel[] = {0, 1, 3, 0, 2, 1, 0, 2, 1};
    const uint32_t *tris[] = {agree, cancel, cancel};
    const int field_on[] = {1, 1, 0};
    const float want_z[] = {1, -1, 1};
    for (int k = 0; k < 3; k++) {
        fs_trimesh m = small_mesh(pos, 4, tris[k], 3);
        m.nrm = calloc(12, sizeof(float));
        for (int v = 1; v < 4; v++) m.nrm[3 * v] = 1; /* sound: +x */
        size_t fixed = 0;
        CHECK(fs_mesh_normals_repair(&m, field_down, &field_on[k], &fixed) == FS_OK, "%s", fs_error_message());
        CHECK(fixed == 1 && m.nrm[2] == want_z[k] && m.nrm[3] == 1, "case %d: %zu repaired, n0 = (%g, %g, %g)", k,
              fixed, m.nrm[0], m.nrm[1], m.nrm[2]);
        fs_trimesh_free(&m);
    }
}

int main(void)
{
    collapse();
    repair();
    crop();
    TEST_DONE();
}
