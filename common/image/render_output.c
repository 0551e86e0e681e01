#include "render_output.h"
#include "camera_text.h"
#include "image_io.h"
#include "obstacle_mask.h"
#include "output_file.h"
#include "fs_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int fs_check_render_path(const char *path)
{
    if (fs_path_ends_with(path, ".png") || fs_path_ends_with(path, ".exr")) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: output must end in .png or .exr", path);
}

int fs_read_render_camera(const char *path, fs_camera *c)
{
    char text[FS_CAMERA_TEXT_MAX];
    int got = fs_read_image_attr(path, "fluidsurf:camera", text, sizeof text);
    if (got < 0) return FS_ERR_INPUT;
    if (!got) return fs_fail(FS_ERR_INPUT, "%s: no fluidsurf:camera (not an image fluidsurf rendered)", path);
    unsigned given;
    int rc = fs_camera_parse(text, path, c, &given);
    if (!rc && given != (FS_CAMERA_HAS_UP | FS_CAMERA_HAS_FOV | FS_CAMERA_HAS_SIZE))
        rc = fs_fail(FS_ERR_INPUT, "%s: fluidsurf:camera '%s' lacks up, fov or size", path, text);
    return rc;
}

/* The suffixes of a 4-component AOV's channels: NAME.R NAME.G NAME.B NAME.A. */
static const char *const rgba_suffix[4] = {"R", "G", "B", "A"};

/* The core layers' channels, in the order they are written. */
enum { CORE_CHANNELS = 10 };
static const char *const core_names[CORE_CHANNELS] = {"R",        "G",        "B",        "A",         "depth",
                                                      "normal.X", "normal.Y", "normal.Z", "thickness", "coverage"};

/* An AOV's EXR channel names into names (from names[0]); returns how many. */
static int aov_channel_names(const fs_aov *a, char names[][FS_AOV_NAME_MAX + 2])
{
    if (a->ncomp == 1) {
        snprintf(names[0], FS_AOV_NAME_MAX + 2, "%s", a->name);
        return 1;
    }
    for (int k = 0; k < 4; k++) snprintf(names[k], FS_AOV_NAME_MAX + 2, "%s.%s", a->name, rgba_suffix[k]);
    return 4;
}

/* One pixel of the EXR: the core channels, then every AOV's components. An empty
 * pixel's depth (infinity in memory) is written as FS_EXR_EMPTY_DEPTH. */
static void pack_pixel(const fs_gbuffer *g, const float *rgba, size_t i, float *o)
{
    memcpy(o, rgba + 4 * i, 4 * sizeof(float));
    o[4] = g->coverage[i] > 0.5f ? g->depth[i] : FS_EXR_EMPTY_DEPTH;
    memcpy(o + 5, g->normal + 3 * i, 3 * sizeof(float));
    o[8] = g->thickness[i];
    o[9] = g->coverage[i];
    o += CORE_CHANNELS;
    for (int a = 0; a < g->naovs; a++) {
        int c = g->aov[a].ncomp;
        memcpy(o, g->aov[a].data + c * i, c * sizeof(float));
        o += c;
    }
}

static int write_exr(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov)
{
    char aov_names[4 * FS_GBUFFER_MAX_AOVS][FS_AOV_NAME_MAX + 2];
    const char *names[CORE_CHANNELS + 4 * FS_GBUFFER_MAX_AOVS];
    int nch = 0, naov = 0;
    for (; nch < CORE_CHANNELS; nch++) names[nch] = core_names[nch];
    for (int a = 0; a < g->naovs; a++) naov += aov_channel_names(&g->aov[a], aov_names + naov);
    for (int k = 0; k < naov; k++) names[nch++] = aov_names[k];
    size_t n = (size_t)g->w * g->h;
    float *pix = malloc(n * nch * sizeof(float));
    if (!pix) return fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    for (size_t i = 0; i < n; i++) pack_pixel(g, rgba, i, pix + i * nch);
    fs_image img = {g->w, g->h, nch, names, pix};
    fs_attr attrs[FS_PROV_MAX + 1]; /* the provenance, then how empty depth is marked */
    memcpy(attrs, prov->attr, (size_t)prov->n * sizeof *attrs);
    attrs[prov->n] = (fs_attr){"fluidsurf:empty_depth", FS_EXR_EMPTY_DEPTH_TEXT};
    int rc = fs_write_exr(path, &img, attrs, prov->n + 1);
    free(pix);
    return rc;
}

int fs_write_render(const char *path, const fs_gbuffer *g, const float *rgba, const fs_provenance *prov)
{
    int rc = fs_check_render_path(path);
    if (rc) return rc;
    if (fs_path_ends_with(path, ".exr")) return write_exr(path, g, rgba, prov);
    const char *names[4] = {"R", "G", "B", "A"};
    fs_image img = {g->w, g->h, 4, names, (float *)rgba};
    return fs_write_png(path, &img);
}

int fs_write_render_in_scene(const char *path, const fs_scene *s, const fs_camera *cam, const fs_gbuffer *g,
                             const float *rgba, const fs_provenance *prov)
{
    if (!fs_path_ends_with(path, ".exr")) return fs_write_render(path, g, rgba, prov);
    fs_gbuffer view;
    float *buf;
    int rc = fs_solids_layer(s, cam, g, &view, &buf);
    if (!rc) rc = fs_write_render(path, &view, rgba, prov);
    free(buf);
    return rc;
}

static int is_core_channel(const char *name)
{
    for (int k = 0; k < CORE_CHANNELS; k++)
        if (!strcmp(name, core_names[k])) return 1;
    return 0;
}

/* The channels of the 4-component AOV called base (NAME.R NAME.G NAME.B NAME.A)
 * into ch: 1 when all four are there. */
static int rgba_group(const fs_image *img, const char *base, int ch[4])
{
    char name[FS_AOV_NAME_MAX + 3];
    for (int k = 0; k < 4; k++) {
        snprintf(name, sizeof name, "%s.%s", base, rgba_suffix[k]);
        if ((ch[k] = fs_image_channel(img, name)) < 0) return 0;
    }
    return 1;
}

/* Adds to g an AOV for every channel group beyond the core: a channel NAME
 * without a '.' (1 component), a complete group NAME.R/G/B/A (4); src gets the
 * image channel of each component. Other channels (another tool's) are skipped. */
static int add_read_aovs(const char *path, const fs_image *img, fs_gbuffer *g, int src[][4])
{
    for (int c = 0; c < img->nch; c++) {
        const char *nm = img->chnames[c], *dot = strrchr(nm, '.');
        char base[FS_AOV_NAME_MAX + 1]; /* room for one character too many: a long name is refused, not cut short */
        int ncomp = 1, ch[4] = {c};
        if (is_core_channel(nm)) continue;
        if (dot) { /* its group is added at its .R channel */
            if (strcmp(dot, ".R")) continue;
            snprintf(base, sizeof base, "%.*s", (int)(dot - nm), nm);
            if (!rgba_group(img, base, ch)) continue;
            ncomp = 4;
        } else snprintf(base, sizeof base, "%s", nm);
        int rc = fs_gbuffer_add_aov(g, base, ncomp);
        if (rc) {
            char why[256]; /* fs_fail must not format its own message into itself */
            snprintf(why, sizeof why, "%s", fs_error_message());
            return fs_fail(rc, "%s: %s", path, why);
        }
        memcpy(src[g->naovs - 1], ch, sizeof ch);
    }
    return FS_OK;
}

/* Pixel i of the image into g and rgba (depth and normal only where covered): an
 * empty pixel's depth becomes infinity whatever the file holds there, so files
 * that marked it with infinity (before fluidsurf:empty_depth) read the same. */
static void unpack_pixel(const float *px, const int core[CORE_CHANNELS], const int src[][4], size_t i, fs_gbuffer *g,
                         float *rgba)
{
    for (int k = 0; k < 4; k++) rgba[4 * i + k] = px[core[k]];
    float cov = px[core[9]] > 0.5f ? 1.0f : 0.0f;
    g->coverage[i] = cov;
    g->depth[i] = cov ? px[core[4]] : INFINITY;
    for (int k = 0; k < 3; k++) g->normal[3 * i + k] = cov ? px[core[5 + k]] : 0.0f;
    g->thickness[i] = core[8] >= 0 ? px[core[8]] : 0.0f;
    for (int a = 0; a < g->naovs; a++)
        for (int k = 0; k < g->aov[a].ncomp; k++) g->aov[a].data[g->aov[a].ncomp * i + k] = px[src[a][k]];
}

int fs_read_render(const char *path, fs_gbuffer *g, float **rgba, float *r_out)
{
    fs_image img;
    memset(g, 0, sizeof *g);
    *rgba = NULL;
    int rc = fs_read_image(path, &img);
    if (rc) return rc;
    int core[CORE_CHANNELS], src[FS_GBUFFER_MAX_AOVS][4];
    for (int k = 0; k < CORE_CHANNELS; k++)
        if ((core[k] = fs_image_channel(&img, core_names[k])) < 0 && k != 8) { /* thickness is optional */
            fs_image_free(&img);
            return fs_fail(FS_ERR_INPUT, "%s: no channel '%s' (not a fluidsurf G-buffer EXR)", path, core_names[k]);
        }
    size_t n = (size_t)img.w * img.h;
    if (!(rc = fs_gbuffer_alloc(g, img.w, img.h))) rc = add_read_aovs(path, &img, g, src);
    if (!rc && !(*rgba = malloc(n * 4 * sizeof(float)))) rc = fs_fail(FS_ERR_RUNTIME, "%s: out of memory", path);
    for (size_t i = 0; i < n && !rc; i++) unpack_pixel(img.pix + i * img.nch, core, src, i, g, *rgba);
    fs_image_free(&img);
    if (rc) {
        fs_gbuffer_free(g);
        free(*rgba);
        *rgba = NULL;
        return rc;
    }
    char buf[64];
    *r_out = 0;
    if (fs_read_image_attr(path, "fluidsurf:r", buf, sizeof buf) == 1) *r_out = strtof(buf, NULL);
    return FS_OK;
}
