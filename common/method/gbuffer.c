#include "gbuffer.h"
#include "fs_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fs_gbuffer_alloc(fs_gbuffer *g, int w, int h)
{
    memset(g, 0, sizeof *g);
    size_t n = (size_t)w * h;
    g->w = w;
    g->h = h;
    g->depth = malloc(n * sizeof(float));
    g->normal = malloc(3 * n * sizeof(float));
    g->thickness = malloc(n * sizeof(float));
    g->coverage = malloc(n * sizeof(float));
    if (!g->depth || !g->normal || !g->thickness || !g->coverage) {
        fs_gbuffer_free(g);
        return fs_fail(FS_ERR_RUNTIME, "out of memory for a %dx%d G-buffer", w, h);
    }
    fs_gbuffer_clear(g);
    return FS_OK;
}

static const fs_aov *find_aov(const fs_gbuffer *g, const char *name)
{
    for (int i = 0; i < g->naovs; i++)
        if (!strcmp(g->aov[i].name, name)) return &g->aov[i];
    return NULL;
}

/* The components of a well-known AOV, 0 for any other name: readers such as the
 * shading index "color" 4 per pixel, so no file may give it another shape. */
static int known_components(const char *name)
{
    if (!strcmp(name, FS_AOV_COLOR) || !strcmp(name, FS_AOV_OWN)) return 4;
    return !strcmp(name, FS_AOV_CAUSTICS) || !strcmp(name, FS_AOV_SOLID_DEPTH) ? 1 : 0;
}

static int check_aov(const char *name, int ncomp)
{
    if (!name[0] || strlen(name) >= FS_AOV_NAME_MAX || strchr(name, '.'))
        return fs_fail(FS_ERR_INPUT, "AOV name '%s': must be 1 to %d characters, without '.'", name,
                       FS_AOV_NAME_MAX - 1);
    if (ncomp != 1 && ncomp != 4) return fs_fail(FS_ERR_INPUT, "AOV '%s': %d components, not 1 or 4", name, ncomp);
    int known = known_components(name);
    if (known && ncomp != known) return fs_fail(FS_ERR_INPUT, "AOV '%s' has %d components, not %d", name, known, ncomp);
    return FS_OK;
}

int fs_gbuffer_add_aov(fs_gbuffer *g, const char *name, int ncomp)
{
    int rc = check_aov(name, ncomp);
    if (rc) return rc;
    const fs_aov *have = find_aov(g, name);
    if (have && have->ncomp != ncomp)
        return fs_fail(FS_ERR_INPUT, "AOV '%s' is there with %d components", name, have->ncomp);
    if (have) return FS_OK;
    if (g->naovs == FS_GBUFFER_MAX_AOVS)
        return fs_fail(FS_ERR_RUNTIME, "AOV '%s': more than %d AOVs", name, FS_GBUFFER_MAX_AOVS);
    fs_aov *a = &g->aov[g->naovs];
    if (!(a->data = calloc((size_t)ncomp * g->w * g->h, sizeof(float))))
        return fs_fail(FS_ERR_RUNTIME, "out of memory for a %dx%d G-buffer", g->w, g->h);
    snprintf(a->name, sizeof a->name, "%s", name);
    a->ncomp = ncomp;
    g->naovs++;
    return FS_OK;
}

int fs_aov_own_look(const char *name) { return !strcmp(name, FS_AOV_OWN) || !strcmp(name, FS_AOV_CAUSTICS); }

float *fs_gbuffer_aov(const fs_gbuffer *g, const char *name)
{
    const fs_aov *a = find_aov(g, name);
    return a ? a->data : NULL;
}

void fs_gbuffer_clear(fs_gbuffer *g)
{
    size_t n = (size_t)g->w * g->h;
    for (size_t i = 0; i < n; i++) g->depth[i] = INFINITY;
    memset(g->normal, 0, 3 * n * sizeof(float));
    memset(g->thickness, 0, n * sizeof(float));
    memset(g->coverage, 0, n * sizeof(float));
    for (int i = 0; i < g->naovs; i++) memset(g->aov[i].data, 0, g->aov[i].ncomp * n * sizeof(float));
}

void fs_gbuffer_free(fs_gbuffer *g)
{
    free(g->depth);
    free(g->normal);
    free(g->thickness);
    free(g->coverage);
    for (int i = 0; i < g->naovs; i++) free(g->aov[i].data);
    memset(g, 0, sizeof *g);
}
