#include "camera.h"
#include "vec3.h"
#include <math.h>
#include <string.h>

void fs_camera_basis(const fs_camera *c, float right[3], float up[3], float fwd[3])
{
    fs_v3_sub(c->target, c->eye, fwd);
    fs_v3_normalize(fwd);
    fs_v3_cross(fwd, c->up, right);
    if (fs_v3_dot(right, right) < 1e-12f) { /* up parallel to the view: pick any perpendicular */
        float alt[3] = {fabsf(fwd[0]) < 0.9f ? 1.0f : 0.0f, fabsf(fwd[0]) < 0.9f ? 0.0f : 1.0f, 0};
        fs_v3_cross(fwd, alt, right);
    }
    fs_v3_normalize(right);
    fs_v3_cross(right, fwd, up);
}

void fs_camera_view_matrix(const fs_camera *c, float m[16])
{
    float r[3], u[3], f[3];
    fs_camera_basis(c, r, u, f);
    float t[16] = {r[0],
                   u[0],
                   -f[0],
                   0,
                   r[1],
                   u[1],
                   -f[1],
                   0,
                   r[2],
                   u[2],
                   -f[2],
                   0,
                   -fs_v3_dot(r, c->eye),
                   -fs_v3_dot(u, c->eye),
                   fs_v3_dot(f, c->eye),
                   1};
    memcpy(m, t, sizeof t);
}

void fs_camera_proj_matrix(const fs_camera *c, float m[16])
{
    float t = 1.0f / tanf(c->fovy_deg * (float)M_PI / 360.0f), a = (float)c->width / c->height;
    float n = c->znear, f = c->zfar;
    memset(m, 0, 16 * sizeof *m);
    m[0] = t / a;
    m[5] = t;
    m[10] = (f + n) / (n - f);
    m[11] = -1;
    m[14] = 2 * f * n / (n - f);
}

void fs_camera_rays_init(const fs_camera *c, fs_camera_rays *r)
{
    fs_camera_basis(c, r->right, r->up, r->fwd);
    for (int i = 0; i < 3; i++) r->eye[i] = c->eye[i];
    r->tan_half = tanf(c->fovy_deg * (float)M_PI / 360.0f);
    r->aspect = (float)c->width / c->height;
    r->width = (float)c->width;
    r->height = (float)c->height;
}

void fs_camera_rays_dir(const fs_camera_rays *r, float px, float py, float dir[3])
{
    float x = (2.0f * px / r->width - 1.0f) * r->tan_half * r->aspect, y = (1.0f - 2.0f * py / r->height) * r->tan_half;
    for (int i = 0; i < 3; i++) dir[i] = r->fwd[i] + x * r->right[i] + y * r->up[i];
    fs_v3_normalize(dir);
}

void fs_camera_rays_to_view(const fs_camera_rays *r, const float w[3], float v[3])
{
    float x = fs_v3_dot(w, r->right), y = fs_v3_dot(w, r->up), z = -fs_v3_dot(w, r->fwd);
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

void fs_camera_rays_from_view(const fs_camera_rays *r, const float v[3], float w[3])
{
    for (int i = 0; i < 3; i++) w[i] = v[0] * r->right[i] + v[1] * r->up[i] - v[2] * r->fwd[i];
}

void fs_camera_ray(const fs_camera *c, float px, float py, float dir[3])
{
    fs_camera_rays r;
    fs_camera_rays_init(c, &r);
    fs_camera_rays_dir(&r, px, py, dir);
}

void fs_camera_to_view_dir(const fs_camera *c, const float w[3], float v[3])
{
    fs_camera_rays r;
    fs_camera_rays_init(c, &r);
    fs_camera_rays_to_view(&r, w, v);
}

void fs_camera_from_view_dir(const fs_camera *c, const float v[3], float w[3])
{
    fs_camera_rays r;
    fs_camera_rays_init(c, &r);
    fs_camera_rays_from_view(&r, v, w);
}

/* Largest |NDC| coordinate of the box corners seen from c, and their NDC centre. */
static float box_extent(const fs_camera *c, const float bmin[3], const float bmax[3], float ctr[2])
{
    float r[3], u[3], f[3], lo[2] = {1e30f, 1e30f}, hi[2] = {-1e30f, -1e30f};
    fs_camera_basis(c, r, u, f);
    float t = tanf(c->fovy_deg * (float)M_PI / 360.0f), a = (float)c->width / c->height;
    for (int k = 0; k < 8; k++) {
        float p[3] = {k & 1 ? bmax[0] : bmin[0], k & 2 ? bmax[1] : bmin[1], k & 4 ? bmax[2] : bmin[2]}, d[3];
        fs_v3_sub(p, c->eye, d);
        float z = fmaxf(fs_v3_dot(d, f), 1e-6f), x = fs_v3_dot(d, r) / (z * t * a), y = fs_v3_dot(d, u) / (z * t);
        lo[0] = fminf(lo[0], x);
        hi[0] = fmaxf(hi[0], x);
        lo[1] = fminf(lo[1], y);
        hi[1] = fmaxf(hi[1], y);
    }
    ctr[0] = 0.5f * (lo[0] + hi[0]);
    ctr[1] = 0.5f * (lo[1] + hi[1]);
    return fmaxf(fmaxf(hi[0] - ctr[0], ctr[0] - lo[0]), fmaxf(hi[1] - ctr[1], ctr[1] - lo[1]));
}

void fs_camera_frame_box(fs_camera *c, const float bmin[3], const float bmax[3], int up_axis)
{
    float ctr[3], ext[3];
    for (int i = 0; i < 3; i++) {
        ctr[i] = 0.5f * (bmin[i] + bmax[i]);
        ext[i] = bmax[i] - bmin[i];
    }
    float radius = 0.5f * sqrtf(fs_v3_dot(ext, ext));
    if (radius <= 0) radius = 1;
    /* Look across the longer horizontal side (a dam break is seen from its
     * long side), 25 degrees above the horizon and 30 degrees off-axis. */
    int a = (up_axis + 1) % 3, b = (up_axis + 2) % 3;
    if (ext[a] < ext[b]) {
        int tmp = a;
        a = b;
        b = tmp;
    }
    float dir[3];
    dir[up_axis] = sinf(25.0f * (float)M_PI / 180);
    dir[b] = cosf(25.0f * (float)M_PI / 180) * cosf(30.0f * (float)M_PI / 180);
    dir[a] = cosf(25.0f * (float)M_PI / 180) * sinf(30.0f * (float)M_PI / 180);
    float half = c->fovy_deg * (float)M_PI / 360.0f;
    float aspect = (float)c->width / c->height;
    if (aspect < 1) half = atanf(tanf(half) * aspect);
    float dist = radius / sinf(half) * 1.02f; /* the bounding sphere fits: a safe start */
    for (int i = 0; i < 3; i++) {
        c->target[i] = ctr[i];
        c->up[i] = i == up_axis ? 1.0f : 0.0f;
    }
    /* Then tighten: move closer until the box corners fill 90% of the frame,
     * re-centring the box's projection each time. */
    for (int it = 0; it < 6; it++) {
        for (int i = 0; i < 3; i++) c->eye[i] = c->target[i] + dir[i] * dist;
        float nc[2], e = box_extent(c, bmin, bmax, nc);
        float r[3], u[3], f[3], t = tanf(c->fovy_deg * (float)M_PI / 360.0f);
        fs_camera_basis(c, r, u, f);
        float zc = fs_v3_dot(dir, dir) * dist;
        for (int i = 0; i < 3; i++) c->target[i] += (nc[0] * t * aspect * r[i] + nc[1] * t * u[i]) * zc;
        if (e > 0) dist *= 0.5f + 0.5f * e / 0.9f;
    }
    for (int i = 0; i < 3; i++) c->eye[i] = c->target[i] + dir[i] * dist;
}

void fs_camera_fit_clip(fs_camera *c, const float bmin[3], const float bmax[3])
{
    float r[3], u[3], f[3], nearest = INFINITY, farthest = 0;
    fs_camera_basis(c, r, u, f);
    for (int k = 0; k < 8; k++) {
        float p[3] = {k & 1 ? bmax[0] : bmin[0], k & 2 ? bmax[1] : bmin[1], k & 4 ? bmax[2] : bmin[2]}, d[3];
        fs_v3_sub(p, c->eye, d);
        float z = fs_v3_dot(d, f);
        if (z < nearest) nearest = z;
        if (z > farthest) farthest = z;
    }
    float span = farthest > 0 ? farthest : 1;
    c->zfar = farthest * 1.05f + 1e-3f;
    c->znear = nearest > span * 1e-3f ? nearest * 0.95f : span * 1e-3f;
}
