/* The scene functions of the C API that nothing else exercises: a copy is
 * independent of its original; the field and camera read back what was set; a
 * setting changes the render it applies to; a scene file's frames are read one
 * by one. The command line's camera, frame and scene-file options (version 8,
 * issue 54): --camera's text and an up of 0 follow the scene's up axis (a z-up
 * scene stands upright); a frame pattern with FIRST:LAST:STEP is the scene's
 * source, compared frame by frame; fluidsurf_scene_save writes a scene that
 * renders the same image and saves back to the same bytes. */
#include "fluidsurf/fluidsurf.h"
#include "api_slab.h"
#include "fs_test.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define R 0.025f

static size_t slab(float *x, float *y, float *z) { return api_slab(x, y, z, 8, 3, 8, R, 0); }

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

static const char *cube = FS_TEST_DATA "/splashsurf/cube_2366_particles.vtk";
static const char *column = FS_TEST_DATA "/splashsurf/hilbert2_7954_particles.vtk";
static char tmp[] = "/tmp/fs_api_scene_fileXXXXXX";

/* A new scene reading path (a file) at w x h, and its frame 0 in *p. */
static fluidsurf_scene *scene_of(const char *path, int w, int h, fluidsurf_particles **p)
{
    fluidsurf_scene *s = NULL;
    CHECK(!fluidsurf_scene_new(&s) && !fluidsurf_scene_set_source(s, path, 0, 0, 0) &&
              !fluidsurf_scene_set_size(s, w, h) && !fluidsurf_scene_read_frame(s, 0, p),
          "a scene reading %s: %s", path, fluidsurf_last_error());
    return s;
}

/* The up of the camera a reference render of s on p used. */
static void rendered_up(const fluidsurf_scene *s, const fluidsurf_particles *p, double up[3])
{
    fluidsurf_image *im = NULL;
    fluidsurf_camera c;
    memset(&c, 0, sizeof c);
    CHECK(!fluidsurf_reference(s, p, &im) && !fluidsurf_image_camera(im, &c), "render: %s", fluidsurf_last_error());
    for (int i = 0; i < 3; i++) up[i] = c.up[i];
    fluidsurf_image_free(im);
}

static void camera_up(void)
{
    fluidsurf_particles *p;
    fluidsurf_scene *s = scene_of(column, 16, 16, &p);
    double up[3];
    CHECK(!fluidsurf_scene_set_up(s, "z") && !fluidsurf_scene_set_camera_text(s, "eye=3,2,1;target=0,0,0.5"),
          "camera text: %s", fluidsurf_last_error());
    rendered_up(s, p, up);
    CHECK(up[0] == 0 && up[1] == 0 && up[2] == 1, "a camera text without up= has the scene's up, z: %g,%g,%g", up[0],
          up[1], up[2]);
    fluidsurf_camera c = {{3, 2, 1}, {0, 0, 0.5}, {0, 0, 0}, 40, 16, 16};
    CHECK(!fluidsurf_scene_set_camera(s, &c), "set_camera: %s", fluidsurf_last_error());
    rendered_up(s, p, up);
    CHECK(up[0] == 0 && up[1] == 0 && up[2] == 1, "a camera with up 0 has the scene's up, z: %g,%g,%g", up[0], up[1],
          up[2]);
    CHECK(!fluidsurf_scene_set_camera_text(s, "eye=3,2,1;target=0,0,0.5;up=x;fov=30;size=20x10"), "up=x: %s",
          fluidsurf_last_error());
    int placed = 0;
    CHECK(!fluidsurf_scene_get_camera(s, &c, &placed) && placed && c.up[0] == 1 && c.fov_deg == 30 && c.width == 20 &&
              c.height == 10,
          "up=x, fov and size as given: up %g,%g,%g fov %g %dx%d", c.up[0], c.up[1], c.up[2], c.fov_deg, c.width,
          c.height);
    CHECK(fluidsurf_scene_set_camera_text(s, "eye=1,2,3") == FLUIDSURF_ERR_INPUT &&
              strstr(fluidsurf_last_error(), "target") && !fluidsurf_scene_get_camera(s, &c, &placed) && c.up[0] == 1 &&
              c.width == 20,
          "a text without target is refused, the camera kept: %s", fluidsurf_last_error());
    fluidsurf_scene_free(s);
    fluidsurf_particles_free(p);
}

/* Rows of frame f (",f,") in a study's metrics table. */
static int rows_of_frame(const char *table, int f)
{
    char key[16];
    int n = 0;
    snprintf(key, sizeof key, ",%d,", f);
    for (const char *l = strchr(table, '\n'); l; l = strchr(l + 1, '\n'))
        if (!strncmp(l + 1, "spheres,", 8) && strstr(l + 1, key) && strstr(l + 1, key) < strchr(l + 1, '\n')) n++;
    return n;
}

static void pattern(void)
{
    char link[300], pat[300];
    for (int f = 1; f <= 3; f++) {
        snprintf(link, sizeof link, "%s/f_%04d.vtk", tmp, f);
        CHECK(!symlink(cube, link), "link %s", link);
    }
    snprintf(pat, sizeof pat, "%s/f_%%04d.vtk", tmp);
    fluidsurf_scene *s;
    int first = -1, last = -1;
    CHECK(!fluidsurf_scene_new(&s) && !fluidsurf_scene_set_source(s, pat, 1, 3, 2) &&
              !fluidsurf_scene_frames(s, &first, &last) && first == 1 && last == 3 &&
              !fluidsurf_scene_set_size(s, 16, 16),
          "a pattern's frames 1..3: %d..%d %s", first, last, fluidsurf_last_error());
    fluidsurf_study *st = NULL;
    CHECK(!fluidsurf_compare(s, NULL, 0, "spheres", NULL, 0, NULL, 0, 1, 0, &st), "compare: %s",
          fluidsurf_last_error());
    const char *m = st ? fluidsurf_study_table(st, "metrics") : "";
    CHECK(rows_of_frame(m, 1) == 1 && rows_of_frame(m, 3) == 1 && rows_of_frame(m, 2) == 0,
          "compare on frames 1:3:2 of the pattern: frames 1 and 3, not 2:\n%s", m);
    fluidsurf_study_free(st);
    CHECK(fluidsurf_scene_set_source(s, cube, 1, 2, 1) == FLUIDSURF_ERR_INPUT &&
              strstr(fluidsurf_last_error(), "not a frame pattern"),
          "frames of a plain file are refused: %s", fluidsurf_last_error());
    CHECK(fluidsurf_scene_set_source(s, pat, 3, 1, 1) == FLUIDSURF_ERR_INPUT &&
              fluidsurf_scene_set_source(s, pat, 1, 3, 0) == FLUIDSURF_ERR_INPUT,
          "last < first and step 0 are refused: %s", fluidsurf_last_error());
    fluidsurf_scene_free(s);
    for (int f = 1; f <= 3; f++) snprintf(link, sizeof link, "%s/f_%04d.vtk", tmp, f), unlink(link);
}

/* The whole file at path (NUL-terminated), or NULL. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = f ? calloc(1, 1 << 16) : NULL;
    if (buf && fread(buf, 1, (1 << 16) - 1, f) == 0) buf[0] = 0;
    if (f) fclose(f);
    return buf;
}

/* A reference render's depth and camera of s on p equal im's. */
static int same_render(const fluidsurf_scene *s, const fluidsurf_particles *p, const fluidsurf_image *im)
{
    fluidsurf_image *b = NULL;
    fluidsurf_camera ca, cb;
    int same = !fluidsurf_reference(s, p, &b) && !fluidsurf_image_camera(im, &ca) && !fluidsurf_image_camera(b, &cb) &&
        !memcmp(&ca, &cb, sizeof ca);
    int n = fluidsurf_image_width(im) * fluidsurf_image_height(im);
    const float *da = fluidsurf_image_layer(im, "depth", NULL),
                *db = same ? fluidsurf_image_layer(b, "depth", NULL) : 0;
    for (int i = 0; same && i < n; i++) same = da[i] == db[i] || (isinf(da[i]) && isinf(db[i]));
    fluidsurf_image_free(b);
    return same;
}

static void save(void)
{
    fluidsurf_particles *p, *q;
    fluidsurf_scene *s = scene_of(column, 24, 18, &p), *t = NULL;
    fluidsurf_image *im = NULL;
    char a[300], b[300];
    snprintf(a, sizeof a, "%s/a.json", tmp), snprintf(b, sizeof b, "%s/b.json", tmp);
    CHECK(!fluidsurf_reference(s, p, &im) && !fluidsurf_scene_save(s, p, a), "save: %s", fluidsurf_last_error());
    CHECK(!fluidsurf_scene_load(a, &t) && !fluidsurf_scene_read_frame(t, 0, &q), "load the saved scene: %s",
          fluidsurf_last_error());
    CHECK(t && im && same_render(t, q, im), "the saved scene renders the same camera and depth");
    CHECK(t && !fluidsurf_scene_save(t, q, b), "save again: %s", fluidsurf_last_error());
    char *ta = slurp(a), *tb = slurp(b);
    CHECK(ta && tb && !strcmp(ta, tb) && strstr(ta, "\"up\":\t\"z\""), "saved twice, the same bytes, up z:\n%s\n%s", ta,
          tb);
    free(ta), free(tb);
    unlink(b);
    fluidsurf_scene *bare;
    CHECK(!fluidsurf_scene_new(&bare) && fluidsurf_scene_save(bare, p, b) == FLUIDSURF_ERR_INPUT &&
              strstr(fluidsurf_last_error(), "no particle source"),
          "a scene without a source is refused: %s", fluidsurf_last_error());
    CHECK(fluidsurf_scene_save(s, NULL, b) == FLUIDSURF_ERR_INPUT && access(b, F_OK) != 0,
          "without the particles to settle on, refused: %s", fluidsurf_last_error());
    CHECK(fluidsurf_scene_save(s, p, "x.txt") == FLUIDSURF_ERR_INPUT && access("x.txt", F_OK) != 0,
          "a name without .json is refused, nothing written: %s", fluidsurf_last_error());
    fluidsurf_scene_free(bare);
    fluidsurf_image_free(im);
    fluidsurf_particles_free(q);
    fluidsurf_particles_free(p);
    fluidsurf_scene_free(t);
    fluidsurf_scene_free(s);
    unlink(a), unlink(b);
}

int main(void)
{
    CHECK(mkdtemp(tmp) != NULL, "temporary folder");
    field_and_copy();
    camera_and_set();
    frames();
    CHECK(FLUIDSURF_API_VERSION >= 8 && fluidsurf_api_version() >= 8, "API version 8: %d", fluidsurf_api_version());
    camera_up();
    pattern();
    save();
    rmdir(tmp);
    TEST_DONE();
}
