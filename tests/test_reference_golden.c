/* Golden image of the reference: the bundled cube_2366 block (a real
 * SPlisHSPlasH lattice) at 128x128, auto-framed, shaded by the shared pass. */
#include "fs_error.h"
#include "fs_test.h"
#include "golden.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "particle_io.h"
#include <stdlib.h>

int main(void)
{
    fs_methods_register_builtin();
    fs_scene s;
    fs_scene_defaults(&s);
    s.camera.width = s.camera.height = 128;
    fs_particles p;
    int rc = fs_particles_read(&p, FS_TEST_DATA "/splashsurf/cube_2366_particles.vtk", NULL);
    CHECK(rc == FS_OK, "read: %s", fs_error_message());
    if (rc) TEST_DONE();
    fs_scene_frame_particles(&s, &p);
    const fs_method *m = fs_method_find("reference");
    fs_run *run = NULL;
    fs_run_image im = {0};
    rc = fs_run_open(&run, m, &s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, &p, NULL, NULL);
    if (!rc) rc = fs_run_render(run, &s.camera, &im, NULL);
    if (!rc) rc = fs_run_shade(run, &s.camera, &im, FS_APPEARANCE_SHARED, NULL);
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (!rc)
        CHECK(fs_golden_check("reference_cube", im.rgba, 128, 128, 1.0, 0.01) == 0,
              "golden image reference_cube differs");
    fs_run_image_free(&im);
    fs_run_close(run);
    fs_particles_free(&p);
    TEST_DONE();
}
