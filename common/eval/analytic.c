/* The exact G-buffer of a synthetic scene's ideal solid (analytic.h): the box
 * [min centre - r, max centre + r] of the unjittered lattice, or the ball with
 * the volume of N cubes of side 2r. */
#include "analytic.h"
#include "fs_error.h"
#include "vec3.h"
#include <math.h>

static const char *scene_name(const fs_scene *s) { return s->path[0] ? s->path : "synthetic scene"; }

/* Entry and exit distances of the ray o + t dir through the box, or 0 on a miss;
 * *axis is the axis of the entry face. */
static int ray_box(const double o[3], const double dir[3], const double lo[3], const double hi[3], double *t0,
                   double *t1, int *axis)
{
    double tn = -INFINITY, tf = INFINITY;
    *axis = 0;
    for (int a = 0; a < 3; a++) {
        if (fabs(dir[a]) < 1e-300) {
            if (o[a] < lo[a] || o[a] > hi[a]) return 0;
            continue;
        }
        double u = (lo[a] - o[a]) / dir[a], v = (hi[a] - o[a]) / dir[a];
        if (u > v) {
            double w = u;
            u = v;
            v = w;
        }
        if (u > tn) {
            tn = u;
            *axis = a;
        }
        if (v < tf) tf = v;
    }
    *t0 = tn;
    *t1 = tf;
    return tn <= tf;
}

static int ray_ball(const double o[3], const double dir[3], const double c[3], double R, double *t0, double *t1)
{
    double oc[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
    double b = oc[0] * dir[0] + oc[1] * dir[1] + oc[2] * dir[2];
    double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - R * R;
    double disc = b * b - cc;
    if (disc < 0) return 0;
    double q = sqrt(disc);
    *t0 = -b - q;
    *t1 = -b + q;
    return 1;
}

int fs_synthetic_analytic(const fs_scene *s, int frame, const fs_camera *cam, fs_gbuffer *out)
{
    fs_synthetic_layout L;
    int rc = fs_synthetic_layout_of(s, frame, &L);
    if (rc) return rc;
    if (!out->depth || out->w != cam->width || out->h != cam->height)
        return fs_fail(FS_ERR_RUNTIME, "%s: analytic G-buffer must be allocated at the camera size %dx%d",
                       scene_name(s), cam->width, cam->height);
    float right[3], up[3], fwd[3];
    fs_camera_basis(cam, right, up, fwd);
    double o[3] = {cam->eye[0], cam->eye[1], cam->eye[2]};
    fs_gbuffer_clear(out);
#pragma omp parallel for schedule(static)
    for (int py = 0; py < cam->height; py++)
        for (int px = 0; px < cam->width; px++) {
            float df[3];
            fs_camera_ray(cam, px + 0.5f, py + 0.5f, df);
            double dir[3] = {df[0], df[1], df[2]}, t0, t1, nw[3] = {0, 0, 0};
            int axis, hit;
            if (L.sphere) hit = ray_ball(o, dir, L.centre, L.R, &t0, &t1);
            else hit = ray_box(o, dir, L.lo, L.hi, &t0, &t1, &axis);
            /* Only a crossing from outside ahead of the eye counts, as in the reference. */
            if (!hit || !(t0 > 0) || !(t1 > t0)) continue;
            if (L.sphere)
                for (int a = 0; a < 3; a++) nw[a] = (o[a] + t0 * dir[a] - L.centre[a]) / L.R;
            else nw[axis] = dir[axis] > 0 ? -1 : 1;
            float n[3] = {(float)nw[0], (float)nw[1], (float)nw[2]}, nv[3];
            fs_camera_to_view_dir(cam, n, nv);
            float len = fs_v3_len(nv);
            size_t id = (size_t)py * cam->width + px;
            for (int a = 0; a < 3; a++) out->normal[3 * id + a] = nv[a] / len;
            out->depth[id] = (float)(t0 * (dir[0] * fwd[0] + dir[1] * fwd[1] + dir[2] * fwd[2]));
            out->thickness[id] = (float)(t1 - t0);
            out->coverage[id] = 1.0f;
        }
    return FS_OK;
}
