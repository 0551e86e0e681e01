/* Orbit camera (orbit_camera.h). Angles live in a frame whose first axis is
 * the up axis u, then a = u+1, b = u+2 (mod 3): for y-up, a = z and b = x, so
 * yaw 0 looks from +z down -z, the default framing's side. */
#include "orbit_camera.h"
#include "vec3.h"
#include <math.h>

static const float pitch_limit = 1.5533f; /* 89 degrees: keeps up and forward apart */

void fs_orbit_from_camera(fs_orbit *o, const fs_camera *c, int up_axis)
{
    int u = up_axis, a = (u + 1) % 3, b = (u + 2) % 3;
    float d[3];
    for (int k = 0; k < 3; k++) {
        o->target[k] = c->target[k];
        d[k] = c->eye[k] - c->target[k];
    }
    o->dist = fs_v3_len(d);
    if (!(o->dist > 0)) o->dist = 1;
    o->pitch = asinf(fmaxf(-1.0f, fminf(1.0f, d[u] / o->dist)));
    o->yaw = atan2f(d[b], d[a]);
    o->fovy_deg = c->fovy_deg;
    o->up_axis = up_axis;
}

void fs_orbit_apply(const fs_orbit *o, fs_camera *c)
{
    int u = o->up_axis, a = (u + 1) % 3, b = (u + 2) % 3;
    float d[3];
    d[u] = o->dist * sinf(o->pitch);
    d[a] = o->dist * cosf(o->pitch) * cosf(o->yaw);
    d[b] = o->dist * cosf(o->pitch) * sinf(o->yaw);
    for (int k = 0; k < 3; k++) {
        c->target[k] = o->target[k];
        c->eye[k] = o->target[k] + d[k];
        c->up[k] = k == u ? 1.0f : 0.0f;
    }
    c->fovy_deg = o->fovy_deg;
}

void fs_orbit_rotate(fs_orbit *o, float dx, float dy)
{
    const float rad_per_px = 0.01f;
    o->yaw -= dx * rad_per_px; /* drag right: the scene turns right */
    o->pitch += dy * rad_per_px;
    o->pitch = fmaxf(-pitch_limit, fminf(pitch_limit, o->pitch));
}

float fs_orbit_pixel_size(const fs_orbit *o, int view_h)
{
    return 2.0f * o->dist * tanf(o->fovy_deg * 0.5f * 3.14159265f / 180.0f) / (float)(view_h > 0 ? view_h : 1);
}

void fs_orbit_pan(fs_orbit *o, float dx, float dy, int view_h)
{
    fs_camera c = {0};
    float right[3], up[3], fwd[3], s = fs_orbit_pixel_size(o, view_h);
    fs_orbit_apply(o, &c);
    fs_camera_basis(&c, right, up, fwd);
    for (int k = 0; k < 3; k++) o->target[k] += (-dx * right[k] + dy * up[k]) * s;
}

void fs_orbit_zoom(fs_orbit *o, float steps)
{
    o->dist *= powf(0.9f, steps);
    if (o->dist < 1e-4f) o->dist = 1e-4f;
}
