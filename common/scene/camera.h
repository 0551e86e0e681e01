/* Pinhole camera shared by every method, the reference and the shading pass.
 * Image rows run top to bottom; pixel (i, j) has its centre at (i + 0.5, j + 0.5).
 * Matrices are column-major (OpenGL). View space looks down -z. */
#ifndef FS_CAMERA_H
#define FS_CAMERA_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_camera {
    float eye[3], target[3], up[3];
    float fovy_deg; /* vertical field of view */
    int width, height;
    float znear, zfar; /* clip planes, scene units (set from the scene bounds) */
} fs_camera;

/* Orthonormal basis: right, up, forward (forward points from eye to target). */
void fs_camera_basis(const fs_camera *c, float right[3], float up[3], float fwd[3]);
void fs_camera_view_matrix(const fs_camera *c, float m[16]);
void fs_camera_proj_matrix(const fs_camera *c, float m[16]);
/* Unit world-space direction through pixel position (px, py) (pixel units, top-left origin). */
void fs_camera_ray(const fs_camera *c, float px, float py, float dir[3]);
/* World direction -> view space (rotation only). */
void fs_camera_to_view_dir(const fs_camera *c, const float w[3], float v[3]);
void fs_camera_from_view_dir(const fs_camera *c, const float v[3], float w[3]);
/* The camera's basis and ray scale computed once, for code that casts a ray per
 * pixel (fs_camera_ray and the view-direction functions compute them per call).
 * The fs_camera_rays_* functions give the same floats as those they stand for. */
typedef struct fs_camera_rays {
    float eye[3]; /* where every ray starts */
    float right[3], up[3], fwd[3];
    float tan_half, aspect, width, height; /* tan(fovy / 2), width / height, the image size */
} fs_camera_rays;
void fs_camera_rays_init(const fs_camera *c, fs_camera_rays *r);
/* As fs_camera_ray, fs_camera_to_view_dir and fs_camera_from_view_dir. */
void fs_camera_rays_dir(const fs_camera_rays *r, float px, float py, float dir[3]);
void fs_camera_rays_to_view(const fs_camera_rays *r, const float w[3], float v[3]);
void fs_camera_rays_from_view(const fs_camera_rays *r, const float v[3], float w[3]);
/* A camera that frames the box [bmin, bmax] with the given up axis (0,1,2),
 * looking slightly down from the front; keeps width/height/fov of c. */
void fs_camera_frame_box(fs_camera *c, const float bmin[3], const float bmax[3], int up_axis);
/* Sets znear/zfar to enclose the box (with margin). */
void fs_camera_fit_clip(fs_camera *c, const float bmin[3], const float bmax[3]);

#ifdef __cplusplus
}
#endif
#endif
