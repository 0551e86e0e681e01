/* The scene functions of the C API that nothing else exercises: a copy is
 * independent of its original; the field and camera read back what was set; a
 * setting changes the render it applies to; a scene file's frames are read one
 * by one. */
#include "fluidsurf/fluidsurf.h"
#include "fs_test.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define R 0.025f

static size_t slab(float *x, float *y, float *z)
{
    size_t n = 0;
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 8; k++) x[n] = 2 * R * i, y[n] = 2 * R * j, z[n] = 2 * R * k, n++;
    return n;
}

/* Covered pixels of a render of method with its settings. */
static long covered(const fluidsurf_scene *s, const fluidsurf_particles *p, const char *method, const char *set)
{
    fluidsurf_image *im;
    const char *params[1] = {set};
    if (fluidsurf_render(s, p, method, set ? params : NULL, set ? 1 : 0, &im)) return -1;
    const float *cov = fluidsurf_image_layer(im, "coverage", NULL);
    long n = 0;
    for (int i = 0; i < fluidsurf_image_width(im) * fluidsurf_image_height(im); i++) n += cov[i] >= 0.5f;
    fluidsurf_image_free(im);
    return n;
}

static void field_and_copy(void)
{
    fluidsurf_scene *s, *c;
    fluidsurf_field f;
    CHECK(!fluidsurf_scene_new(&s) && !fluidsurf_scene_get_field(s, &f), "get_field: %s", fluidsurf_last_error());
    f.radius = 0.03, f.iso = 0.4, f.support = 3, f.volume_scale = 1.1;
    snprintf(f.kernel, sizeof f.kernel, "poly6");
    CHECK(!fluidsurf_scene_set_field(s, &f), "set_field: %s", fluidsurf_last_error());
    CHECK(!fluidsurf_scene_copy(s, &c), "copy");
    fluidsurf_field g = {0};
    CHECK(!fluidsurf_scene_get_field(c, &g) && fabs(g.radius - 0.03) < 1e-7 && fabs(g.iso - 0.4) < 1e-7 &&
              fabs(g.support - 3) < 1e-7 && fabs(g.volume_scale - 1.1) < 1e-7 && !strcmp(g.kernel, "poly6"),
          "the copy has the field set: r %g iso %g support %g V %g %s", g.radius, g.iso, g.support, g.volume_scale,
          g.kernel);
    f.iso = 0.7;
    CHECK(!fluidsurf_scene_set_field(s, &f) && !fluidsurf_scene_get_field(c, &g) && fabs(g.iso - 0.4) < 1e-7,
          "changing the original leaves the copy as it was (iso %g)", g.iso);
    snprintf(f.kernel, sizeof f.kernel, "gauss");
    CHECK(fluidsurf_scene_set_field(s, &f) == FLUIDSURF_ERR_INPUT && strstr(fluidsurf_last_error(), "gauss"),
          "an unknown kernel is refused: %s", fluidsurf_last_error());
    fluidsurf_scene_free(s);
    fluidsurf_scene_free(c);
}

static void camera_and_set(void)
{
    static float x[192], y[192], z[192];
    fluidsurf_particles *p;
    fluidsurf_scene *s;
    fluidsurf_camera cam;
    int placed = -1;
    CHECK(!fluidsurf_particles_wrap(slab(x, y, z), x, y, z, &p) && !fluidsurf_scene_new(&s), "scene");
    CHECK(!fluidsurf_scene_set_radius(s, R) && !fluidsurf_scene_get_camera(s, &cam, &placed) && placed == 0,
          "framed until placed");
    fluidsurf_camera want = {{0.2, 1.2, 0.9}, {0.2, 0, 0.2}, {0, 1, 0}, 35, 40, 30};
    CHECK(!fluidsurf_scene_set_camera(s, &want) && !fluidsurf_scene_get_camera(s, &cam, &placed) && placed == 1 &&
              cam.width == 40 && cam.height == 30 && fabs(cam.fov_deg - 35) < 1e-6 && fabs(cam.eye[1] - 1.2) < 1e-6,
          "get_camera reads back the placed camera");
    long plain = covered(s, p, "spheres", NULL), small = covered(s, p, "spheres", "radius_scale=0.5");
    CHECK(!fluidsurf_scene_set(s, "spheres.radius_scale=0.5"), "set: %s", fluidsurf_last_error());
    long via_scene = covered(s, p, "spheres", NULL);
    CHECK(plain > 0 && small < plain && via_scene == small,
          "a scene setting changes the render as a render parameter does (%ld %ld %ld)", plain, small, via_scene);
    fluidsurf_scene_free(s);
    fluidsurf_particles_free(p);
}

static void frames(void)
{
    char dir[] = "/tmp/fs_api_sceneXXXXXX", path[256];
    CHECK(mkdtemp(dir) != NULL, "temporary folder");
    snprintf(path, sizeof path, "%s/s.json", dir);
    FILE *f = fopen(path, "w");
    fprintf(
        f,
        "{\"particles\": {\"synthetic\": \"slab\", \"size\": [4, 2, 4], \"jitter\": 0.1, \"first\": 2, \"last\": 4}, \"radius\": 0.025}\n");
    fclose(f);
    fluidsurf_scene *s;
    int first = -1, last = -1;
    CHECK(!fluidsurf_scene_load(path, &s) && !fluidsurf_scene_frames(s, &first, &last) && first == 2 && last == 4,
          "frames %d..%d", first, last);
    fluidsurf_particles *a = NULL, *b = NULL;
    CHECK(!fluidsurf_scene_read_frame(s, 2, &a) && !fluidsurf_scene_read_frame(s, 3, &b), "read_frame: %s",
          fluidsurf_last_error());
    const float *xa = a ? fluidsurf_particles_column(a, "x", NULL) : NULL,
                *xb = b ? fluidsurf_particles_column(b, "x", NULL) : NULL;
    CHECK(xa && xb && fluidsurf_particles_count(a) == fluidsurf_particles_count(b) &&
              fluidsurf_particles_count(a) > 0 && xa[0] != xb[0],
          "two frames: the same particles, re-jittered");
    fluidsurf_particles_free(a);
    fluidsurf_particles_free(b);
    fluidsurf_scene_free(s);
    unlink(path);
    rmdir(dir);
}

int main(void)
{
    field_and_copy();
    camera_and_set();
    frames();
    TEST_DONE();
}
