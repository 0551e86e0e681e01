/* Static obstacles: parsing, distance, ray hits, the shared shading's depth
 * compositing and refraction of a solid, and the metrics that leave out the
 * pixels a solid hides. */
#include "camera.h"
#include "fs_error.h"
#include "fs_test.h"
#include "gbuffer.h"
#include "obstacle_mask.h"
#include "obstacles.h"
#include "scene.h"
#include "shading.h"
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 64, H = 64 };

static int parse_at(const char *json, const char *scene_path, fs_obstacles *ob)
{
    cJSON *a = cJSON_Parse(json);
    int rc = fs_obstacles_parse(a, scene_path, ob);
    cJSON_Delete(a);
    return rc;
}

static int parse(const char *json, fs_obstacles *ob) { return parse_at(json, "t.json", ob); }

static void test_parse(void)
{
    fs_obstacles ob;
    int rc = parse("[{\"min\": [0, 0, 0], \"max\": [1, 2, 3]}, {\"centre\": [1, 1, 1], \"radius\": 0.5, "
                   "\"color\": [1, 0, 0]}]",
                   &ob);
    CHECK(rc == FS_OK && ob.n == 2, "valid obstacles refused: %s", fs_error_message());
    CHECK(ob.o[0].kind == FS_OBSTACLE_BOX && ob.o[0].hi[2] == 3 && ob.o[1].kind == FS_OBSTACLE_SPHERE &&
              ob.o[1].radius == 0.5f && ob.o[1].color[0] == 1,
          "obstacles read wrongly");
    static const char *const bad[] = {"{}",
                                      "[1]",
                                      "[{\"min\": [1, 0, 0], \"max\": [0, 1, 1]}]",
                                      "[{\"centre\": [0, 0, 0], \"radius\": -1}]",
                                      "[{\"min\": [0, 0, 0], \"max\": [1, 1, 1], \"size\": 2}]",
                                      "[{\"min\": [0, 0, 0]}]",
                                      "[{\"min\": [0, 0, 0], \"max\": [1, 1, 1], \"radius\": 1}]",
                                      "[{\"centre\": [0, 0], \"radius\": 1}]",
                                      "[{\"centre\": [0, 0, 0], \"radius\": 1, \"color\": [2, 0, 0]}]",
                                      "[{\"centre\": [0, 0, 0], \"radius\": 1, \"radius\": 2}]"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        rc = parse(bad[i], &ob);
        const char *m = fs_error_message();
        CHECK(rc == FS_ERR_INPUT && strstr(m, "t.json: ") == m && !strchr(m, '\n') && ob.n == 0, "%s: rc %d, %s",
              bad[i], rc, m);
    }
}

static void test_geometry(void)
{
    fs_obstacles ob;
    parse("[{\"min\": [0, 0, 0], \"max\": [1, 1, 1]}, {\"centre\": [3, 0.5, 0.5], \"radius\": 0.5}]", &ob);
    float inside[3] = {0.25f, 0.5f, 0.5f}, out_face[3] = {0.5f, 1.5f, 0.5f}, out_edge[3] = {1.3f, 1.4f, 0.5f};
    CHECK_NEAR(fs_obstacle_distance(&ob.o[0], inside), -0.25, 1e-6, "box inside");
    CHECK_NEAR(fs_obstacle_distance(&ob.o[0], out_face), 0.5, 1e-6, "box over a face");
    CHECK_NEAR(fs_obstacle_distance(&ob.o[0], out_edge), 0.5, 1e-6, "box beside an edge");
    CHECK_NEAR(fs_obstacle_distance(&ob.o[1], inside), 2.25, 1e-6, "sphere");
    float t, n[3], org[3] = {-2, 0.5f, 0.5f}, dir[3] = {1, 0, 0};
    int i = fs_obstacles_hit(&ob, org, dir, 0, INFINITY, &t, n);
    CHECK(i == 0 && fabsf(t - 2) < 1e-5f && n[0] == -1, "ray hits the box: %d at %g, n %g", i, t, n[0]);
    i = fs_obstacles_hit(&ob, inside, dir, 0, INFINITY, &t, n);
    CHECK(i == 0 && fabsf(t - 0.75f) < 1e-5f && n[0] == 1, "ray leaves the box: %d at %g, n %g", i, t, n[0]);
    float beyond[3] = {1.5f, 0.5f, 0.5f};
    i = fs_obstacles_hit(&ob, beyond, dir, 0, INFINITY, &t, n);
    CHECK(i == 1 && fabsf(t - 1) < 1e-5f && fabsf(n[0] + 1) < 1e-5f, "ray hits the sphere: %d at %g", i, t);
    CHECK(fs_obstacles_hit(&ob, beyond, dir, 0, 0.9f, &t, n) < 0, "a hit beyond tmax counts");
    float up[3] = {0, 1, 0};
    CHECK(fs_obstacles_hit(&ob, out_face, up, 0, INFINITY, &t, n) < 0, "a ray away from the box hits it");
}

/* Camera at z = 3 looking at the origin; a unit box in front at z in [0.5, 1.5]
 * over the left half of the image (x < 0). */
static void setup(fs_scene *s, fs_camera *cam)
{
    fs_scene_defaults(s);
    memset(cam, 0, sizeof *cam);
    cam->eye[2] = 3;
    cam->up[1] = 1;
    cam->fovy_deg = 40;
    cam->width = W;
    cam->height = H;
    cam->znear = 0.1f;
    cam->zfar = 10;
    s->background = FS_BACKGROUND_SKY;
    parse("[{\"min\": [-5, -5, 0.5], \"max\": [0, 5, 1.5], \"color\": [0.9, 0.1, 0.1]}]", &s->obstacles);
}

/* Fluid everywhere at eye depth `depth`, facing the camera. */
static void fill(fs_gbuffer *g, float depth)
{
    fs_gbuffer_clear(g);
    for (int i = 0; i < W * H; i++) {
        g->depth[i] = depth;
        g->normal[3 * i + 2] = 1;
        g->thickness[i] = 0.5f;
        g->coverage[i] = 1;
    }
}

static int same(const float *a, const float *b)
{
    return fabsf(a[0] - b[0]) + fabsf(a[1] - b[1]) + fabsf(a[2] - b[2]) < 1e-5f;
}

static void test_shading(fs_gbuffer *g)
{
    fs_scene s, none;
    fs_camera cam;
    setup(&s, &cam);
    none = s;
    none.obstacles.n = 0;
    float *img = malloc(sizeof(float) * 4 * W * H), *empty = malloc(sizeof(float) * 4 * W * H);
    float *plain = malloc(sizeof(float) * 4 * W * H);
    const int L = (H / 2) * W + W / 4, R = (H / 2) * W + 3 * W / 4; /* a left and a right pixel */
    fs_gbuffer_clear(g);
    fs_shade(&s, &cam, g, 0, empty); /* the obstacle alone */
    CHECK(empty[4 * L] > 2 * empty[4 * L + 2], "the red box is not drawn: %g %g %g", empty[4 * L], empty[4 * L + 1],
          empty[4 * L + 2]);
    fill(g, 4.0f); /* fluid behind the box: the box hides it on the left */
    s.material = none.material = FS_MATERIAL_OPAQUE;
    fs_shade(&s, &cam, g, 0, img);
    fs_shade(&none, &cam, g, 0, plain);
    CHECK(same(img + 4 * L, empty + 4 * L), "fluid behind the box shows through it");
    CHECK(same(img + 4 * R, plain + 4 * R), "the box changes pixels it does not cover");
    fill(g, 1.0f); /* opaque fluid in front of the box hides it */
    fs_shade(&s, &cam, g, 0, img);
    fs_shade(&none, &cam, g, 0, plain);
    CHECK(same(img + 4 * L, plain + 4 * L), "the box shows through opaque fluid in front of it");
    s.material = none.material = FS_MATERIAL_WATER; /* water in front refracts the box */
    fs_shade(&s, &cam, g, 0, img);
    fs_shade(&none, &cam, g, 0, plain);
    CHECK(img[4 * L + 1] < 0.5f * plain[4 * L + 1], "the red box is not seen through the water: G %g vs %g",
          img[4 * L + 1], plain[4 * L + 1]);
    CHECK(same(img + 4 * R, plain + 4 * R), "the box changes water pixels it is not behind");
    free(img);
    free(empty);
    free(plain);
}

static void test_metrics(fs_gbuffer *a, fs_gbuffer *b)
{
    fs_scene s;
    fs_camera cam;
    setup(&s, &cam);
    fill(b, 4.0f);
    fill(a, 4.0f);
    for (int y = 0; y < H; y++) /* the method's normals are wrong on the left half only */
        for (int x = 0; x < W / 2; x++) {
            float *n = a->normal + 3 * (y * W + x);
            n[0] = 0.6f;
            n[2] = 0.8f;
        }
    fs_metrics hid, all;
    int rc = fs_metrics_compute_in_scene(&s, &cam, a, NULL, b, NULL, &hid);
    CHECK(rc == FS_OK, "%s", fs_error_message());
    CHECK(fabs(hid.normal_mean_deg) < 0.1 && hid.n_union <= (size_t)(W * H / 2 + W),
          "hidden pixels counted: %g deg over %zu px", hid.normal_mean_deg, hid.n_union);
    unsigned char mask[W * H];
    fs_obstacle_hidden_mask(&s, &cam, b, mask);
    int hidden = 0, wrong = 0;
    for (int i = 0; i < W * H; i++) {
        hidden += mask[i];
        wrong += mask[i] != ((i % W) < W / 2);
    }
    CHECK(wrong <= H, "%d pixels masked wrongly (%d hidden)", wrong, hidden);
    fill(b, 0.2f); /* reference surface in front of the box: nothing hidden */
    fill(a, 0.2f);
    a->normal[3 * (H / 2 * W + 5)] = 0.6f;
    a->normal[3 * (H / 2 * W + 5) + 2] = 0.8f;
    fs_metrics_compute_in_scene(&s, &cam, a, NULL, b, NULL, &all);
    CHECK(all.n_union == W * H && all.normal_mean_deg > 0, "fluid in front of the box masked: %zu px", all.n_union);
}

/* fs_obstacle_hide: a pixel leaves every view when a solid hides it in any reference. */
static void test_hide(fs_gbuffer *a, fs_gbuffer *b)
{
    fs_scene s;
    fs_camera cam;
    setup(&s, &cam);
    fill(a, 0.2f); /* in front of the box: hides nothing */
    fill(b, 4.0f); /* behind it: hidden on the left half */
    const fs_gbuffer *by[2] = {a, b}, *g[2] = {a, b};
    fs_gbuffer v[2];
    float *cov = malloc(sizeof(float) * 2 * W * H);
    int rc = fs_obstacle_hide(&s, &cam, by, 1, g, 2, v, cov);
    int kept = 0;
    for (int i = 0; i < W * H; i++) kept += v[0].coverage[i] > 0.5f && v[1].coverage[i] > 0.5f;
    CHECK(rc == FS_OK && kept == W * H, "a reference in front of the solid hides %d pixels", W * H - kept);
    rc = fs_obstacle_hide(&s, &cam, by, 2, g, 2, v, cov);
    int wrong = 0;
    for (int i = 0; i < W * H; i++) {
        int left = (i % W) < W / 2;
        wrong += (v[0].coverage[i] > 0.5f) == left || (v[1].coverage[i] > 0.5f) == left;
    }
    CHECK(rc == FS_OK && wrong <= 2 * H, "%d pixels wrong when either reference is behind the solid", wrong);
    CHECK(a->coverage[0] == 1 && b->coverage[0] == 1, "the inputs' coverage changed");
    free(cov);
}

/* An OBJ unit cube [0, 1]^3 as quads. */
static void write_unit_cube(const char *path)
{
    FILE *f = fopen(path, "w");
    for (int v = 0; v < 8; v++) fprintf(f, "v %d %d %d\n", v & 1, (v >> 1) & 1, (v >> 2) & 1);
    fputs("# six quads\nf 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n", f);
    fclose(f);
}

/* A mesh cube, scaled and moved, is the box it covers: distances, hits and the shading. */
static void test_mesh(fs_gbuffer *g)
{
    write_unit_cube(FS_TEST_OUT "/unit_cube.obj");
    fs_obstacles ob;
    int rc = parse_at("[{\"mesh\": \"unit_cube.obj\", \"scale\": 2, \"offset\": [1, 0, -1]},"
                      " {\"min\": [1, 0, -1], \"max\": [3, 2, 1]}]",
                      FS_TEST_OUT "/scene.json", &ob);
    CHECK(rc == FS_OK && ob.n == 2 && ob.o[0].kind == FS_OBSTACLE_MESH, "mesh obstacle: %s", fs_error_message());
    if (rc) return;
    CHECK(ob.o[0].lo[0] == 1 && ob.o[0].hi[0] == 3 && ob.o[0].hi[1] == 2, "mesh bounds %g..%g", ob.o[0].lo[0],
          ob.o[0].hi[0]);
    float worst = 0;
    for (int k = 0; k < 200; k++) { /* points inside, outside and near the faces */
        float p[3] = {(float)(k % 7) * 0.7f - 0.5f, (float)(k % 5) * 0.6f - 0.4f, (float)(k % 11) * 0.35f - 1.9f};
        worst = fmaxf(worst, fabsf(fs_obstacle_distance(&ob.o[0], p) - fs_obstacle_distance(&ob.o[1], p)));
    }
    CHECK(worst < 1e-4f, "mesh and box distances differ by up to %g", worst);
    fs_obstacles one = {1, {ob.o[0]}}, other = {1, {ob.o[1]}};
    int misses = 0;
    for (int k = 0; k < 100; k++) {
        float org[3] = {-2, 0.03f * k, 0.5f - 0.02f * k}, d[3] = {1, 0.05f, 0.01f}, t1 = 0, t2 = 0, n1[3], n2[3];
        float l = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int i = 0; i < 3; i++) d[i] /= l;
        int h1 = fs_obstacles_hit(&one, org, d, 0, INFINITY, &t1, n1),
            h2 = fs_obstacles_hit(&other, org, d, 0, INFINITY, &t2, n2);
        misses += (h1 < 0) != (h2 < 0) || (h1 >= 0 && (fabsf(t1 - t2) > 1e-4f || fabsf(n1[0] - n2[0]) > 1e-4f));
    }
    CHECK(misses == 0, "%d of 100 rays hit the mesh and the box differently", misses);
    fs_scene s, t;
    fs_camera cam;
    setup(&s, &cam);
    t = s;
    s.obstacles = one;
    t.obstacles = other;
    float *ia = malloc(sizeof(float) * 4 * W * H), *ib = malloc(sizeof(float) * 4 * W * H);
    fill(g, 4.0f);
    fs_shade(&s, &cam, g, 0, ia);
    fs_shade(&t, &cam, g, 0, ib);
    int differ = 0;
    for (int i = 0; i < W * H; i++) differ += !same(ia + 4 * i, ib + 4 * i);
    CHECK(differ <= W / 4, "%d pixels differ between the mesh cube and the box", differ);
    free(ia);
    free(ib);
}

/* Bad mesh obstacles: one line naming the scene, the obstacle and the mesh file's problem. */
static void test_bad_mesh(void)
{
    static const char *const files[][2] = {{"nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
                                           {"badv.obj", "v 0 0\nf 1 1 1\n"},
                                           {"badf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"},
                                           {"short.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"}};
    for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
        char path[512], json[256];
        snprintf(path, sizeof path, FS_TEST_OUT "/%s", files[i][0]);
        FILE *f = fopen(path, "w");
        fputs(files[i][1], f);
        fclose(f);
        snprintf(json, sizeof json, "[{\"mesh\": \"%s\"}]", files[i][0]);
        fs_obstacles ob;
        int rc = parse_at(json, FS_TEST_OUT "/t.json", &ob);
        const char *m = fs_error_message();
        CHECK(rc == FS_ERR_INPUT && strstr(m, FS_TEST_OUT "/t.json: obstacles[0]: ") == m && strstr(m, files[i][0]) &&
                  !strchr(m, '\n'),
              "%s: rc %d, %s", files[i][0], rc, m);
    }
    static const char *const bad[] = {
        "[{\"mesh\": \"missing.obj\"}]", "[{\"mesh\": 3}]", "[{\"mesh\": \"x.obj\", \"radius\": 1}]",
        "[{\"centre\": [0, 0, 0], \"radius\": 1, \"scale\": 2}]", "[{\"mesh\": \"x.obj\", \"scale\": -1}]"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        fs_obstacles ob;
        int rc = parse(bad[i], &ob);
        CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "t.json: obstacles[0]: "), "%s: rc %d, %s", bad[i], rc,
              fs_error_message());
    }
}

static void test_scene_file(void)
{
    const char *path = FS_TEST_OUT "/obstacles_scene.json";
    FILE *f = fopen(path, "w");
    fputs("{\"particles\": {\"synthetic\": \"slab\"}, \"obstacles\": [{\"centre\": [0, 0, 0], \"radius\": 0.1}]}", f);
    fclose(f);
    fs_scene s;
    int rc = fs_scene_load(&s, path);
    CHECK(rc == FS_OK && s.obstacles.n == 1 && s.obstacles.o[0].radius == 0.1f, "scene obstacles: %s",
          fs_error_message());
    f = fopen(path, "w");
    fputs("{\"particles\": {\"synthetic\": \"slab\"}, \"obstacles\": [{\"centre\": [0, 0, 0]}]}", f);
    fclose(f);
    rc = fs_scene_load(&s, path);
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), path) && strstr(fs_error_message(), "obstacles[0]"),
          "a bad obstacle in a scene: rc %d, %s", rc, fs_error_message());
    remove(path);
}

int main(void)
{
    fs_gbuffer a, b;
    fs_gbuffer_alloc(&a, W, H);
    fs_gbuffer_alloc(&b, W, H);
    test_parse();
    test_geometry();
    test_shading(&a);
    test_metrics(&a, &b);
    test_hide(&a, &b);
    test_mesh(&a);
    test_bad_mesh();
    test_scene_file();
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    TEST_DONE();
}
