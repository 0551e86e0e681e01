/* Golden image of the reference: the bundled cube_2366 block (a real
 * SPlisHSPlasH lattice) at 128x128, auto-framed, shaded by the shared pass. */
#include "fs_error.h"
#include "fs_test.h"
#include "golden.h"
#include "method.h"
#include "method_params.h"
#include "frame_source.h"
#include "particle_io.h"
#include "shading.h"
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
    double params[FS_MAX_PARAMS];
    CHECK(fs_method_params_resolve(m, &s, params) == FS_OK, "params");
    fs_method_setup setup = {fs_scene_field(&s), fs_method_params_alloc(m, params), NULL};
    fs_grid g;
    fs_gbuffer gb;
    fs_stages st = {0};
    void *self = NULL;
    rc = fs_grid_build(&g, &p, setup.field.H);
    if (!rc && !(self = m->create(&setup))) rc = FS_ERR_RUNTIME;
    if (!rc) rc = m->upload(self, &p, &g);
    if (!rc) rc = fs_gbuffer_alloc(&gb, 128, 128, 0);
    if (!rc) rc = m->render(self, &s.camera, &gb, &st);
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    if (!rc) {
        float *rgba = malloc(128 * 128 * 4 * sizeof(float));
        fs_shade(&s, &s.camera, &gb, fs_scene_floor(&s, &p), rgba);
        CHECK(fs_golden_check("reference_cube", rgba, 128, 128, 1.0, 0.01) == 0, "golden image reference_cube differs");
        free(rgba);
        fs_gbuffer_free(&gb);
    }
    if (self) m->destroy(self);
    free((void *)setup.params);
    fs_grid_free(&g);
    fs_particles_free(&p);
    TEST_DONE();
}
