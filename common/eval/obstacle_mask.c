/* Obstacle-hidden pixels left out of the metrics (obstacle_mask.h). */
#include "obstacle_mask.h"
#include "fs_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int fs_obstacle_hidden_mask(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *ref, unsigned char *hidden)
{
    size_t n = (size_t)ref->w * ref->h;
    memset(hidden, 0, n);
    if (!s->obstacles.n) return FS_OK;
    float *depth = malloc(n * sizeof *depth);
    if (!depth) return fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", ref->w, ref->h);
    fs_obstacles_depth(&s->obstacles, cam, ref->w, ref->h, depth);
    for (size_t i = 0; i < n; i++) {
        int fluid = ref->coverage[i] >= 0.5f && isfinite(ref->depth[i]);
        hidden[i] = isfinite(depth[i]) && (!fluid || depth[i] < ref->depth[i]);
    }
    free(depth);
    return FS_OK;
}

/* A view of g whose coverage is `cov`: g's with the hidden pixels emptied. */
static fs_gbuffer masked_view(const fs_gbuffer *g, const unsigned char *hidden, float *cov)
{
    fs_gbuffer v = *g;
    size_t n = (size_t)g->w * g->h;
    for (size_t i = 0; i < n; i++) cov[i] = hidden[i] ? 0.0f : g->coverage[i];
    v.coverage = cov;
    return v;
}

int fs_metrics_compute_in_scene(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *a, const float *rgba_a,
                                const fs_gbuffer *b, const float *rgba_b, fs_metrics *out)
{
    if (!s->obstacles.n || !a || !b || !a->coverage || !b->coverage || a->w != b->w || a->h != b->h)
        return fs_metrics_compute(a, rgba_a, b, rgba_b, s->radius, out); /* which reports what is wrong */
    size_t n = (size_t)b->w * b->h;
    unsigned char *hidden = malloc(n);
    float *cov = malloc(2 * n * sizeof *cov);
    int rc = hidden && cov ? fs_obstacle_hidden_mask(s, cam, b, hidden)
                           : fs_fail(FS_ERR_RUNTIME, "metrics: out of memory for %dx%d images", b->w, b->h);
    if (!rc) {
        fs_gbuffer va = masked_view(a, hidden, cov), vb = masked_view(b, hidden, cov + n);
        rc = fs_metrics_compute(&va, rgba_a, &vb, rgba_b, s->radius, out);
    }
    free(hidden);
    free(cov);
    return rc;
}
