/* Scene files: every key parsed, relative paths resolved against the scene's
 * folder, --set lists, and each kind of error reported as one line naming the file. */
#include "camera_text.h"
#include "frame_pattern.h"
#include "frame_source.h"
#include "fs_error.h"
#include "fs_test.h"
#include "scene.h"
#include <stdlib.h>
#include <string.h>

static const char *write_scene(const char *name, const char *text)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", FS_TEST_OUT, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    return path;
}

static void full_scene(void)
{
    const char *path = write_scene(
        "scene_full.json",
        "{\"particles\": {\"file\": \"frames/f_%03d.bgeo\", \"first\": 3, \"last\": 7, \"format\": \"bgeo\"},\n"
        " \"radius\": 0.01, \"volume_scale\": 0.8, \"kernel\": \"poly6\", \"support\": 3, \"iso\": 0.5, \"up\": \"z\",\n"
        " \"camera\": {\"eye\": [1, 2, 3], \"target\": [0, 0, 0], \"up\": [0, 0, 1], \"fov\": 30, \"width\": 320, \"height\": 200},\n"
        " \"light\": {\"direction\": [0, 0, 2], \"color\": [1, 0.5, 0.25], \"ambient\": 0.1},\n"
        " \"material\": {\"type\": \"opaque\", \"color\": [0.1, 0.2, 0.3], \"ior\": 1.5, \"absorption\": [1, 2, 3]},\n"
        " \"background\": \"sky\", \"methods\": {\"spheres\": {\"radius_scale\": 0.5, \"thickness\": false}},\n"
        " \"description\": \"all keys\"}\n");
    fs_scene s;
    int rc = fs_scene_load(&s, path);
    CHECK(rc == FS_OK, "load: %s", fs_error_message());
    char expect[600];
    snprintf(expect, sizeof expect, "%s/frames/f_%%03d.bgeo", FS_TEST_OUT);
    CHECK(!strcmp(s.source, expect), "source %s, expected %s", s.source, expect);
    CHECK(!strcmp(s.format, "bgeo"), "format %s", s.format);
    CHECK(s.frame_first == 3 && s.frame_last == 7, "frames %d..%d", s.frame_first, s.frame_last);
    int first, last;
    fs_scene_frames(&s, &first, &last);
    CHECK(first == 3 && last == 7, "fs_scene_frames %d..%d", first, last);
    CHECK_NEAR(s.radius, 0.01, 1e-9, "radius");
    CHECK_NEAR(s.volume_scale, 0.8, 1e-7, "volume_scale");
    CHECK(s.kernel == FS_KERNEL_POLY6, "kernel %d", s.kernel);
    CHECK_NEAR(s.support_r, 3, 0, "support");
    CHECK_NEAR(s.iso, 0.5, 0, "iso");
    CHECK(s.up_axis == 2, "up %d", s.up_axis);
    CHECK(s.has_camera && s.camera.width == 320 && s.camera.height == 200, "camera size");
    CHECK_NEAR(s.camera.eye[1], 2, 0, "eye");
    CHECK_NEAR(s.camera.fovy_deg, 30, 0, "fov");
    CHECK_NEAR(s.light_dir[2], 1, 1e-6, "light normalised");
    CHECK_NEAR(s.light_color[1], 0.5, 0, "light colour");
    CHECK(s.material == FS_MATERIAL_OPAQUE, "material");
    CHECK_NEAR(s.ior, 1.5, 1e-7, "ior");
    CHECK(s.background == FS_BACKGROUND_SKY, "background");
    CHECK(s.nsets == 2, "sets %d", s.nsets);
    CHECK(s.nsets == 2 && !strcmp(s.sets[1].text, "spheres.thickness=off"), "set %s", s.sets[1].text);
    fs_field f = fs_scene_field(&s);
    CHECK_NEAR(f.volume, 0.8 * 0.02 * 0.02 * 0.02, 1e-12, "V");
    CHECK_NEAR(f.H, 0.03, 1e-7, "H");
    /* the hash follows the file's bytes */
    fs_scene s2;
    fs_scene_load(&s2, path);
    CHECK(s.hash == s2.hash && s.hash != 0, "hash not stable");
}

static void expect_error(const char *name, const char *text, const char *word)
{
    const char *path = write_scene(name, text);
    fs_scene s;
    int rc = fs_scene_load(&s, path);
    const char *msg = fs_error_message();
    CHECK(rc == FS_ERR_INPUT, "%s: rc %d", name, rc);
    CHECK(strncmp(msg, path, strlen(path)) == 0, "%s: message does not start with the path: %s", name, msg);
    CHECK(strstr(msg, word) != NULL, "%s: message lacks '%s': %s", name, word, msg);
    CHECK(strchr(msg, '\n') == NULL, "%s: message has several lines", name);
}

/* A camera's text reads back to the same bits; up, fov and size are optional. */
static void camera_text(void)
{
    fs_camera c = {{0.1f, -2.0f / 3, 1e-7f}, {3.14159274f, 0, -1}, {0.3f, 0.9f, 0.1f}, 37.25f, 321, 123, 0, 0}, d;
    char text[FS_CAMERA_TEXT_MAX];
    unsigned given;
    fs_camera_format(&c, text, sizeof text);
    memset(&d, 0, sizeof d);
    CHECK(fs_camera_parse(text, "t", &d, &given) == FS_OK, "%s", fs_error_message());
    CHECK(!memcmp(c.eye, d.eye, sizeof c.eye) && !memcmp(c.target, d.target, sizeof c.target) &&
              !memcmp(c.up, d.up, sizeof c.up) && c.fovy_deg == d.fovy_deg && d.width == 321 && d.height == 123,
          "%s did not read back exactly", text);
    CHECK(given == (FS_CAMERA_HAS_UP | FS_CAMERA_HAS_FOV | FS_CAMERA_HAS_SIZE), "given %u", given);
    CHECK(fs_camera_parse("eye=1,2,3;target=0,0,0;up=z", "t", &d, &given) == FS_OK && d.up[2] == 1 && d.up[1] == 0 &&
              given == FS_CAMERA_HAS_UP && d.fovy_deg == 37.25f,
          "up=z: %s", fs_error_message());
    static const char *const bad[][2] = {{"eye=1,2,3", "target"},
                                         {"target=1,2,3", "eye"},
                                         {"eye=1,2;target=0,0,0", "eye"},
                                         {"eye=1,2,3;target=0,0,0;up=w", "up"},
                                         {"eye=1,2,3;target=0,0,0;up=0,0,0", "up"},
                                         {"eye=1,2,3;target=0,0,0;fov=200", "fov"},
                                         {"eye=1,2,3;target=1,2,3", "differ"},
                                         {"eye=1,2,3;target=0,0,0;size=0x4", "size"},
                                         {"eye=1,2,3;target=0,0,0;zoom=2", "unknown key"},
                                         {"eye=1,2,3;eye=1,2,3;target=0,0,0", "twice"},
                                         {"eye=1,2,nan;target=0,0,0", "eye"},
                                         {"", "eye"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        d = c;
        int rc = fs_camera_parse(bad[i][0], "--camera", &d, NULL);
        const char *msg = fs_error_message();
        CHECK(rc == FS_ERR_INPUT && !strncmp(msg, "--camera: camera '", 18) && strstr(msg, bad[i][1]) &&
                  !strchr(msg, '\n') && !memcmp(&d, &c, sizeof d),
              "'%s': rc %d, %s", bad[i][0], rc, msg);
    }
}

/* A placed camera without an up of its own turns to the scene's up axis. */
static void camera_up(void)
{
    fs_scene s;
    float lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    fs_scene_load(&s,
                  write_scene("up_z.json",
                              "{\"particles\": \"a.vtk\", \"up\": \"z\", \"camera\": "
                              "{\"eye\": [3, 0, 1], \"target\": [0, 0, 0]}}"));
    fs_scene_finish_camera(&s, lo, hi);
    CHECK(s.camera.up[0] == 0 && s.camera.up[1] == 0 && s.camera.up[2] == 1, "camera up %g %g %g, not the scene's z",
          s.camera.up[0], s.camera.up[1], s.camera.up[2]);
    fs_scene_load(&s,
                  write_scene("up_own.json",
                              "{\"particles\": \"a.vtk\", \"up\": \"z\", \"camera\": "
                              "{\"eye\": [3, 0, 1], \"target\": [0, 0, 0], \"up\": [1, 0, 0]}}"));
    fs_scene_finish_camera(&s, lo, hi);
    CHECK(s.camera.up[0] == 1 && s.camera.up[2] == 0, "the camera's own up was replaced");
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    static char buf[2][8192];
    static int k;
    char *b = buf[k++ % 2];
    size_t n = f ? fread(b, 1, sizeof buf[0] - 1, f) : 0;
    b[n] = 0;
    if (f) fclose(f);
    return b;
}

/* A saved scene loads back to the same values, and saves to the same bytes. */
static void save_round_trip(void)
{
    FILE *f = fopen(FS_TEST_OUT "/tet.obj", "w");
    fputs("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n", f);
    fclose(f);
    const char *path = write_scene("save_in.json",
                                   "{\"particles\": {\"file\": \"f_{}.ply\", \"first\": 2, \"last\": 9, \"step\": 3},\n"
                                   " \"radius\": 0.0123, \"up\": \"z\", \"kernel\": \"spiky\", \"iso\": 0.45,\n"
                                   " \"camera\": {\"eye\": [1.1, 2.2, 3.3], \"target\": [0, 0.1, 0], \"fov\": 33.3},\n"
                                   " \"light\": {\"direction\": [0.2, 0.3, 0.9]}, \"background\": \"sky\",\n"
                                   " \"obstacles\": [{\"min\": [0, 0, 0], \"max\": [1, 2, 3]}, {\"centre\": [1, 1, 1], "
                                   "\"radius\": 0.5}, {\"mesh\": \"tet.obj\", \"scale\": 2, \"offset\": [1, 0, 0]}],\n"
                                   " \"methods\": {\"spheres\": {\"radius_scale\": 0.7, \"thickness\": false}}}\n");
    fs_scene a, b;
    CHECK(fs_scene_load(&a, path) == FS_OK, "%s", fs_error_message());
    CHECK(a.frame_step == 3 && fs_scene_frame_count(&a) == 3 && fs_scene_frame_number(&a, 2) == 8, "step %d: %d frames",
          a.frame_step, fs_scene_frame_count(&a));
    CHECK(fs_scene_save(&a, FS_TEST_OUT "/save_1.json") == FS_OK, "%s", fs_error_message());
    CHECK(fs_scene_load(&b, FS_TEST_OUT "/save_1.json") == FS_OK, "%s", fs_error_message());
    CHECK(!strcmp(a.source, b.source) && a.frame_first == b.frame_first && a.frame_last == b.frame_last &&
              a.frame_step == b.frame_step,
          "particles %s vs %s", a.source, b.source);
    CHECK(a.radius == b.radius && a.up_axis == b.up_axis && a.kernel == b.kernel && a.iso == b.iso, "field");
    CHECK(!memcmp(a.camera.eye, b.camera.eye, sizeof a.camera.eye) && a.camera.fovy_deg == b.camera.fovy_deg, "camera");
    CHECK(!memcmp(a.light_dir, b.light_dir, sizeof a.light_dir), "light %.9g vs %.9g", a.light_dir[2], b.light_dir[2]);
    CHECK(b.obstacles.n == 3 && !memcmp(a.obstacles.o[2].lo, b.obstacles.o[2].lo, sizeof a.obstacles.o[2].lo) &&
              b.obstacles.o[1].radius == 0.5f,
          "obstacles");
    CHECK(b.nsets == 2 && !strcmp(b.sets[1].text, "spheres.thickness=off"), "methods");
    CHECK(fs_scene_save(&b, FS_TEST_OUT "/save_2.json") == FS_OK, "%s", fs_error_message());
    CHECK(!strcmp(slurp(FS_TEST_OUT "/save_1.json"), slurp(FS_TEST_OUT "/save_2.json")), "saved twice: not the same");
}

/* {} and printf patterns, --frames ranges. */
static void patterns(void)
{
    char out[64];
    CHECK(fs_is_frame_pattern("f_{}.ply") && fs_is_frame_pattern("f_%04d.ply") && !fs_is_frame_pattern("100%.ply") &&
              !fs_is_frame_pattern("f.ply"),
          "fs_is_frame_pattern");
    CHECK(fs_frame_pattern("a%_{}.ply", out, sizeof out) == FS_OK && !strcmp(out, "a%%_%d.ply"), "{} gave %s", out);
    CHECK(fs_frame_pattern("f_%04d.ply", out, sizeof out) == FS_OK && !strcmp(out, "f_%04d.ply"), "%%04d gave %s", out);
    CHECK(fs_frame_pattern("f_{}_{}.ply", out, sizeof out) == FS_ERR_INPUT, "two {} accepted");
    CHECK(fs_frame_pattern("f.ply", out, sizeof out) == FS_ERR_INPUT, "no conversion accepted");
    int a, b, c;
    CHECK(!fs_frame_range("2:9", &a, &b, &c) && a == 2 && b == 9 && c == 1, "2:9");
    CHECK(!fs_frame_range("0:10:5", &a, &b, &c) && a == 0 && b == 10 && c == 5, "0:10:5");
    const char *bad[] = {"2", "9:2", "1:2:0", "-1:2", "1:2:", "a:b", "1:2:3:4", "1: 2"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) CHECK(fs_frame_range(bad[i], &a, &b, &c), "%s", bad[i]);
}

int main(void)
{
    full_scene();
    camera_text();
    camera_up();
    save_round_trip();
    patterns();
    fs_scene s;
    CHECK(fs_scene_load(&s, FS_TEST_OUT "/no_such_scene.json") == FS_ERR_INPUT, "missing scene");
    expect_error("e_empty.json", "", "empty");
    expect_error("e_malformed.json", "{\n\"radius\": 0.1,\n\"particles\": [\n", "line");
    expect_error("e_notobject.json", "[1, 2]", "object");
    expect_error("e_noparticles.json", "{\"radius\": 0.1}", "particles");
    expect_error("e_unknown.json", "{\"particles\": \"a.vtk\", \"radius\": 0.1, \"colour\": 1}", "colour");
    expect_error("e_negradius.json", "{\"particles\": \"a.vtk\", \"radius\": -1}", "radius");
    expect_error("e_zeroradius.json", "{\"particles\": \"a.vtk\", \"radius\": 0}", "radius");
    expect_error("e_radiusstr.json", "{\"particles\": \"a.vtk\", \"radius\": \"big\"}", "number");
    expect_error("e_kernel.json", "{\"particles\": \"a.vtk\", \"kernel\": \"gauss\"}", "kernel");
    expect_error("e_up.json", "{\"particles\": \"a.vtk\", \"up\": \"w\"}", "up");
    expect_error("e_width.json", "{\"particles\": \"a.vtk\", \"camera\": {\"width\": 0}}", "width");
    expect_error("e_huge.json", "{\"particles\": \"a.vtk\", \"camera\": {\"height\": 1e9}}", "height");
    expect_error("e_frac.json", "{\"particles\": \"a.vtk\", \"camera\": {\"width\": 10.5}}", "integer");
    expect_error("e_eyeonly.json", "{\"particles\": \"a.vtk\", \"camera\": {\"eye\": [0, 0, 1]}}", "target");
    expect_error("e_eyeistarget.json",
                 "{\"particles\": \"a.vtk\", \"camera\": {\"eye\": [1,1,1], \"target\": [1,1,1]}}", "target");
    expect_error("e_vec.json", "{\"particles\": \"a.vtk\", \"camera\": {\"eye\": [1, 2], \"target\": [0,0,0]}}", "eye");
    expect_error("e_light.json", "{\"particles\": \"a.vtk\", \"light\": {\"direction\": [0, 0, 0]}}", "direction");
    expect_error("e_material.json", "{\"particles\": \"a.vtk\", \"material\": \"glass\"}", "material");
    expect_error("e_background.json", "{\"particles\": \"a.vtk\", \"background\": \"space\"}", "background");
    expect_error("e_synth.json", "{\"particles\": {\"synthetic\": \"torus\"}}", "synthetic");
    expect_error("e_both.json", "{\"particles\": {\"synthetic\": \"slab\", \"file\": \"a.vtk\"}}", "exactly one");
    expect_error("e_frames.json", "{\"particles\": {\"file\": \"a%d.vtk\", \"first\": 5, \"last\": 2}}", "last");
    expect_error("e_firstonly.json", "{\"particles\": {\"file\": \"a%d.vtk\", \"first\": 5}}", "first");
    expect_error("e_jitter.json", "{\"particles\": {\"synthetic\": \"slab\", \"jitter\": 5}}", "jitter");
    expect_error("e_size.json", "{\"particles\": {\"synthetic\": \"slab\", \"size\": [0, 2, 2]}}", "size");
    expect_error("e_methods.json", "{\"particles\": \"a.vtk\", \"methods\": {\"spheres\": 3}}", "spheres");
    expect_error("e_methodval.json", "{\"particles\": \"a.vtk\", \"methods\": {\"spheres\": {\"x\": [1]}}}", "x");
    /* --set syntax */
    fs_scene_defaults(&s);
    CHECK(fs_scene_add_set(&s, "spheres.radius_scale=2") == FS_OK, "good set");
    CHECK(fs_scene_add_set(&s, "spheres=2") == FS_ERR_INPUT, "set without a parameter");
    CHECK(fs_scene_add_set(&s, ".x=2") == FS_ERR_INPUT, "set without a method");
    CHECK(fs_scene_add_set(&s, "spheres.x") == FS_ERR_INPUT, "set without a value");
    TEST_DONE();
}
