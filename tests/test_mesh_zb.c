/* mesh.field=zhu_bridson: marching cubes of Zhu & Bridson's phi at its zero
 * (the volume holds R - phi, meshed at R; methods/mesh/README.md). On the rest
 * lattice (r = 0.025, spacing 2r, R = 4r, cube 0.25 r), against an independent
 * double sum of the formula:
 *  - a slab 16 x 16 x 6: every vertex lies where |phi| < 0.01 r (marching cubes'
 *    linear interpolation of a distance-like field), the top face's vertices
 *    (8 r from the rims) between 0.85 and 0.90 r above the top layer (the formula's
 *    0.860-0.885 r, test_zhu_bridson), their normals within 3 degrees of +z (1.8 measured: the face undulates);
 *  - a lattice ball (|p| <= sqrt(108) r): |phi| < 0.01 r at every vertex, every
 *    vertex within r of the outermost centres (the proven bound), a closed surface
 *    with positive volume.
 * A wrong sign (meshing phi instead of -phi at the iso the volume expects) or
 * broken weights move the vertices off phi's zero and fail. */
#include "fs_error.h"
#include "fs_test.h"
#include "zb_lattice.h"
#include "grid.h"
#include "kernels.h"
#include "mesh/mesh_build.h"
#include "mesh/trimesh.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define R_ ZB_R
#define KR (4 * R_)

static int build(const fs_particles *p, fs_trimesh *m)
{
    fs_field f = {(float)R_, (float)(8 * R_ * R_ * R_), FS_KERNEL_CUBIC, (float)(4 * R_), 0.6f};
    fs_grid g;
    int rc = fs_grid_build(&g, p, f.H);
    fs_mesh_opts o = {.cube = 0.25 * R_, .zb = 1, .zb_radius = KR};
    if (!rc) rc = fs_mesh_build(p, &g, &f, &o, m, NULL);
    CHECK(rc == FS_OK && m->nv > 0, "mesh field=zhu_bridson: %s", fs_error_message());
    fs_grid_free(&g);
    return rc;
}

/* The largest |phi| (in r) over the vertices. */
static double worst_phi(const fs_particles *p, const fs_trimesh *m)
{
    double w = 0;
    for (size_t v = 0; v < m->nv; v++) {
        double x[3] = {m->pos[3 * v], m->pos[3 * v + 1], m->pos[3 * v + 2]};
        w = fmax(w, fabs(zb_indep_phi(p, x, KR)) / R_);
    }
    return w;
}

static void slab(void)
{
    fs_particles p;
    zb_lattice(&p, zb_slab_site);
    fs_trimesh m;
    if (build(&p, &m)) return;
    double lo = 1e9, hi = -1e9, ang = 0;
    size_t n = 0;
    for (size_t v = 0; v < m.nv; v++) {
        const float *x = m.pos + 3 * v;
        if (x[2] < 0 || fabs(x[0]) > 6 * R_ || fabs(x[1]) > 6 * R_) continue;
        lo = fmin(lo, x[2] / R_), hi = fmax(hi, x[2] / R_);
        ang = fmax(ang, acos(fmin(1, m.nrm[3 * v + 2])) * 180 / M_PI);
        n++;
    }
    double w = worst_phi(&p, &m);
    printf(
        "slab: %zu vertices, largest |phi| %.4f r; top face %zu vertices at %.4f-%.4f r, normals within %.3f deg of +z\n",
        m.nv, w, n, lo, hi, ang);
    CHECK(w < 0.01, "slab: a vertex at |phi| = %.4f r", w);
    CHECK(n > 100 && lo > 0.85 && hi < 0.90, "slab: top face at %.4f-%.4f r (%zu vertices), 0.860-0.885 expected", lo,
          hi, n);
    CHECK(ang < 3, "slab: a top normal %.3f deg off +z",
          ang); /* the face undulates 0.025 r between sites and hollows */
    fs_trimesh_free(&m);
    fs_particles_free(&p);
}

static void ball(void)
{
    fs_particles p;
    zb_lattice(&p, zb_ball_site);
    double pmax = 0, vmax = 0;
    for (size_t i = 0; i < p.n; i++) pmax = fmax(pmax, sqrt(p.x[i] * p.x[i] + p.y[i] * p.y[i] + p.z[i] * p.z[i]));
    fs_trimesh m;
    if (build(&p, &m)) return;
    for (size_t v = 0; v < m.nv; v++) {
        const float *x = m.pos + 3 * v;
        vmax = fmax(vmax, sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
    }
    double w = worst_phi(&p, &m), vol = fs_trimesh_volume6(&m) / 6 / (R_ * R_ * R_);
    printf(
        "ball: %zu vertices, largest |phi| %.4f r, farthest vertex %.4f r (outermost centre %.4f r), volume %.0f r^3\n",
        m.nv, w, vmax / R_, pmax / R_, vol);
    CHECK(w < 0.01, "ball: a vertex at |phi| = %.4f r", w);
    CHECK(vmax <= pmax + R_, "ball: a vertex %.4f r out, beyond the outermost centre + r", vmax / R_);
    CHECK(vol > 0.5 * 619 * 8, "ball: volume %.0f r^3, under half the particles' %d", vol, 619 * 8);
    fs_trimesh_free(&m);
    fs_particles_free(&p);
}

int main(void)
{
    slab();
    ball();
    TEST_DONE();
}
