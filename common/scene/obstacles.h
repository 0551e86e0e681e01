/* Static obstacles (solids) of a scene: boxes, spheres and closed OBJ meshes, in scene units. The
 * simulator turns them into boundary particles (sph_scenes.c), the shared shading
 * draws them as opaque geometry composited by depth with a method's G-buffer, and
 * the metrics leave out the pixels where one is in front of the reference surface
 * (docs/DESIGN.md, "Obstacles"). */
#ifndef FS_OBSTACLES_H
#define FS_OBSTACLES_H
#include "camera.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MAX_OBSTACLES 16

typedef enum { FS_OBSTACLE_BOX = 0, FS_OBSTACLE_SPHERE, FS_OBSTACLE_MESH } fs_obstacle_kind;

struct fs_mesh_solid;
typedef struct fs_obstacle {
    fs_obstacle_kind kind;
    float lo[3], hi[3];               /* the bounds in the scene (a box's corners), lo < hi */
    float c[3], radius;               /* sphere: centre and radius > 0 */
    const struct fs_mesh_solid *mesh; /* mesh (obstacle_mesh.h), placed at scale * p + offset */
    float scale, offset[3];
    float color[3]; /* linear albedo of the opaque shading */
} fs_obstacle;

typedef struct fs_obstacles {
    int n;
    fs_obstacle o[FS_MAX_OBSTACLES];
} fs_obstacles;

struct cJSON;
/* A JSON array of {"min": [..], "max": [..]} (box), {"centre": [..], "radius": R}
 * (sphere) or {"mesh": "file.obj", "scale": S, "offset": [..]} (a closed OBJ mesh,
 * its path relative to the folder of `path`, placed at S p + offset; S defaults to 1,
 * offset to 0) objects, each with an optional linear "color": [r, g, b] in [0, 1].
 * FS_ERR_INPUT with "path: obstacles[i]: what" when malformed, or the mesh file's
 * own error. */
int fs_obstacles_parse(const struct cJSON *array, const char *path, fs_obstacles *out);
/* Moves the obstacle to scale * p + offset (scale > 0): the simulator's scene scale
 * and its moving walls. */
void fs_obstacle_transform(fs_obstacle *o, float scale, const float offset[3]);
/* Signed distance from p to the obstacle's surface: negative inside. For a box
 * the exact Euclidean distance outside and minus the distance to the nearest
 * face inside. */
float fs_obstacle_distance(const fs_obstacle *o, const float p[3]);
/* Nearest obstacle hit by the ray org + t dir (dir unit) with tmin < t < tmax:
 * its index, t and outward unit normal; -1 when none. */
int fs_obstacles_hit(const fs_obstacles *ob, const float org[3], const float dir[3], float tmin, float tmax, float *t,
                     float n[3]);
/* Eye depth (distance along the view axis, as G-buffers store it) of the nearest
 * obstacle through each pixel centre of a w x h image spanning cam's; INFINITY
 * where none is hit. depth: w*h floats. */
void fs_obstacles_depth(const fs_obstacles *ob, const fs_camera *cam, int w, int h, float *depth);

#ifdef __cplusplus
}
#endif
#endif
