#include "gbuffer.h"
#include "fs_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int fs_gbuffer_alloc(fs_gbuffer *g, int w, int h, int with_color)
{
    memset(g, 0, sizeof *g);
    size_t n = (size_t)w * h;
    g->w = w;
    g->h = h;
    g->depth = malloc(n * sizeof(float));
    g->normal = malloc(3 * n * sizeof(float));
    g->thickness = malloc(n * sizeof(float));
    g->coverage = malloc(n * sizeof(float));
    g->color = with_color ? malloc(4 * n * sizeof(float)) : NULL;
    if (!g->depth || !g->normal || !g->thickness || !g->coverage || (with_color && !g->color)) {
        fs_gbuffer_free(g);
        return fs_fail(FS_ERR_RUNTIME, "out of memory for a %dx%d G-buffer", w, h);
    }
    fs_gbuffer_clear(g);
    return FS_OK;
}

int fs_gbuffer_alloc_own(fs_gbuffer *g)
{
    size_t n = (size_t)g->w * g->h;
    if (!g->own) g->own = calloc(4 * n, sizeof(float));
    if (!g->caustics) g->caustics = calloc(n, sizeof(float));
    if (!g->own || !g->caustics) return fs_fail(FS_ERR_RUNTIME, "out of memory for a %dx%d G-buffer", g->w, g->h);
    return FS_OK;
}

void fs_gbuffer_clear(fs_gbuffer *g)
{
    size_t n = (size_t)g->w * g->h;
    for (size_t i = 0; i < n; i++) g->depth[i] = INFINITY;
    memset(g->normal, 0, 3 * n * sizeof(float));
    memset(g->thickness, 0, n * sizeof(float));
    memset(g->coverage, 0, n * sizeof(float));
    if (g->color) memset(g->color, 0, 4 * n * sizeof(float));
    if (g->own) memset(g->own, 0, 4 * n * sizeof(float));
    if (g->caustics) memset(g->caustics, 0, n * sizeof(float));
}

void fs_gbuffer_free(fs_gbuffer *g)
{
    free(g->depth);
    free(g->normal);
    free(g->thickness);
    free(g->coverage);
    free(g->color);
    free(g->own);
    free(g->caustics);
    memset(g, 0, sizeof *g);
}
