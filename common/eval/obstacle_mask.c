/* Obstacle-hidden pixels left out of the metrics (obstacle_mask.h). */
#include "obstacle_mask.h"
#include "fs_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fs_solids_hidden(const float *solid_depth, const fs_gbuffer *ref, unsigned char *hidden)
{
    size_t n = (size_t)ref->w * ref->h;
    for (size_t i = 0; i < n; i++) {
        float d = solid_depth[i];
        int fluid = ref->coverage[i] >= 0.5f && isfinite(ref->depth[i]);
        hidden[i] = isfinite(d) && d > 0 && (!fluid || d < ref->depth[i]);
    }
}

int fs_obstacle_hidden_mask(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *ref, unsigned char *hidden)
{
    size_t n = (size_t)ref->w * ref->h;
    memset(hidden, 0, n);
    if (!s->obstacles.n) return FS_OK;
    float *depth = malloc(n * sizeof *depth);
    if (!depth) return fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", ref->w, ref->h);
    fs_obstacles_depth(&s->obstacles, cam, ref->w, ref->h, depth);
    fs_solids_hidden(depth, ref, hidden);
    free(depth);
    return FS_OK;
}

int fs_obstacle_hide(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *const *by, int nby,
                     const fs_gbuffer *const *g, int ng, fs_gbuffer *views, float *cov)
{
    int w = g[0]->w, h = g[0]->h;
    size_t n = (size_t)w * h;
    for (int k = 0; k < nby; k++)
        if (by[k]->w != w || by[k]->h != h) return fs_fail(FS_ERR_INPUT, "metrics: image sizes differ");
    unsigned char *hidden = malloc(n), *one = malloc(n);
    int rc = hidden && one ? FS_OK : fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", w, h);
    if (!rc) memset(hidden, 0, n);
    for (int k = 0; k < nby && !rc; k++) /* hidden in any of them */
        if (!(rc = fs_obstacle_hidden_mask(s, cam, by[k], one)))
            for (size_t i = 0; i < n; i++) hidden[i] |= one[i];
    for (int k = 0; k < ng && !rc; k++) {
        if (g[k]->w != w || g[k]->h != h) {
            rc = fs_fail(FS_ERR_INPUT, "metrics: image sizes differ");
            break;
        }
        views[k] = *g[k];
        views[k].coverage = cov + (size_t)k * n;
        for (size_t i = 0; i < n; i++) views[k].coverage[i] = hidden[i] ? 0.0f : g[k]->coverage[i];
    }
    free(hidden);
    free(one);
    return rc;
}

int fs_metrics_compute_masked(const float *solid_depth, const fs_gbuffer *a, const float *rgba_a, const fs_gbuffer *b,
                              const float *rgba_b, float r, fs_metrics *out, long *nhidden)
{
    if (nhidden) *nhidden = 0;
    if (!solid_depth || !a || !b || !a->coverage || !b->coverage || a->w != b->w || a->h != b->h)
        return fs_metrics_compute(a, rgba_a, b, rgba_b, r, out); /* which reports what is wrong */
    size_t n = (size_t)b->w * b->h;
    float *cov = malloc(2 * n * sizeof *cov);
    unsigned char *hidden = malloc(n);
    int rc = cov && hidden ? FS_OK : fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", b->w, b->h);
    if (!rc) {
        fs_solids_hidden(solid_depth, b, hidden);
        const fs_gbuffer *g[2] = {a, b};
        fs_gbuffer v[2];
        long nh = 0;
        for (size_t i = 0; i < n; i++) nh += hidden[i];
        for (int k = 0; k < 2; k++) {
            v[k] = *g[k];
            v[k].coverage = cov + (size_t)k * n;
            for (size_t i = 0; i < n; i++) v[k].coverage[i] = hidden[i] ? 0.0f : g[k]->coverage[i];
        }
        rc = fs_metrics_compute(&v[0], rgba_a, &v[1], rgba_b, r, out);
        if (!rc && nhidden) *nhidden = nh;
    }
    free(cov);
    free(hidden);
    return rc;
}

int fs_metrics_compute_in_scene(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *a, const float *rgba_a,
                                const fs_gbuffer *b, const float *rgba_b, fs_metrics *out)
{
    if (!s->obstacles.n || !b || !b->coverage || b->w < 1 || b->h < 1)
        return fs_metrics_compute(a, rgba_a, b, rgba_b, s->radius, out); /* which reports what is wrong */
    size_t n = (size_t)b->w * b->h;
    float *depth = malloc(n * sizeof *depth);
    if (!depth) return fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", b->w, b->h);
    fs_obstacles_depth(&s->obstacles, cam, b->w, b->h, depth);
    int rc = fs_metrics_compute_masked(depth, a, rgba_a, b, rgba_b, s->radius, out, NULL);
    free(depth);
    return rc;
}

int fs_solids_layer(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g, fs_gbuffer *view, float **buf)
{
    *view = *g;
    *buf = NULL;
    if (!s->obstacles.n || fs_gbuffer_aov(g, FS_AOV_SOLID_DEPTH) || g->naovs >= FS_GBUFFER_MAX_AOVS) return FS_OK;
    size_t n = (size_t)g->w * g->h;
    if (!(*buf = malloc(n * sizeof **buf)))
        return fs_fail(FS_ERR_RUNTIME, "out of memory for a %dx%d image", g->w, g->h);
    fs_obstacles_depth(&s->obstacles, cam, g->w, g->h, *buf);
    for (size_t i = 0; i < n; i++)
        if (!isfinite((*buf)[i])) (*buf)[i] = 0.0f; /* no solid: 0, as empty depth in an EXR */
    fs_aov *a = &view->aov[view->naovs++];
    snprintf(a->name, sizeof a->name, "%s", FS_AOV_SOLID_DEPTH);
    a->ncomp = 1;
    a->data = *buf;
    return FS_OK;
}
