/* The C API's version-6 calls as a program links them: metrics that refuse what
 * `fluidsurf diff` refuses (fluidsurf_metrics_compute3), an EXR's provenance and
 * camera read back and rendered again bit for bit, images and meshes written with
 * their provenance, and `fluidsurf info`'s numbers of a particle set; version 7's
 * point arrays of a file read. */
#include "fluidsurf/fluidsurf.h"
#include "api_slab.h"
#include "fs_test.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define R 0.025f
#define OUT FS_TEST_OUT "/test_api_io"

/* A slab of particles on a lattice of spacing 2r: n of them into x, y, z. */
static size_t slab(float *x, float *y, float *z) { return api_slab(x, y, z, 10, 4, 8, R, 0); }

/* A render of p with r radius (0: estimated) and the up axis up, w x 32 pixels, through
 * cam (NULL: framed); NULL on failure. */
static fluidsurf_image *render_cam(fluidsurf_particles *p, double radius, const char *up, int w, const char *method,
                                   const fluidsurf_camera *cam)
{
    fluidsurf_scene *s = NULL;
    fluidsurf_image *im = NULL;
    int rc = fluidsurf_scene_new(&s);
    if (!rc && radius > 0) rc = fluidsurf_scene_set_radius(s, radius);
    if (!rc) rc = fluidsurf_scene_set_up(s, up);
    if (!rc) rc = fluidsurf_scene_set_size(s, w, 32);
    if (!rc && cam) rc = fluidsurf_scene_set_camera(s, cam);
    if (!rc) rc = fluidsurf_render(s, p, method, NULL, 0, &im);
    CHECK(!rc, "render: %s", fluidsurf_last_error());
    fluidsurf_scene_free(s);
    return im;
}

static fluidsurf_image *render(fluidsurf_particles *p, double radius, const char *up, int w, const char *method)
{
    return render_cam(p, radius, up, w, method, NULL);
}

/* compute3 of a against b: its return code, its warnings into warn. */
static int checked(const fluidsurf_image *a, const fluidsurf_image *b, int flags, char *warn, size_t size)
{
    fluidsurf_metrics m;
    return fluidsurf_metrics_compute3(a, b, 0, flags, &m, NULL, warn, size);
}

/* diff's rules: a different camera or size refused, a different r warned about
 * (refused under strict), images without provenance accepted; the old call unchanged. */
static void metrics_as_diff(fluidsurf_particles *p)
{
    fluidsurf_image *y = render(p, R, "y", 48, "spheres"), *z = render(p, R, "z", 48, "spheres");
    fluidsurf_camera cam;
    if (!y || !z || fluidsurf_image_camera(y, &cam)) return;
    fluidsurf_image *y2 = render_cam(p, 1.5 * R, "y", 48, "spheres", &cam), *small = render(p, R, "y", 40, "spheres");
    if (!y2 || !small) return;
    char warn[1200];
    int rc = checked(y, z, 0, warn, sizeof warn);
    const char *msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT && strstr(msg, "image and reference were rendered with different cameras (") &&
              strstr(msg, "they cannot be compared"),
          "two cameras refused: %s", msg);
    fluidsurf_metrics m;
    CHECK(fluidsurf_metrics_compute2(y, z, 0, &m, NULL) == FLUIDSURF_OK, "the old call measures them as before");
    rc = checked(small, y, 0, warn, sizeof warn);
    msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT &&
              !strcmp(msg, "image is 40x32 but reference is 48x32: images of different sizes cannot be compared"),
          "two sizes refused: %s", msg);
    rc = checked(y2, y, 0, warn, sizeof warn);
    CHECK(rc == FLUIDSURF_OK &&
              strstr(warn,
                     "image has r = 0.0375 but reference has r = 0.025; depth errors are in "
                     "the reference's r"),
          "another r warned about: %d, '%s' %s", rc, warn, rc ? fluidsurf_last_error() : "");
    rc = checked(y2, y, FLUIDSURF_METRICS_STRICT, warn, sizeof warn);
    msg = fluidsurf_last_error();
    CHECK(rc == FLUIDSURF_ERR_INPUT && strstr(msg, "(refused under strict)"), "strict refuses it: %s", msg);
    rc = checked(y, y, FLUIDSURF_METRICS_STRICT, warn, sizeof warn);
    CHECK(rc == FLUIDSURF_OK && !warn[0], "an image against itself: no word (%s)", warn);
    CHECK(checked(y, z, 16, warn, sizeof warn) == FLUIDSURF_ERR_INPUT, "unknown flags refused");
    /* arrays without provenance: only what both carry is checked */
    fluidsurf_image *bare = NULL;
    fluidsurf_image_from_arrays(48, 32, fluidsurf_image_layer(z, "depth", NULL),
                                fluidsurf_image_layer(z, "normal", NULL), NULL,
                                fluidsurf_image_layer(z, "coverage", NULL), NULL, R, &bare);
    rc = checked(bare, y, FLUIDSURF_METRICS_STRICT, warn, sizeof warn);
    CHECK(rc == FLUIDSURF_OK && !warn[0], "an image of arrays is accepted: %s", rc ? fluidsurf_last_error() : warn);
    rc = fluidsurf_image_set_provenance(bare, "fluidsurf:camera", "eye=1,2");
    CHECK(rc == FLUIDSURF_ERR_INPUT && strstr(fluidsurf_last_error(), "eye=1,2"), "a malformed camera refused: %s",
          fluidsurf_last_error());
    CHECK(fluidsurf_image_set_provenance(bare, "camera", "x") == FLUIDSURF_ERR_INPUT &&
              fluidsurf_image_set_provenance(bare, "fluidsurf:a", "two\nlines") == FLUIDSURF_ERR_INPUT,
          "a name without fluidsurf: and a value of two lines refused");
    for (int i = 0; i < fluidsurf_image_provenance_count(z); i++) /* z's provenance: now it is z's camera */
        fluidsurf_image_set_provenance(bare, fluidsurf_image_provenance_name(z, i),
                                       fluidsurf_image_provenance_value(z, i));
    CHECK(checked(bare, y, 0, warn, sizeof warn) == FLUIDSURF_ERR_INPUT, "with z's provenance it is refused");
    fluidsurf_image_free(bare), fluidsurf_image_free(y), fluidsurf_image_free(z), fluidsurf_image_free(y2);
    fluidsurf_image_free(small);
}

/* 1 when the float arrays a and b of n values hold the same bits. */
static int same_bits(const float *a, const float *b, size_t n) { return a && b && !memcmp(a, b, n * sizeof *a); }

/* A rendered image written as EXR and read back: the provenance, r and camera as
 * rendered, and that camera renders the same image again, bit for bit. */
static void exr_round_trip(fluidsurf_particles *p)
{
    fluidsurf_image *a = render(p, R, "auto", 40, "raycast_pca"), *back = NULL, *again = NULL;
    if (!a) return;
    int rc = fluidsurf_image_write(a, OUT ".exr");
    if (!rc) rc = fluidsurf_image_read(OUT ".exr", &back);
    CHECK(!rc, "write and read: %s", fluidsurf_last_error());
    if (rc) return;
    int same = 0, n = fluidsurf_image_provenance_count(a);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < fluidsurf_image_provenance_count(back); j++)
            same += !strcmp(fluidsurf_image_provenance_name(a, i), fluidsurf_image_provenance_name(back, j)) &&
                !strcmp(fluidsurf_image_provenance_value(a, i), fluidsurf_image_provenance_value(back, j));
    CHECK(n > 10 && same == n, "the file's provenance is the render's: %d of %d entries", same, n);
    fluidsurf_camera ca, cb;
    CHECK(!fluidsurf_image_camera(a, &ca) && !fluidsurf_image_camera(back, &cb), "both have a camera: %s",
          fluidsurf_last_error());
    CHECK(!memcmp(ca.eye, cb.eye, sizeof ca.eye) && !memcmp(ca.target, cb.target, sizeof ca.target) &&
              !memcmp(ca.up, cb.up, sizeof ca.up) && ca.fov_deg == cb.fov_deg && cb.width == 40 && cb.height == 32,
          "the camera read back exactly");
    CHECK(fluidsurf_image_radius(back) == fluidsurf_image_radius(a), "r read back");
    again = render_cam(p, fluidsurf_image_radius(back), "auto", cb.width, "raycast_pca", &cb);
    size_t px = 40 * 32;
    CHECK(again &&
              same_bits(fluidsurf_image_layer(again, "depth", NULL), fluidsurf_image_layer(a, "depth", NULL), px) &&
              same_bits(fluidsurf_image_layer(again, "rgba", NULL), fluidsurf_image_layer(a, "rgba", NULL), 4 * px),
          "rendered again through the file's camera: the same bits");
    CHECK(fluidsurf_image_write(a, OUT ".png") == FLUIDSURF_OK, "a PNG: %s", fluidsurf_last_error());
    CHECK(fluidsurf_image_write(a, OUT ".tif") == FLUIDSURF_ERR_INPUT, "another extension refused");
    float layer[40 * 32] = {0};
    CHECK(fluidsurf_image_set_layer(a, "depth", 1, layer) == FLUIDSURF_ERR_INPUT, "a core layer refused");
    CHECK(fluidsurf_image_set_layer(back, "extra", 1, layer) == FLUIDSURF_OK &&
              fluidsurf_image_layer(back, "extra", NULL),
          "a layer added: %s", fluidsurf_last_error());
    fluidsurf_image *bare = NULL;
    fluidsurf_image_from_arrays(40, 32, layer, fluidsurf_image_layer(a, "normal", NULL), NULL, layer, NULL, R, &bare);
    CHECK(fluidsurf_image_write(bare, OUT "_bare.exr") == FLUIDSURF_ERR_INPUT && access(OUT "_bare.exr", F_OK) != 0,
          "an image without rgba is refused, no file left: %s", fluidsurf_last_error());
    fluidsurf_image_free(bare), fluidsurf_image_free(a), fluidsurf_image_free(back), fluidsurf_image_free(again);
}

/* The text of a file (NULL when it cannot be read), NUL-terminated. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    char *s = malloc(n + 1);
    if (s && fread(s, 1, n, f) != (size_t)n) free(s), s = NULL;
    if (s) s[n] = 0;
    fclose(f);
    return s;
}

/* path holds text (a binary file's header too: searched up to its first NUL). */
static int file_has(const char *path, const char *text)
{
    char *s = slurp(path);
    int found = s && strstr(s, text);
    free(s);
    return found;
}

#if FS_WITH_OPENVDB
/* A built mesh carries its provenance into every format; a mesh of arrays gets normals. */
static void meshes(fluidsurf_particles *p)
{
    fluidsurf_scene *s = NULL;
    fluidsurf_mesh *m = NULL;
    int rc = fluidsurf_scene_new(&s);
    if (!rc) rc = fluidsurf_scene_set_radius(s, R);
    if (!rc) rc = fluidsurf_mesh_build(s, p, (const char *[]){"cube=0.75"}, 1, &m);
    CHECK(!rc, "mesh: %s", fluidsurf_last_error());
    if (rc) return;
    const char *method = NULL, *params = NULL;
    for (int i = 0; i < fluidsurf_mesh_provenance_count(m); i++) {
        if (!strcmp(fluidsurf_mesh_provenance_name(m, i), "fluidsurf:method"))
            method = fluidsurf_mesh_provenance_value(m, i);
        if (!strcmp(fluidsurf_mesh_provenance_name(m, i), "fluidsurf:params"))
            params = fluidsurf_mesh_provenance_value(m, i);
    }
    CHECK(method && !strcmp(method, "mesh") && params && strstr(params, "cube=0.75"),
          "provenance: method %s, params %s", method ? method : "-", params ? params : "-");
    static const char *const ext[] = {".ply", ".obj", ".vtk", ".vtp"};
    for (int k = 0; k < 4; k++) {
        char path[512];
        snprintf(path, sizeof path, OUT "%s", ext[k]);
        rc = fluidsurf_mesh_write(m, path);
        /* .vtp's values are in its zlib-compressed appended data: only the array names show */
        CHECK(!rc && file_has(path, "fluidsurf:params") && (k == 3 || file_has(path, "cube=0.75")),
              "%s carries the provenance: %s", path, rc ? fluidsurf_last_error() : "");
    }
    CHECK(fluidsurf_mesh_write(m, OUT ".stl") == FLUIDSURF_ERR_INPUT, "an unknown format refused");
    fluidsurf_mesh_free(m);
    fluidsurf_scene_free(s);
    /* a tetrahedron of the caller's, wound outward, normals from its faces */
    const float v[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t t[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}, bad[] = {0, 1, 4};
    rc = fluidsurf_mesh_from_arrays(4, v, NULL, 4, t, &m);
    CHECK(!rc, "a mesh of arrays: %s", fluidsurf_last_error());
    const float *nrm = rc ? NULL : fluidsurf_mesh_normals(m);
    CHECK(nrm && nrm[0] < 0 && nrm[1] < 0 && nrm[2] < 0 &&
              fabsf(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2] - 1) < 1e-5,
          "the corner at the origin's normal points out of the tetrahedron");
    CHECK(!fluidsurf_mesh_set_provenance(m, "fluidsurf:note", "made by hand") &&
              !fluidsurf_mesh_write(m, OUT "_tet.ply") &&
              file_has(OUT "_tet.ply", "comment fluidsurf:note=made by hand\n"),
          "its provenance written: %s", fluidsurf_last_error());
    fluidsurf_mesh_free(m);
    m = (fluidsurf_mesh *)1;
    rc = fluidsurf_mesh_from_arrays(4, v, NULL, 1, bad, &m);
    CHECK(rc == FLUIDSURF_ERR_INPUT && !m && strstr(fluidsurf_last_error(), "triangle 0 names vertex 4 of 4"),
          "a bad index refused: %s", fluidsurf_last_error());
}
#endif

/* `fluidsurf info`'s numbers: the spacing's r is the r a render without one uses. */
static void particle_stats(fluidsurf_particles *p, size_t n)
{
    double est = 0;
    fluidsurf_particles_info in;
    int rc = fluidsurf_particles_estimate_radius(p, &est);
    /* 4 layers thick: most particles' neighbour balls reach out of the slab, and it reads high */
    CHECK(!rc && est > R && est < 1.2 * R, "the lattice of spacing 2r gives about r: %g", est);
    fluidsurf_image *im = render(p, 0, "auto", 16, "spheres");
    CHECK(im && fluidsurf_image_radius(im) == (float)est, "a render without r uses it: %g", fluidsurf_image_radius(im));
    fluidsurf_image_free(im);
    rc = fluidsurf_particles_stats(p, 0, 1, &in);
    CHECK(!rc && in.count == n && in.radius == (float)est && in.radius_source == FLUIDSURF_R_ESTIMATED &&
              in.bbox_min[0] == 0 && fabs(in.bbox_max[0] - 18 * R) < 1e-6 && fabs(in.nn_median - 2 * R) < 1e-6,
          "stats: %zu particles, r %g (source %d), nn %g", in.count, in.radius, in.radius_source, in.nn_median);
    rc = fluidsurf_particles_stats(p, 2 * R, 1, &in);
    CHECK(!rc && in.radius == 2 * R && in.radius_source == FLUIDSURF_R_GIVEN && in.estimated_radius == (float)est,
          "a given r is used, the estimate still said");
    CHECK(fluidsurf_particles_stats(p, -1, 1, &in) == FLUIDSURF_ERR_INPUT &&
              fluidsurf_particles_stats(p, 0, 0, &in) == FLUIDSURF_ERR_INPUT,
          "a negative r and a zero volume_scale refused");
    static float zero[8];
    fluidsurf_particles *pile = NULL;
    fluidsurf_particles_wrap(8, zero, zero, zero, &pile);
    rc = fluidsurf_particles_estimate_radius(pile, &est);
    CHECK(rc == FLUIDSURF_ERR_INPUT, "no spacing, no estimate: %s", fluidsurf_last_error());
    fluidsurf_particles_free(pile);
}

/* Version 7: the DualSPHysics crop's Idp and Rhop, as `fluidsurf info` lists them;
 * none on wrapped arrays (p). */
static void point_arrays(const fluidsurf_particles *p)
{
    CHECK(fluidsurf_particles_array_count(p) == 0 && !fluidsurf_particles_array(p, 0, NULL, NULL, NULL),
          "wrapped arrays have no point arrays");
    fluidsurf_particles *f = NULL;
    int rc = fluidsurf_particles_read(FS_TEST_DATA "/dualsphysics/dambreak200k_t0.300_crop902.vtk", NULL, &f);
    CHECK(!rc && fluidsurf_particles_count(f) == 902 && fluidsurf_particles_array_count(f) == 2,
          "the crop read with its 2 arrays: %s", rc ? fluidsurf_last_error() : "");
    if (rc) return;
    const char *name[2];
    int ncomp[2], type[2];
    const uint32_t *idp = fluidsurf_particles_array(f, 0, &name[0], &ncomp[0], &type[0]);
    const float *rhop = fluidsurf_particles_array(f, 1, &name[1], &ncomp[1], &type[1]);
    CHECK(idp && rhop && !strcmp(name[0], "Idp") && !strcmp(name[1], "Rhop") && ncomp[0] == 1 && ncomp[1] == 1 &&
              type[0] == FLUIDSURF_ARRAY_U32 && type[1] == FLUIDSURF_ARRAY_F32,
          "Idp (1 x uint32) and Rhop (1 x float32)");
    size_t bad = 0, same = 0;
    for (size_t i = 0; idp && rhop && i < 902; i++)
        bad += !(rhop[i] >= 853 && rhop[i] <= 1087), same += i && idp[i] == idp[i - 1];
    CHECK(idp && rhop && !bad && !same, "densities in 853-1087 (%zu not), ids not repeated (%zu)", bad, same);
    CHECK(!fluidsurf_particles_array(f, 2, &name[0], NULL, NULL) && !name[0] &&
              !fluidsurf_particles_array(f, -1, NULL, NULL, NULL),
          "an index out of range gives NULL");
    fluidsurf_particles_free(f);
}

int main(void)
{
    CHECK(fluidsurf_api_version() >= 6 && FLUIDSURF_API_VERSION >= 6, "API version 6: %d", fluidsurf_api_version());
    static float x[400], y[400], z[400];
    size_t n = slab(x, y, z);
    fluidsurf_particles *p = NULL;
    if (fluidsurf_particles_wrap(n, x, y, z, &p)) {
        fprintf(stderr, "set-up: %s\n", fluidsurf_last_error());
        return 1;
    }
    metrics_as_diff(p);
    exr_round_trip(p);
#if FS_WITH_OPENVDB
    meshes(p);
#endif
    particle_stats(p, n);
    point_arrays(p);
    fluidsurf_particles_free(p);
    TEST_DONE();
}
