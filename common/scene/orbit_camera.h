/* An orbit camera for the interactive viewer: a target, a distance and two
 * angles around the scene's up axis, turned into an fs_camera each frame. */
#ifndef FS_ORBIT_CAMERA_H
#define FS_ORBIT_CAMERA_H
#include "camera.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_orbit {
    float target[3];
    float dist;       /* eye to target */
    float yaw, pitch; /* radians; pitch from the horizontal plane, up positive */
    float fovy_deg;
    int up_axis; /* 0 x, 1 y, 2 z */
} fs_orbit;

/* The orbit that reproduces camera c (eye, target, fov) around up_axis. */
void fs_orbit_from_camera(fs_orbit *o, const fs_camera *c, int up_axis);
/* Sets c's eye, target, up and fov (keeps its size and clip planes). */
void fs_orbit_apply(const fs_orbit *o, fs_camera *c);
/* Mouse drags in pixels: rotate about the target; pan the target in the view
 * plane (the scene follows the cursor) for a view view_h pixels high. */
void fs_orbit_rotate(fs_orbit *o, float dx, float dy);
void fs_orbit_pan(fs_orbit *o, float dx, float dy, int view_h);
/* Wheel steps: positive moves closer. */
void fs_orbit_zoom(fs_orbit *o, float steps);
/* World units per pixel at the target's distance, for a view view_h pixels high. */
float fs_orbit_pixel_size(const fs_orbit *o, int view_h);

#ifdef __cplusplus
}
#endif
#endif
