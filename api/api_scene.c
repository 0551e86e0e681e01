/* Scenes of the library: fs_scene's field, camera and settings behind setters. */
#include "api_internal.h"
#include "frame_source.h"
#include "fs_error.h"
#include "kernels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int new_scene(fluidsurf_scene **out)
{
    int rc = fs_api_check(out, "out");
    if (rc) return rc;
    fs_api_init();
    *out = calloc(1, sizeof **out);
    return *out ? FLUIDSURF_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
}

int fluidsurf_scene_new(fluidsurf_scene **out)
{
    int rc = new_scene(out);
    if (!rc) fs_scene_defaults(&(*out)->s), (*out)->s.up_source = FS_UP_AUTO;
    return rc;
}

int fluidsurf_scene_load(const char *path, fluidsurf_scene **out)
{
    int rc = fs_api_check(path, "path");
    if (rc || (rc = new_scene(out))) return rc;
    if ((rc = fs_scene_load(&(*out)->s, path))) {
        free(*out);
        *out = NULL;
    }
    return rc;
}

int fluidsurf_scene_copy(const fluidsurf_scene *s, fluidsurf_scene **out)
{
    int rc = fs_api_check(s, "scene");
    if (rc || (rc = new_scene(out))) return rc;
    **out = *s;
    return FLUIDSURF_OK;
}

void fluidsurf_scene_free(fluidsurf_scene *s) { free(s); }

int fluidsurf_scene_get_field(const fluidsurf_scene *s, fluidsurf_field *f)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(f, "field"))) return rc;
    memset(f, 0, sizeof *f);
    f->radius = s->s.radius, f->volume_scale = s->s.volume_scale;
    f->support = s->s.support_r, f->iso = s->s.iso;
    snprintf(f->kernel, sizeof f->kernel, "%s", fs_kernel_name(s->s.kernel));
    return FLUIDSURF_OK;
}

/* v finite and in (0, 1e9]: else FS_ERR_INPUT naming it. */
static int positive(const char *what, double v)
{
    return isfinite(v) && v > 0 && v <= 1e9 ? FLUIDSURF_OK
                                            : fs_fail(FS_ERR_INPUT, "%s %g: must be positive and finite", what, v);
}

int fluidsurf_scene_set_field(fluidsurf_scene *s, const fluidsurf_field *f)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(f, "field"))) return rc;
    if ((f->radius != 0 && (rc = positive("radius", f->radius))) || (rc = positive("volume_scale", f->volume_scale)) ||
        (rc = positive("support", f->support)) || (rc = positive("iso", f->iso)))
        return rc;
    int k = fs_kernel_from_name(f->kernel);
    if (k < 0) return fs_fail(FS_ERR_INPUT, "kernel '%.16s': expected cubic, poly6, spiky or wyvill", f->kernel);
    if (f->radius != 0) s->s.radius = (float)f->radius, s->radius_set = 1;
    s->s.volume_scale = (float)f->volume_scale;
    s->s.support_r = (float)f->support, s->s.iso = (float)f->iso, s->s.kernel = (fs_kernel)k;
    return FLUIDSURF_OK;
}

int fluidsurf_scene_set_up(fluidsurf_scene *s, const char *up)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(up, "up"))) return rc;
    if (!strcmp(up, "auto")) s->s.up_source = FS_UP_AUTO;
    else if (strlen(up) == 1 && up[0] >= 'x' && up[0] <= 'z') s->s.up_axis = up[0] - 'x', s->s.up_source = FS_UP_OPTION;
    else return fs_fail(FS_ERR_INPUT, "up '%.16s': expected x, y, z or auto", up);
    return FLUIDSURF_OK;
}

int fluidsurf_scene_set_radius(fluidsurf_scene *s, double radius)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = positive("radius", radius))) return rc;
    s->s.radius = (float)radius;
    s->radius_set = 1;
    return FLUIDSURF_OK;
}

void fs_api_camera_out(const fs_camera *k, fluidsurf_camera *c)
{
    for (int i = 0; i < 3; i++) c->eye[i] = k->eye[i], c->target[i] = k->target[i], c->up[i] = k->up[i];
    c->fov_deg = k->fovy_deg, c->width = k->width, c->height = k->height;
}

int fluidsurf_scene_get_camera(const fluidsurf_scene *s, fluidsurf_camera *c, int *placed)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(c, "camera"))) return rc;
    fs_api_camera_out(&s->s.camera, c);
    if (placed) *placed = s->s.has_camera;
    return FLUIDSURF_OK;
}

static int check_size(int width, int height)
{
    if (width < 1 || height < 1 || width > 16384 || height > 16384 || (long)width * height > 16384L * 16384L / 4)
        return fs_fail(FS_ERR_INPUT, "image size %dx%d: each side 1 to 16384, at most 67108864 pixels", width, height);
    return FLUIDSURF_OK;
}

int fluidsurf_scene_set_camera(fluidsurf_scene *s, const fluidsurf_camera *c)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(c, "camera")) || (rc = check_size(c->width, c->height)))
        return rc;
    double d2 = 0, u2 = 0;
    for (int i = 0; i < 3; i++) {
        if (!isfinite(c->eye[i]) || !isfinite(c->target[i]) || !isfinite(c->up[i]))
            return fs_fail(FS_ERR_INPUT, "camera: eye, target and up must be finite");
        d2 += (c->target[i] - c->eye[i]) * (c->target[i] - c->eye[i]), u2 += c->up[i] * c->up[i];
    }
    if (!(d2 > 0)) return fs_fail(FS_ERR_INPUT, "camera: eye equals target");
    if (!(c->fov_deg > 0 && c->fov_deg < 180))
        return fs_fail(FS_ERR_INPUT, "camera: fov %g: expected (0, 180) degrees", c->fov_deg);
    fs_camera k = s->s.camera;
    for (int i = 0; i < 3; i++)
        k.eye[i] = (float)c->eye[i], k.target[i] = (float)c->target[i], k.up[i] = (float)c->up[i];
    k.fovy_deg = (float)c->fov_deg, k.width = c->width, k.height = c->height;
    fs_scene_place_camera(&s->s, &k, u2 > 0); /* up 0: the scene's up axis, as --camera without up= */
    return FLUIDSURF_OK;
}

int fluidsurf_scene_set_size(fluidsurf_scene *s, int width, int height)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = check_size(width, height))) return rc;
    s->s.camera.width = width, s->s.camera.height = height;
    return FLUIDSURF_OK;
}

int fluidsurf_scene_set(fluidsurf_scene *s, const char *setting)
{
    int rc;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(setting, "setting"))) return rc;
    return fs_scene_add_set(&s->s, setting);
}

int fluidsurf_scene_frames(const fluidsurf_scene *s, int *first, int *last)
{
    int rc, a, b;
    if ((rc = fs_api_check(s, "scene"))) return rc;
    if (!s->s.source[0] && !s->s.synth.shape)
        return fs_fail(FS_ERR_INPUT, "scene: no particle source (a scene file names one)");
    fs_scene_frames(&s->s, &a, &b);
    if (first) *first = a;
    if (last) *last = b;
    return FLUIDSURF_OK;
}

int fluidsurf_scene_read_frame(const fluidsurf_scene *s, int frame, fluidsurf_particles **out)
{
    int rc, first, last;
    if ((rc = fs_api_check(out, "out")) || (rc = fluidsurf_scene_frames(s, &first, &last))) return rc;
    *out = NULL;
    if (frame < first || frame > last)
        return fs_fail(FS_ERR_INPUT, "frame %d: the scene has frames %d..%d", frame, first, last);
    fluidsurf_particles *p = calloc(1, sizeof *p);
    if (!p) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    if ((rc = fs_scene_load_frame(&s->s, frame, &p->p))) {
        free(p);
        return rc;
    }
    p->owned = 1;
    *out = p;
    return FLUIDSURF_OK;
}
