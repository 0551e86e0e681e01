/* fluidsurf_render: one method on one particle set through the run layer, as
 * `fluidsurf render` does, into an image the caller reads. Renders may come from
 * any thread and take turns; GL methods share one context, made on the first
 * GL render and made current by whichever render holds the lock. */
#include "api_internal.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "obstacle_mask.h"
#include "study.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One render at a time (each uses every core through OpenMP): the shared GL
 * context and the methods' process-wide state need no more care than that. */
static pthread_mutex_t render_lock = PTHREAD_MUTEX_INITIALIZER;
static fs_gl_context gl_ctx;
static int gl_ready;

/* With render_lock held: the shared context, current on this thread. */
int fs_api_gl_acquire(void)
{
    if (!gl_ready) {
        int rc = fs_gl_context_create(&gl_ctx, fs_gl_context_default_kind(), 16, 16);
        if (rc) return rc;
        gl_ready = 1;
        return FLUIDSURF_OK;
    }
    return fs_gl_context_make_current(&gl_ctx);
}

/* The scene of this render: the caller's, the method's settings added. */
static int render_scene(const fluidsurf_scene *s, const fs_method *m, const char *const *params, int nparams,
                        fs_scene *out)
{
    *out = s->s;
    if (nparams < 0 || (nparams > 0 && !params))
        return fs_fail(FS_ERR_INPUT, "params: %d settings but no list", nparams);
    for (int i = 0; i < nparams; i++) {
        char set[200];
        if (!params[i]) return fs_fail(FS_ERR_INPUT, "params[%d] is NULL", i);
        if (!strchr(params[i], '='))
            return fs_fail(FS_ERR_INPUT, "params[%d] '%.60s': expected param=value", i, params[i]);
        if (snprintf(set, sizeof set, "%s.%s", m->name, params[i]) >= (int)sizeof set)
            return fs_fail(FS_ERR_INPUT, "params[%d]: too long", i);
        int rc = fs_scene_add_set(out, set);
        if (rc) return rc;
    }
    return FLUIDSURF_OK;
}

/* Stages, their renderers and the provenance into im, from the finished run. */
static void keep_run_facts(fluidsurf_image *im, const fs_run *run, const fs_stages *st)
{
    im->st = *st;
    for (int i = 0; i < st->n; i++)
        snprintf(im->renderer[i], sizeof im->renderer[i], "%s", fs_run_stage_renderer(run, st->name[i]));
    fs_run_provenance(run, NULL, 0, &im->prov);
}

static int run_method(const fs_method *m, const fs_scene *sc, const double *values, const fs_particles *p,
                      fluidsurf_image *im)
{
    fs_run *run = NULL;
    fs_stages st = {0};
    int rc = fs_run_open(&run, m, sc, values, m->needs_gl ? &gl_ctx : NULL);
    if (!rc) rc = fs_study_render_once(run, sc, p, NULL, &im->im, &st); /* as compare renders a reference */
    if (!rc) keep_run_facts(im, run, &st);
    fs_run_close(run);
    return rc;
}

/* The solids' depth as the image's layer solid_depth (a scene with solids), so
 * that its metrics leave out what compare leaves out. */
static int keep_solids(const fs_scene *sc, fluidsurf_image *im)
{
    fs_gbuffer view;
    float *buf;
    int rc = fs_solids_layer(sc, &sc->camera, &im->im.g, &view, &buf);
    if (!rc && buf) {
        rc = fs_gbuffer_add_aov(&im->im.g, FS_AOV_SOLID_DEPTH, 1);
        if (!rc)
            memcpy(fs_gbuffer_aov(&im->im.g, FS_AOV_SOLID_DEPTH), buf, (size_t)im->im.g.w * im->im.g.h * sizeof *buf);
    }
    free(buf);
    return rc;
}

const fs_gl_context *fs_api_gl(void) { return gl_ready ? &gl_ctx : NULL; }

void fs_api_lock(int on)
{
    if (on) pthread_mutex_lock(&render_lock);
    else pthread_mutex_unlock(&render_lock);
}

/* The frame settles r and the camera as the command line's first frame does. */
int fs_api_prepare(const fluidsurf_scene *s, const fluidsurf_particles *fp, const fs_method *m,
                   const char *const *params, int nparams, fs_scene *sc, fs_particles *p, double *values)
{
    int rc = render_scene(s, m, params, nparams, sc);
    if (rc || (rc = fs_method_params_resolve(m, sc, values))) return rc;
    *p = fp->p;
    if ((rc = fs_particles_validate(p, "particles"))) return rc;
    fs_particles_bounds(p);
    char note[1024];
    fs_scene_adopt_frame(sc, p, s->radius_set ? sc->radius : 0, note, sizeof note);
    return FLUIDSURF_OK;
}

int fluidsurf_render(const fluidsurf_scene *s, const fluidsurf_particles *fp, const char *method,
                     const char *const *params, int nparams, fluidsurf_image **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out"))) return rc;
    *out = NULL;
    if ((rc = fs_api_check(s, "scene")) || (rc = fs_api_check(fp, "particles")) ||
        (rc = fs_api_check(method, "method")))
        return rc;
    fs_api_init();
    const fs_method *m = fs_method_find(method);
    if (!m) return fs_method_fail_unknown(NULL, method);
    fs_scene *sc = malloc(sizeof *sc);
    fs_particles p;
    double values[FS_MAX_PARAMS];
    fluidsurf_image *im = calloc(1, sizeof *im);
    if (!sc || !im) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc) rc = fs_api_prepare(s, fp, m, params, nparams, sc, &p, values);
    if (!rc) {
        fs_api_lock(1);
        rc = m->needs_gl ? fs_api_gl_acquire() : FLUIDSURF_OK;
        if (!rc) rc = run_method(m, sc, values, &p, im);
        fs_api_lock(0);
    }
    if (!rc) im->radius = sc->radius, im->camera = sc->camera, im->has_camera = 1;
    if (!rc) rc = keep_solids(sc, im);
    free(sc);
    if (rc) {
        fluidsurf_image_free(im);
        return rc;
    }
    *out = im;
    return FLUIDSURF_OK;
}

int fluidsurf_reference(const fluidsurf_scene *s, const fluidsurf_particles *p, fluidsurf_image **out)
{
    return fluidsurf_render(s, p, "reference", NULL, 0, out);
}
