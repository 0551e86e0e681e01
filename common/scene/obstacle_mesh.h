/* Closed triangle meshes read from Wavefront OBJ files, as static obstacles
 * (obstacles.h): signed distance and ray hits. A mesh is loaded once per path and
 * kept for the life of the process (scenes are copied by value; they share it). */
#ifndef FS_OBSTACLE_MESH_H
#define FS_OBSTACLE_MESH_H
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MESH_MAX_TRIANGLES 200000

typedef struct fs_mesh_solid {
    int ntri;
    float *tri;         /* 9 floats per triangle: its three corners */
    float lo[3], hi[3]; /* bounds */
    const char *path;   /* the file it was read from (a saved scene names it) */
} fs_mesh_solid;

/* Reads an OBJ file's "v" and "f" lines (polygons fanned into triangles; "v/vt/vn"
 * and negative indices allowed; other lines ignored). FS_ERR_INPUT with "path: what"
 * for a file that cannot be read, a malformed or out-of-range line, no triangle, or
 * more than FS_MESH_MAX_TRIANGLES. */
int fs_mesh_solid_load(const char *path, const fs_mesh_solid **out);
/* Signed distance from p to the surface: negative inside (ray parity, so the mesh
 * must be closed). */
float fs_mesh_solid_distance(const fs_mesh_solid *m, const float p[3]);
/* Nearest triangle hit by org + t dir with tmin < t < tmax: 1, t and the triangle's
 * unit normal turned to face the ray's origin; 0 when none. */
int fs_mesh_solid_hit(const fs_mesh_solid *m, const float org[3], const float dir[3], float tmin, float tmax, float *t,
                      float n[3]);

#ifdef __cplusplus
}
#endif
#endif
