/* The C API as a program links it (libfluidsurf.so, include/fluidsurf/fluidsurf.h):
 * fluidsurf_mesh_build on a ball of particles is a closed mesh around the ball's
 * surface with unit outward normals; its parameters and the library's messages
 * (settings named as written, the valid names listed, no command-line flags);
 * in a scene with solids, metrics that leave out what the solids hide.
 * In a build without OpenVDB the mesh is refused in one line. */
#include "fluidsurf/fluidsurf.h"
#include "fs_test.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define R 0.025f
#define BALL (8 * R) /* the ball's particles lie within BALL of the origin */

/* A ball of particles on a lattice of spacing 2r: n of them into x, y, z. */
static size_t ball(float *x, float *y, float *z)
{
    size_t n = 0;
    for (int i = -4; i <= 4; i++)
        for (int j = -4; j <= 4; j++)
            for (int k = -4; k <= 4; k++) {
                float p[3] = {2 * R * i, 2 * R * j, 2 * R * k};
                if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > BALL * BALL * 1.0001f) continue;
                x[n] = p[0], y[n] = p[1], z[n] = p[2], n++;
            }
    return n;
}

#if FS_WITH_OPENVDB
static int cmp_edge(const void *a, const void *b)
{
    uint64_t u = *(const uint64_t *)a, v = *(const uint64_t *)b;
    return u < v ? -1 : u > v;
}

/* Every edge in exactly two triangles, once each way (closed and consistently wound). */
static int closed(const uint32_t *tri, size_t nt)
{
    uint64_t *e = malloc(3 * nt * sizeof *e);
    if (!e) return 0;
    for (size_t t = 0; t < nt; t++)
        for (int k = 0; k < 3; k++) e[3 * t + k] = (uint64_t)tri[3 * t + k] << 32 | tri[3 * t + (k + 1) % 3];
    qsort(e, 3 * nt, sizeof *e, cmp_edge);
    int ok = nt > 0;
    for (size_t i = 0; i < 3 * nt && ok; i++) {
        uint64_t rev = e[i] << 32 | e[i] >> 32, *hit = bsearch(&rev, e, 3 * nt, sizeof *e, cmp_edge);
        ok = (i + 1 == 3 * nt || e[i + 1] != e[i]) && hit;
    }
    free(e);
    return ok;
}

static void mesh_of_ball(fluidsurf_scene *s, fluidsurf_particles *p)
{
    fluidsurf_mesh *m = NULL;
    int rc = fluidsurf_mesh_build(s, p, NULL, 0, &m);
    CHECK(rc == FLUIDSURF_OK && m, "mesh: %s", fluidsurf_last_error());
    if (rc) return;
    size_t nv = fluidsurf_mesh_vertex_count(m), nt = fluidsurf_mesh_triangle_count(m);
    const float *v = fluidsurf_mesh_vertices(m), *n = fluidsurf_mesh_normals(m);
    const uint32_t *tri = fluidsurf_mesh_triangles(m);
    CHECK(nv > 100 && nt > 100 && v && n && tri, "a mesh: %zu vertices, %zu triangles", nv, nt);
    CHECK(fluidsurf_mesh_radius(m) == R, "built with r = %g", fluidsurf_mesh_radius(m));
    size_t bad_index = 0, bad_normal = 0;
    for (size_t i = 0; i < 3 * nt; i++) bad_index += tri[i] >= nv;
    double lo = 1e9, hi = 0;
    for (size_t i = 0; i < nv; i++) {
        const float *q = v + 3 * i, *d = n + 3 * i;
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), rad = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        double out = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / (rad * len);
        bad_normal += !(fabs(len - 1) < 1e-4 && out > 0.5);
        lo = fmin(lo, rad), hi = fmax(hi, rad);
    }
    printf("ball of radius %g: %zu vertices, %zu triangles, vertices at %.4f..%.4f\n", BALL, nv, nt, lo, hi);
    CHECK(bad_index == 0, "%zu triangle corners index no vertex", bad_index);
    CHECK(bad_normal == 0, "%zu normals are not unit or do not point outward", bad_normal);
    /* the iso-surface (iso 0.6) of a lattice ball lies within r of its outer particles'
     * centres (0.3 to 0.9 r inside them at the defaults: the lattice's terraces) */
    CHECK(lo > BALL - R && hi < BALL + R, "vertices within (%g, %g) of the centre: %g..%g", BALL - R, BALL + R, lo, hi);
    CHECK(closed(tri, nt), "closed: every edge in two triangles, once each way");
    fluidsurf_mesh_free(m);

    /* a finer cube gives more vertices; parameters are the mesh method's */
    const char *fine[] = {"cube=0.25"};
    rc = fluidsurf_mesh_build(s, p, fine, 1, &m);
    CHECK(rc == FLUIDSURF_OK && fluidsurf_mesh_vertex_count(m) > 3 * nv, "cube=0.25: %zu vertices against %zu",
          fluidsurf_mesh_vertex_count(m), nv);
    fluidsurf_mesh_free(m);
    const char *bad[] = {"nosuch=1"};
    m = (fluidsurf_mesh *)1;
    rc = fluidsurf_mesh_build(s, p, bad, 1, &m);
    const char *msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT && m == NULL && strstr(msg, "mesh.nosuch=1: mesh has no parameter 'nosuch'") &&
              strstr(msg, "cube, smooth") && !strstr(msg, "--"),
          "an unknown parameter named, the valid ones listed: %s", msg);
}

#endif

/* Messages of the library name what the caller wrote, never a command-line flag. */
static void messages(fluidsurf_scene *s, fluidsurf_particles *p)
{
    fluidsurf_image *im = NULL;
    const char *value[] = {"normals=zz"};
    int rc = fluidsurf_render(s, p, "raycast_pca", value, 1, &im);
    const char *msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT && !strcmp(msg, "raycast_pca.normals: 'zz' is not one of basic|pca|blend"),
          "a bad value: %s", msg);
    rc = fluidsurf_render(s, p, "nosuch", NULL, 0, &im);
    msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT && strstr(msg, "unknown method 'nosuch' (methods: ") && strstr(msg, "reference") &&
              strstr(msg, "raycast_pca"),
          "an unknown method, the methods listed: %s", msg);
    /* a scene's setting is parsed once, when it is set: refused there, and not stored */
    rc = fluidsurf_scene_set(s, "reference.nosuch=1");
    msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT &&
              strstr(msg, "reference.nosuch=1: reference has no parameter 'nosuch' (its parameters: step_min,") &&
              !strstr(msg, "--"),
          "a scene's unknown setting: %s", msg);
    CHECK(fluidsurf_render(s, p, "reference", NULL, 0, &im) == FLUIDSURF_OK, "the refused setting was not kept: %s",
          fluidsurf_last_error());
    fluidsurf_image_free(im);
}

/* An image made from im's core layers alone: what the metrics saw before images
 * carried the solids' depth. */
static fluidsurf_image *without_solids(const fluidsurf_image *im)
{
    fluidsurf_image *out = NULL;
    int w = fluidsurf_image_width(im), h = fluidsurf_image_height(im);
    fluidsurf_image_from_arrays(w, h, fluidsurf_image_layer(im, "depth", NULL),
                                fluidsurf_image_layer(im, "normal", NULL), fluidsurf_image_layer(im, "thickness", NULL),
                                fluidsurf_image_layer(im, "coverage", NULL), fluidsurf_image_layer(im, "rgba", NULL),
                                fluidsurf_image_radius(im), &out);
    return out;
}

/* A scene with solids: its images carry the layer solid_depth, and the metrics
 * leave out the pixels a solid hides, as compare does (old and new numbers printed). */
static void metrics_mask_solids(fluidsurf_particles *p)
{
    const char *path = "test_api_solids.json"; /* a rod through the ball along each axis, out of it on both sides;
                                                   * the particles are the caller's, never read from the file */
    FILE *f = fopen(path, "w");
    if (f)
        fprintf(
            f,
            "{\"particles\": \"unused.bgeo\", \"obstacles\": [{\"min\": [-0.04, -0.04, -0.5], \"max\": [0.04, 0.04, 0.5]},"
            " {\"min\": [-0.5, -0.04, -0.04], \"max\": [0.5, 0.04, 0.04]},"
            " {\"min\": [-0.04, -0.5, -0.04], \"max\": [0.04, 0.5, 0.04]}]}\n"),
            fclose(f);
    fluidsurf_scene *s = NULL;
    fluidsurf_image *a = NULL, *b = NULL;
    int rc = fluidsurf_scene_load(path, &s);
    if (!rc) rc = fluidsurf_scene_set_radius(s, R);
    if (!rc) rc = fluidsurf_scene_set_size(s, 96, 96);
    if (!rc) rc = fluidsurf_render(s, p, "reference", (const char *[]){"supersample=2"}, 1, &a);
    if (!rc) rc = fluidsurf_render(s, p, "reference", NULL, 0, &b);
    CHECK(rc == FLUIDSURF_OK, "renders in a scene with solids: %s", rc ? fluidsurf_last_error() : "");
    remove(path);
    if (rc) return;
    int nc = 0;
    CHECK(fluidsurf_image_layer(b, "solid_depth", &nc) && nc == 1, "the image carries the solids' depth");
    fluidsurf_image *a0 = without_solids(a), *b0 = without_solids(b);
    fluidsurf_metrics now, old;
    CHECK(fluidsurf_metrics_compute(a, b, 0, &now) == FLUIDSURF_OK &&
              fluidsurf_metrics_compute(a0, b0, 0, &old) == FLUIDSURF_OK,
          "metrics: %s", fluidsurf_last_error());
    printf("     n_union, n_both, normal_mean_deg: masked %zu, %zu, %g; unmasked (before) %zu, %zu, %g\n", now.n_union,
           now.n_both, now.normal_mean_deg, old.n_union, old.n_both, old.normal_mean_deg);
    CHECK(now.n_both > 0 && now.n_both < old.n_both && now.n_union < old.n_union, "the solids' pixels are left out");
    fluidsurf_image_free(a0), fluidsurf_image_free(b0), fluidsurf_image_free(a), fluidsurf_image_free(b);
    fluidsurf_scene_free(s);
}

int main(void)
{
    CHECK(fluidsurf_api_version() >= 3 && FLUIDSURF_API_VERSION >= 3, "API version 3 or later: %d",
          fluidsurf_api_version());
    static float x[1000], y[1000], z[1000];
    size_t n = ball(x, y, z);
    fluidsurf_particles *p = NULL;
    fluidsurf_scene *s = NULL;
    if (fluidsurf_particles_wrap(n, x, y, z, &p) || fluidsurf_scene_new(&s) || fluidsurf_scene_set_radius(s, R)) {
        fprintf(stderr, "set-up: %s\n", fluidsurf_last_error());
        return 1;
    }
#if FS_WITH_OPENVDB
    mesh_of_ball(s, p);
#else
    fluidsurf_mesh *m = (fluidsurf_mesh *)1;
    int rc = fluidsurf_mesh_build(s, p, NULL, 0, &m);
    CHECK(rc == FLUIDSURF_ERR_INPUT && m == NULL && strstr(fluidsurf_last_error(), "FS_WITH_OPENVDB=ON") &&
              !strchr(fluidsurf_last_error(), '\n'),
          "refused in one line naming the option: %s", fluidsurf_last_error());
#endif
    messages(s, p);
    metrics_mask_solids(p);
    fluidsurf_scene_free(s);
    fluidsurf_particles_free(p);
    TEST_DONE();
}
