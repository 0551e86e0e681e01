/* The viewer's orbit camera (common/scene/orbit_camera.c): it reproduces the camera
 * it starts from for each up axis; rotating keeps the target and distance,
 * pitch stops short of the pole; panning moves the target across the view
 * only, by the pixel size; zooming scales the distance. */
#include "fs_test.h"
#include "orbit_camera.h"
#include <math.h>

static float dist3(const float a[3], const float b[3])
{
    return sqrtf((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

int main(void)
{
    for (int up = 0; up < 3; up++) {
        fs_camera c = {
            .eye = {3.2f, 3.4f, 5.4f}, .target = {0.1f, 1.0f, -0.2f}, .fovy_deg = 40, .width = 64, .height = 48};
        c.up[up] = 1;
        fs_orbit o;
        fs_orbit_from_camera(&o, &c, up);
        fs_camera d = c;
        fs_orbit_apply(&o, &d);
        CHECK(dist3(d.eye, c.eye) < 1e-4f && dist3(d.target, c.target) < 1e-6f, "up %d: round trip moved the eye by %g",
              up, dist3(d.eye, c.eye));
        float r0 = o.dist;
        fs_orbit_rotate(&o, 37, -12);
        fs_orbit_apply(&o, &d);
        CHECK(fabsf(dist3(d.eye, d.target) - r0) < 1e-4f && dist3(d.target, c.target) < 1e-6f,
              "up %d: rotation changed the distance or the target", up);
        CHECK(dist3(d.eye, c.eye) > 0.1f * r0, "up %d: rotation did not move the eye", up);
        fs_orbit_rotate(&o, 0, 1e5f);
        CHECK(o.pitch < 1.5708f && o.pitch > 1.5f, "up %d: pitch %g not held below the pole", up, o.pitch);

        fs_orbit_from_camera(&o, &c, up);
        float px = fs_orbit_pixel_size(&o, 48), right[3], vup[3], fwd[3],
              t0[3] = {o.target[0], o.target[1], o.target[2]};
        fs_orbit_apply(&o, &d);
        fs_camera_basis(&d, right, vup, fwd);
        fs_orbit_pan(&o, 10, 0, 48); /* drag right: the scene follows, the target moves left */
        float m[3] = {o.target[0] - t0[0], o.target[1] - t0[1], o.target[2] - t0[2]};
        float along = m[0] * right[0] + m[1] * right[1] + m[2] * right[2];
        float across = m[0] * fwd[0] + m[1] * fwd[1] + m[2] * fwd[2];
        CHECK(fabsf(along + 10 * px) < 1e-4f * r0 && fabsf(across) < 1e-5f * r0,
              "up %d: pan moved %g along right (want %g), %g along the view", up, along, -10 * px, across);
        fs_orbit_zoom(&o, 2);
        CHECK(fabsf(o.dist - r0 * 0.81f) < 1e-4f * r0, "up %d: two wheel steps give distance %g, want %g", up, o.dist,
              r0 * 0.81f);
    }
    TEST_DONE();
}
