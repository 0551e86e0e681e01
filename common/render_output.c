#include "render_output.h"
#include "fs_error.h"
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && !strcasecmp(s + n - k, suffix);
}

int fs_check_render_path(const char *path)
{
    if (ends_with(path, ".png") || ends_with(path, ".exr")) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: output must end in .png or .exr", path);
}

int fs_write_render(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov)
{
    int rc = fs_check_render_path(path);
    if (rc) return rc;
    size_t n = (size_t)g->w * g->h;
    if (ends_with(path, ".png")) {
        const char *names[4] = {"R", "G", "B", "A"};
        fs_image img = {g->w, g->h, 4, names, (float *)rgba};
        return fs_write_png(path, &img);
    }
    static const char *names[] = {"R", "G", "B", "A", "depth", "normal.X", "normal.Y", "normal.Z", "thickness",
                                  "coverage", "color.R", "color.G", "color.B", "color.A"};
    int nch = g->color ? 14 : 10;
    float *pix = malloc(n * nch * sizeof(float));
    if (!pix) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    for (size_t i = 0; i < n; i++) {
        float *o = pix + i * nch;
        memcpy(o, rgba + 4 * i, 4 * sizeof(float));
        o[4] = g->depth[i];
        memcpy(o + 5, g->normal + 3 * i, 3 * sizeof(float));
        o[8] = g->thickness[i];
        o[9] = g->coverage[i];
        if (g->color) memcpy(o + 10, g->color + 4 * i, 4 * sizeof(float));
    }
    fs_image img = {g->w, g->h, nch, names, pix};
    rc = fs_write_exr(path, &img, prov->attr, prov->n);
    free(pix);
    return rc;
}
