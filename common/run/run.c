/* The method-run layer (run.h). */
#include "run.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl.h"
#include "method_params.h"
#include "scene_provenance.h"
#include "shading.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fs_run {
    const fs_method *m;
    const fs_scene *scene;
    void *self;
    double values[FS_MAX_PARAMS];
    char renderer[256], gl_version[128];
    /* Methods keep pointers to the particle set and grid they were given, so
     * the run hands them its own copies (of the structs; the arrays stay the
     * caller's) at addresses that live until the next upload: two slots, the
     * current frame's and the one being uploaded. */
    fs_particles frame[2];
    fs_grid grid[2];
    int grid_owned[2]; /* 1: the run built grid[k] and frees it */
    int cur;           /* slot of the current frame, -1 when none */
    float floor_y;
    int floor_set;
    int shared_only; /* renders leave out the own look's layers (fs_run_shared_only) */
    char why[512];   /* why there is no frame (a failed upload) */
};

void fs_run_image_free(fs_run_image *im)
{
    fs_gbuffer_free(&im->g);
    free(im->rgba);
    im->rgba = NULL;
}

/* The renderer every timing and provenance names: the context's, or for a GL
 * method without one given, the current context's (which must be 4.5 core). */
static int name_renderer(fs_run *r, const fs_gl_context *ctx)
{
    snprintf(r->renderer, sizeof r->renderer, "CPU");
    snprintf(r->gl_version, sizeof r->gl_version, "%s", ctx ? ctx->version : "none");
    if (!r->m->needs_gl) return FS_OK;
    if (ctx) {
        snprintf(r->renderer, sizeof r->renderer, "%s", ctx->renderer);
        return FS_OK;
    }
    int rc = fs_gl_check_core45(r->renderer, sizeof r->renderer, r->gl_version, sizeof r->gl_version);
    if (!rc) return FS_OK;
    char why[300];
    snprintf(why, sizeof why, "%s", fs_error_message());
    return fs_fail(rc, "%s: needs a current OpenGL 4.5 context (%s)", r->m->name, why);
}

int fs_run_open(fs_run **out, const fs_method *m, const fs_scene *s, const double *values, const fs_gl_context *ctx)
{
    *out = NULL;
    fs_run *r = calloc(1, sizeof *r);
    if (!r) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", m->name);
    r->m = m;
    r->scene = s;
    int rc = name_renderer(r, ctx);
    if (!rc && values) memcpy(r->values, values, m->nparams * sizeof *values);
    else if (!rc) rc = fs_method_params_resolve(m, s, r->values);
    r->cur = -1;
    snprintf(r->why, sizeof r->why, "%s: no frame uploaded", m->name);
    /* create() receives the method's filled parameter struct and copies it */
    fs_method_setup setup = {fs_scene_field(s), rc ? NULL : fs_method_params_alloc(m, r->values), s};
    if (!rc && !setup.params) rc = FS_ERR_RUNTIME;
    /* a failed create() reports through fs_fail: its code decides the exit status */
    if (!rc) fs_error_clear();
    if (!rc && !(r->self = m->create(&setup))) rc = fs_error_code();
    free((void *)setup.params);
    if (rc) {
        free(r);
        return rc;
    }
    *out = r;
    return FS_OK;
}

void fs_run_close(fs_run *r)
{
    if (!r) return;
    r->m->destroy(r->self);
    for (int k = 0; k < 2; k++)
        if (r->grid_owned[k]) fs_grid_free(&r->grid[k]);
    free(r);
}

const fs_method *fs_run_method(const fs_run *r) { return r->m; }
const double *fs_run_values(const fs_run *r) { return r->values; }
const char *fs_run_renderer(const fs_run *r) { return r->renderer; }

/* Every method bounds its work by the particles' box: a frame without one
 * (bmin > bmax) would render nothing or fail deep inside a method. */
static int check_bounds(const fs_run *r, const fs_particles *p)
{
    for (int k = 0; k < 3; k++)
        if (!(p->bmin[k] <= p->bmax[k]))
            return fs_fail(FS_ERR_INPUT, "%s: the frame's bounding box is empty on axis %d ([%g, %g])", r->m->name, k,
                           p->bmin[k], p->bmax[k]);
    return FS_OK;
}

static int build_grid(const fs_run *r, const fs_particles *p, fs_grid *g, fs_stages *st)
{
    double t0 = fs_now_ms();
    int rc = fs_grid_build(g, p, fs_scene_field(r->scene).H);
    if (!rc && st) fs_stages_add(st, "grid", fs_now_ms() - t0);
    return rc;
}

/* Frees the grid of slot k when the run built it. */
static void drop_own_grid(fs_run *r, int k)
{
    if (r->grid_owned[k]) fs_grid_free(&r->grid[k]);
    r->grid_owned[k] = 0;
}

/* Fills slot k with the frame and its grid (the caller's, or built; none for
 * a method that ignores it). */
static int fill_slot(fs_run *r, int k, const fs_particles *p, const fs_grid *g, fs_stages *st)
{
    drop_own_grid(r, k);
    memset(&r->grid[k], 0, sizeof r->grid[k]);
    r->frame[k] = *p;
    if (!p->n) return FS_OK;
    int rc = check_bounds(r, p);
    if (rc) return rc;
    if (r->m->grid_use == FS_GRID_UNUSED) return FS_OK;
    if (g) {
        r->grid[k] = *g;
        return FS_OK;
    }
    rc = build_grid(r, p, &r->grid[k], st);
    r->grid_owned[k] = !rc;
    return rc;
}

int fs_run_upload(fs_run *r, const fs_particles *p, const fs_grid *g, fs_stages *st)
{
    int k = r->cur == 0 ? 1 : 0; /* not the current frame's slot (after a failure, none is current) */
    int rc = fill_slot(r, k, p, g, st);
    if (!rc && !r->floor_set) /* from the grid's bulk (while it is held), so far strays do not lower the floor */
        r->floor_y = !p->n ? 0
                           : (r->m->grid_use == FS_GRID_UNUSED ? fs_scene_floor_of(r->scene, p)
                                                               : fs_scene_floor(r->scene, &r->grid[k]));
    if (!rc && p->n) {
        double t0 = fs_now_ms();
        rc = r->m->upload(r->self, &r->frame[k], r->m->grid_use == FS_GRID_UNUSED ? NULL : &r->grid[k]);
        if (!rc && st) fs_stages_add(st, "upload", fs_now_ms() - t0);
    }
    if (r->m->grid_use == FS_GRID_AT_UPLOAD) drop_own_grid(r, k); /* read; not kept */
    if (rc) { /* the method may hold half a frame now: render nothing until the next upload */
        r->cur = -1;
        snprintf(r->why, sizeof r->why, "%s", fs_error_message());
        return rc;
    }
    r->cur = k;
    drop_own_grid(r, 1 - k); /* the previous frame's: no longer held */
    return FS_OK;
}

int fs_run_export(fs_run *r, const char *path, const fs_provenance *prov)
{
    if (!r->m->export_file) return fs_fail(FS_ERR_INPUT, "%s: method '%s' exports nothing", path, r->m->name);
    if (r->cur < 0) return fs_fail(FS_ERR_RUNTIME, "%s", r->why);
    if (!r->frame[r->cur].n) return fs_fail(FS_ERR_INPUT, "%s: the frame holds no particles: nothing to export", path);
    fs_provenance own;
    if (!prov) fs_run_provenance(r, NULL, 0, &own);
    return r->m->export_file(r->self, path, prov ? prov : &own);
}

void fs_run_shared_only(fs_run *r, int on) { r->shared_only = on; }

/* Whether renders of r fill AOV d for frame p. */
static int aov_wanted(const fs_run *r, const fs_aov_def *d, const fs_particles *p)
{
    return fs_method_aov_wanted(d, p) && !(r->shared_only && fs_aov_own_look(d->name));
}

/* 1 when g holds exactly the AOVs r's method writes for frame p, in its order. */
static int has_aovs(const fs_gbuffer *g, const fs_run *r, const fs_particles *p)
{
    const fs_method *m = r->m;
    int k = 0;
    for (int i = 0; i < m->naovs; i++) {
        const fs_aov_def *d = &m->aovs[i];
        if (!aov_wanted(r, d, p)) continue;
        if (k == g->naovs || strcmp(g->aov[k].name, d->name) || g->aov[k].ncomp != d->ncomp) return 0;
        k++;
    }
    return k == g->naovs;
}

/* im->g at the camera size with the AOVs the method writes for frame p (none
 * that need the particles' colour when there is no frame, none of the own look's
 * when r is shared only), cleared. */
static int size_gbuffer(const fs_run *r, const fs_camera *cam, const fs_particles *p, fs_run_image *im)
{
    fs_gbuffer *g = &im->g;
    if (g->depth && g->w == cam->width && g->h == cam->height && has_aovs(g, r, p)) {
        fs_gbuffer_clear(g);
        return FS_OK;
    }
    fs_run_image_free(im);
    int rc = fs_gbuffer_alloc(g, cam->width, cam->height);
    for (int i = 0; i < r->m->naovs && !rc; i++) {
        const fs_aov_def *d = &r->m->aovs[i];
        if (aov_wanted(r, d, p)) rc = fs_gbuffer_add_aov(g, d->name, d->ncomp);
    }
    return rc;
}

int fs_run_render(fs_run *r, const fs_camera *cam, fs_run_image *im, fs_stages *st)
{
    static const fs_particles none; /* no frame: no colour, no particles */
    const fs_particles *p = r->cur >= 0 ? &r->frame[r->cur] : &none;
    int rc = size_gbuffer(r, cam, p, im); /* so that a failure still leaves an empty image to show */
    if (rc) return rc;
    if (r->cur < 0) return fs_fail(FS_ERR_RUNTIME, "%s", r->why);
    if (!p->n) return FS_OK;
    fs_stages local = {0};
    rc = r->m->render(r->self, cam, &im->g, st ? st : &local);
    if (rc) fs_gbuffer_clear(&im->g); /* nothing half-drawn */
    return rc;
}

void fs_run_set_floor(fs_run *r, float y)
{
    r->floor_y = y;
    r->floor_set = 1;
}

int fs_run_shade(fs_run *r, const fs_camera *cam, fs_run_image *im, fs_appearance a, fs_stages *st)
{
    const float *own = fs_gbuffer_aov(&im->g, FS_AOV_OWN);
    if (!im->g.depth) return fs_fail(FS_ERR_RUNTIME, "%s: no image to shade", r->m->name);
    if (a == FS_APPEARANCE_OWN && !own)
        return fs_fail(FS_ERR_INPUT, "%s: no own appearance (only the shared shading)", r->m->name);
    size_t n = (size_t)im->g.w * im->g.h;
    if (!im->rgba && !(im->rgba = malloc(n * 4 * sizeof(float))))
        return fs_fail(FS_ERR_RUNTIME, "out of memory for a %dx%d image", im->g.w, im->g.h);
    double t0 = fs_now_ms();
    if (a == FS_APPEARANCE_OWN) memcpy(im->rgba, own, n * 4 * sizeof(float));
    else fs_shade(r->scene, cam, &im->g, r->floor_y, im->rgba);
    if (st) fs_stages_add(st, "shade", fs_now_ms() - t0);
    return FS_OK;
}

void fs_run_provenance(const fs_run *r, const fs_provenance *base, int frame, fs_provenance *out)
{
    if (base) {
        *out = *base;
        for (int i = 0; i < out->n; i++) { /* the entries point into their own struct */
            out->attr[i].name = out->name[i];
            out->attr[i].value = out->value[i];
        }
    } else fs_provenance_init(out, r->scene, r->renderer, r->gl_version);
    fs_method_provenance(out, r->m, r->values, frame);
    fs_provenance_set(out, "gl_renderer", r->renderer);
}

const char *fs_run_stage_renderer(const fs_run *r, const char *stage)
{
    static const char *const cpu[] = {"load", "grid", "shade", "renormalize", "own"};
    for (size_t i = 0; i < sizeof cpu / sizeof *cpu; i++)
        if (!strcmp(stage, cpu[i])) return "CPU";
    return r->renderer;
}
