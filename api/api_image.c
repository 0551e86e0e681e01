/* Images of the library: a rendered or read G-buffer (with the file's provenance
 * and camera), or one of the caller's arrays, its stages and provenance. */
#include "api_internal.h"
#include "fs_error.h"
#include "image_io.h"
#include "output_file.h"
#include "render_output.h"
#include "camera_text.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The file's provenance, and the camera it names (a file without one has none). */
static int keep_file_facts(const char *path, fluidsurf_image *im)
{
    if (fs_read_image_provenance(path, &im->prov) < 0) return FS_ERR_INPUT;
    const char *cam = fs_provenance_get(&im->prov, "camera");
    if (!cam) return FLUIDSURF_OK;
    unsigned given;
    int rc = fs_camera_parse(cam, path, &im->camera, &given);
    if (rc) return rc;
    im->has_camera = 1;
    return FLUIDSURF_OK;
}

int fluidsurf_image_read(const char *path, fluidsurf_image **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out")) || (rc = fs_api_check(path, "path"))) return rc;
    fs_api_init();
    *out = NULL;
    fluidsurf_image *im = calloc(1, sizeof *im);
    if (!im) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!(rc = fs_read_render(path, &im->im.g, &im->im.rgba, &im->radius))) rc = keep_file_facts(path, im);
    if (rc) {
        fluidsurf_image_free(im);
        return rc;
    }
    *out = im;
    return FLUIDSURF_OK;
}

/* n floats of src (NULL: leave dst as allocated, cleared) into dst. */
static void copy_layer(float *dst, const float *src, size_t n)
{
    if (src) memcpy(dst, src, n * sizeof *src);
}

int fluidsurf_image_from_arrays(int w, int h, const float *depth, const float *normal, const float *thickness,
                                const float *coverage, const float *rgba, double radius, fluidsurf_image **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out")) || (rc = fs_api_check(depth, "depth")) ||
        (rc = fs_api_check(normal, "normal")) || (rc = fs_api_check(coverage, "coverage")))
        return rc;
    *out = NULL;
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
        return fs_fail(FS_ERR_INPUT, "image size %dx%d: each side 1 to 16384", w, h);
    if (!(radius >= 0)) return fs_fail(FS_ERR_INPUT, "radius %g: must be 0 or positive", radius);
    fluidsurf_image *im = calloc(1, sizeof *im);
    size_t n = (size_t)w * h;
    if (!im || fs_gbuffer_alloc(&im->im.g, w, h) || (rgba && !(im->im.rgba = malloc(n * 4 * sizeof(float))))) {
        fluidsurf_image_free(im);
        return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    copy_layer(im->im.g.depth, depth, n), copy_layer(im->im.g.normal, normal, 3 * n);
    copy_layer(im->im.g.thickness, thickness, n), copy_layer(im->im.g.coverage, coverage, n);
    copy_layer(im->im.rgba, rgba, 4 * n);
    im->radius = (float)radius;
    *out = im;
    return FLUIDSURF_OK;
}

/* Names an AOV may not take: the core layers and the EXR's R G B A channels. */
static int core_name(const char *name)
{
    static const char *const core[] = {"depth", "normal", "thickness", "coverage", "rgba", "R", "G", "B", "A"};
    for (size_t i = 0; i < sizeof core / sizeof *core; i++)
        if (!strcmp(core[i], name)) return 1;
    return 0;
}

int fluidsurf_image_set_layer(fluidsurf_image *im, const char *name, int ncomp, const float *data)
{
    int rc;
    if ((rc = fs_api_check(im, "image")) || (rc = fs_api_check(name, "name")) || (rc = fs_api_check(data, "data")))
        return rc;
    if (core_name(name)) return fs_fail(FS_ERR_INPUT, "layer '%s': a core layer, set when the image is made", name);
    fs_gbuffer *g = &im->im.g;
    if ((rc = fs_gbuffer_add_aov(g, name, ncomp))) return rc; /* one of this name is kept, and written over */
    copy_layer(fs_gbuffer_aov(g, name), data, (size_t)ncomp * g->w * g->h);
    return FLUIDSURF_OK;
}

int fluidsurf_image_set_solid_depth(fluidsurf_image *im, const float *solid_depth)
{
    return fluidsurf_image_set_layer(im, FS_AOV_SOLID_DEPTH, 1, solid_depth);
}

int fs_api_set_provenance(fs_provenance *p, const char *name, const char *value)
{
    int rc;
    if ((rc = fs_api_check(name, "name")) || (rc = fs_api_check(value, "value"))) return rc;
    size_t n = strlen(name), v = strlen(value);
    if (strncmp(name, "fluidsurf:", 10) || n == 10 || n >= sizeof p->name[0] || strpbrk(name, "=\n\r"))
        return fs_fail(FS_ERR_INPUT, "provenance name '%.60s': expected fluidsurf:NAME, at most %zu characters", name,
                       sizeof p->name[0] - 1);
    if (v >= sizeof p->value[0] || strpbrk(value, "\n\r"))
        return fs_fail(FS_ERR_INPUT, "provenance %s: expected one line of at most %zu characters", name,
                       sizeof p->value[0] - 1);
    if (!fs_provenance_get(p, name + 10) && p->n == FS_PROV_MAX)
        return fs_fail(FS_ERR_INPUT, "provenance %s: %d entries already", name, FS_PROV_MAX);
    fs_camera cam = {0};
    unsigned given;
    if (!strcmp(name, "fluidsurf:camera") && (rc = fs_camera_parse(value, name, &cam, &given))) return rc;
    fs_provenance_set(p, name + 10, value);
    return FLUIDSURF_OK;
}

int fluidsurf_image_set_provenance(fluidsurf_image *im, const char *name, const char *value)
{
    int rc = fs_api_check(im, "image");
    return rc ? rc : fs_api_set_provenance(&im->prov, name, value);
}

int fluidsurf_image_write(const fluidsurf_image *im, const char *path)
{
    int rc;
    if ((rc = fs_api_check(im, "image")) || (rc = fs_api_check(path, "path")) || (rc = fs_check_render_path(path)))
        return rc;
    /* an EXR without the shaded image would give diff a black one to measure PSNR and SSIM on */
    if (!im->im.rgba) return fs_fail(FS_ERR_INPUT, "%s: the image has no shaded rgba to write", path);
    return fs_write_render(path, &im->im.g, im->im.rgba, &im->prov);
}

void fluidsurf_image_free(fluidsurf_image *im)
{
    if (!im) return;
    fs_run_image_free(&im->im);
    free(im);
}

int fluidsurf_image_width(const fluidsurf_image *im) { return im ? im->im.g.w : 0; }
int fluidsurf_image_height(const fluidsurf_image *im) { return im ? im->im.g.h : 0; }
double fluidsurf_image_radius(const fluidsurf_image *im) { return im ? im->radius : 0; }

int fluidsurf_image_camera(const fluidsurf_image *im, fluidsurf_camera *c)
{
    int rc;
    if ((rc = fs_api_check(im, "image")) || (rc = fs_api_check(c, "camera"))) return rc;
    if (!im->has_camera) return fs_fail(FS_ERR_INPUT, "image: not rendered by this library, so it has no camera");
    fs_api_camera_out(&im->camera, c);
    return FLUIDSURF_OK;
}

const float *fluidsurf_image_layer(const fluidsurf_image *im, const char *name, int *ncomp)
{
    if (ncomp) *ncomp = 0;
    if (!im || !name) return NULL;
    const fs_gbuffer *g = &im->im.g;
    const struct {
        const char *name;
        const float *data;
        int ncomp;
    } core[] = {
        {"depth", g->depth, 1},       {"normal", g->normal, 3}, {"thickness", g->thickness, 1},
        {"coverage", g->coverage, 1}, {"rgba", im->im.rgba, 4},
    };
    for (size_t i = 0; i < sizeof core / sizeof *core; i++)
        if (!strcmp(core[i].name, name)) {
            if (ncomp && core[i].data) *ncomp = core[i].ncomp;
            return core[i].data;
        }
    for (int i = 0; i < g->naovs; i++)
        if (!strcmp(g->aov[i].name, name)) {
            if (ncomp) *ncomp = g->aov[i].ncomp;
            return g->aov[i].data;
        }
    return NULL;
}

int fluidsurf_image_aov_count(const fluidsurf_image *im) { return im ? im->im.g.naovs : 0; }
const char *fluidsurf_image_aov_name(const fluidsurf_image *im, int i)
{
    return im && i >= 0 && i < im->im.g.naovs ? im->im.g.aov[i].name : NULL;
}

static int stage_ok(const fluidsurf_image *im, int i) { return im && i >= 0 && i < im->st.n; }
int fluidsurf_image_stage_count(const fluidsurf_image *im) { return im ? im->st.n : 0; }
const char *fluidsurf_image_stage_name(const fluidsurf_image *im, int i)
{
    return stage_ok(im, i) ? im->st.name[i] : NULL;
}
double fluidsurf_image_stage_ms(const fluidsurf_image *im, int i) { return stage_ok(im, i) ? im->st.ms[i] : 0; }
const char *fluidsurf_image_stage_renderer(const fluidsurf_image *im, int i)
{
    return stage_ok(im, i) ? im->renderer[i] : NULL;
}

static int prov_ok(const fluidsurf_image *im, int i) { return im && i >= 0 && i < im->prov.n; }
int fluidsurf_image_provenance_count(const fluidsurf_image *im) { return im ? im->prov.n : 0; }
const char *fluidsurf_image_provenance_name(const fluidsurf_image *im, int i)
{
    return prov_ok(im, i) ? im->prov.name[i] : NULL;
}
const char *fluidsurf_image_provenance_value(const fluidsurf_image *im, int i)
{
    return prov_ok(im, i) ? im->prov.value[i] : NULL;
}
