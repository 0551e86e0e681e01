#include "render_output.h"
#include "image_io.h"
#include "output_file.h"
#include "fs_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int fs_check_render_path(const char *path)
{
    if (fs_path_ends_with(path, ".png") || fs_path_ends_with(path, ".exr")) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: output must end in .png or .exr", path);
}

int fs_write_render(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov)
{
    int rc = fs_check_render_path(path);
    if (rc) return rc;
    size_t n = (size_t)g->w * g->h;
    if (fs_path_ends_with(path, ".png")) {
        const char *names[4] = {"R", "G", "B", "A"};
        fs_image img = {g->w, g->h, 4, names, (float *)rgba};
        return fs_write_png(path, &img);
    }
    const char *names[19] = {"R", "G", "B", "A", "depth", "normal.X", "normal.Y", "normal.Z", "thickness", "coverage"};
    int nch = 10, col = -1, own = -1;
    if (g->color) {
        static const char *cn[] = {"color.R", "color.G", "color.B", "color.A"};
        col = nch;
        for (int k = 0; k < 4; k++) names[nch++] = cn[k];
    }
    if (g->own) {
        static const char *on[] = {"own.R", "own.G", "own.B", "own.A", "caustics"};
        own = nch;
        for (int k = 0; k < 5; k++) names[nch++] = on[k];
    }
    float *pix = malloc(n * nch * sizeof(float));
    if (!pix) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    for (size_t i = 0; i < n; i++) {
        float *o = pix + i * nch;
        memcpy(o, rgba + 4 * i, 4 * sizeof(float));
        o[4] = g->depth[i];
        memcpy(o + 5, g->normal + 3 * i, 3 * sizeof(float));
        o[8] = g->thickness[i];
        o[9] = g->coverage[i];
        if (col >= 0) memcpy(o + col, g->color + 4 * i, 4 * sizeof(float));
        if (own >= 0) {
            memcpy(o + own, g->own + 4 * i, 4 * sizeof(float));
            o[own + 4] = g->caustics[i];
        }
    }
    fs_image img = {g->w, g->h, nch, names, pix};
    rc = fs_write_exr(path, &img, prov->attr, prov->n);
    free(pix);
    return rc;
}

int fs_read_render(const char *path, fs_gbuffer *g, float **rgba, float *r_out)
{
    fs_image img;
    memset(g, 0, sizeof *g);
    *rgba = NULL;
    int rc = fs_read_image(path, &img);
    if (rc) return rc;
    static const char *need[] = {"R", "G", "B", "A", "depth", "normal.X", "normal.Y", "normal.Z", "coverage"};
    int ch[9];
    for (int k = 0; k < 9; k++)
        if ((ch[k] = fs_image_channel(&img, need[k])) < 0) {
            fs_image_free(&img);
            return fs_fail(FS_ERR_INPUT, "%s: no channel '%s' (not a fluidsurf G-buffer EXR)", path, need[k]);
        }
    int th = fs_image_channel(&img, "thickness"), col[4];
    static const char *cn[] = {"color.R", "color.G", "color.B", "color.A"};
    int has_color = 1;
    for (int k = 0; k < 4; k++) has_color &= (col[k] = fs_image_channel(&img, cn[k])) >= 0;
    size_t n = (size_t)img.w * img.h;
    if ((rc = fs_gbuffer_alloc(g, img.w, img.h, has_color)) || !(*rgba = malloc(n * 4 * sizeof(float)))) {
        fs_gbuffer_free(g);
        fs_image_free(&img);
        return rc ? rc : fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    }
    for (size_t i = 0; i < n; i++) {
        const float *px = img.pix + i * img.nch;
        for (int k = 0; k < 4; k++) (*rgba)[4 * i + k] = px[ch[k]];
        float cov = px[ch[8]] > 0.5f ? 1.0f : 0.0f;
        g->coverage[i] = cov;
        g->depth[i] = cov ? px[ch[4]] : INFINITY;
        for (int k = 0; k < 3; k++) g->normal[3 * i + k] = cov ? px[ch[5 + k]] : 0.0f;
        g->thickness[i] = th >= 0 ? px[th] : 0.0f;
        if (has_color)
            for (int k = 0; k < 4; k++) g->color[4 * i + k] = px[col[k]];
    }
    fs_image_free(&img);
    char buf[64];
    *r_out = 0;
    if (fs_read_image_attr(path, "fluidsurf:r", buf, sizeof buf) == 1) *r_out = strtof(buf, NULL);
    return FS_OK;
}
