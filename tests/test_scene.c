/* Scene files: every key parsed, relative paths resolved against the scene's
 * folder, --set lists, and each kind of error reported as one line naming the file. */
#include "frame_source.h"
#include "fs_error.h"
#include "fs_test.h"
#include "scene.h"
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

int main(void)
{
    full_scene();
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
