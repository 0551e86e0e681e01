/* A camera as one line of text, "eye=X,Y,Z;target=X,Y,Z;up=X,Y,Z;fov=F;size=WxH":
 * the --camera option reads it, and every output's provenance (fluidsurf:camera)
 * is written in it, so an EXR's camera reads back exactly (%.9g: a float's
 * every bit). */
#ifndef FS_CAMERA_TEXT_H
#define FS_CAMERA_TEXT_H
#include "camera.h"
#ifdef __cplusplus
extern "C" {
#endif

enum { FS_CAMERA_TEXT_MAX = 400 };

/* The keys a camera text gave (fs_camera_parse). */
enum { FS_CAMERA_HAS_UP = 1, FS_CAMERA_HAS_FOV = 2, FS_CAMERA_HAS_SIZE = 4 };

/* Parses text into c: eye and target (both needed), up (x, y, z or X,Y,Z; not
 * zero), fov (degrees, 1 to 170), size (WxH, 1 to 16384 each); keys left out
 * keep c's values. *given receives FS_CAMERA_HAS_* of the keys given.
 * FS_ERR_INPUT with "what: camera 'TEXT': the problem" on an unknown or
 * repeated key, a malformed value, eye or target missing, or eye == target. */
int fs_camera_parse(const char *text, const char *what, fs_camera *c, unsigned *given);
/* c as text, every key, into buf (FS_CAMERA_TEXT_MAX bytes suffice). */
void fs_camera_format(const fs_camera *c, char *buf, int size);

#ifdef __cplusplus
}
#endif
#endif
