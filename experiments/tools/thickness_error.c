/* thickness_error: a method's thickness layer against the reference's, over the
 * pixels both cover (coverage > 0.5) where the reference's thickness is > 0.
 *
 *   thickness_error [--map OUT.png] [--scale S] REFERENCE.exr METHOD.exr...
 *
 * Prints CSV rows (no header; the header is printed with --header alone):
 *   file,pixels,ref_mean_r,method_mean_r,ratio_of_means,mean_ratio,median_ratio,
 *   diff_mean_r,diff_abs_mean_r,diff_abs_p95_r
 * thicknesses and differences in multiples of the particle radius r (the EXRs'
 * fluidsurf:r); mean_ratio and median_ratio are of method / reference per pixel;
 * diff = method - reference; p95 is the nearest rank.
 * --map writes, for the first METHOD, the signed difference: white 0, red where the
 * method is thicker, blue where thinner, full colour at S r (default 4); grey where
 * only one of the two covers, dark blue-grey where neither does. */
#include "fs_error.h"
#include "gbuffer.h"
#include "image_io.h"
#include "percentile.h"
#include "render_output.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char header[] = "file,pixels,ref_mean_r,method_mean_r,ratio_of_means,mean_ratio,median_ratio,"
                             "diff_mean_r,diff_abs_mean_r,diff_abs_p95_r";

static int covered(const fs_gbuffer *g, size_t i) { return g->coverage[i] > 0.5f; }

/* One pixel of the difference map (RGB). */
static void map_pixel(const fs_gbuffer *ref, const fs_gbuffer *g, size_t i, float r, float scale, unsigned char *p)
{
    int a = covered(ref, i), b = covered(g, i);
    if (!a && !b) {
        p[0] = 60, p[1] = 60, p[2] = 90;
        return;
    }
    if (a != b || !(ref->thickness[i] > 0)) {
        p[0] = p[1] = p[2] = 150;
        return;
    }
    float d = (g->thickness[i] - ref->thickness[i]) / r / scale;
    float t = fminf(fabsf(d), 1.0f);
    unsigned char hi = 255, lo = (unsigned char)(255 * (1.0f - t));
    if (d > 0) p[0] = hi, p[1] = lo, p[2] = lo;
    else p[0] = lo, p[1] = lo, p[2] = hi;
}

static int compare(const char *path, const fs_gbuffer *ref, float r, const char *map, float scale)
{
    fs_gbuffer g;
    float *rgba = NULL, rg = 0;
    int rc = fs_read_render(path, &g, &rgba, &rg);
    free(rgba);
    if (rc) return rc;
    if (g.w != ref->w || g.h != ref->h) {
        rc = fs_fail(FS_ERR_INPUT, "%s: %dx%d, the reference is %dx%d", path, g.w, g.h, ref->w, ref->h);
        fs_gbuffer_free(&g);
        return rc;
    }
    size_t n = (size_t)g.w * g.h, m = 0;
    double *ratio = malloc(n * sizeof *ratio), *absd = malloc(n * sizeof *absd);
    if (!ratio || !absd) {
        free(ratio), free(absd), fs_gbuffer_free(&g);
        return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    double sr = 0, sm = 0, sratio = 0, sd = 0, sabs = 0;
    for (size_t i = 0; i < n; i++) {
        if (!covered(ref, i) || !covered(&g, i) || !(ref->thickness[i] > 0)) continue;
        double a = ref->thickness[i] / r, b = isfinite(g.thickness[i]) ? g.thickness[i] / r : 0;
        sr += a, sm += b, sd += b - a, sabs += fabs(b - a);
        ratio[m] = b / a;
        sratio += ratio[m];
        absd[m++] = fabs(b - a);
    }
    if (!m) {
        free(ratio), free(absd), fs_gbuffer_free(&g);
        return fs_fail(FS_ERR_INPUT, "%s: no pixel both cover with a reference thickness", path);
    }
    double med = fs_percentile(ratio, m, 50), p95 = fs_percentile(absd, m, 95);
    printf("%s,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", path, m, sr / m, sm / m, sm / sr, sratio / m, med,
           sd / m, sabs / m, p95);
    if (map) {
        unsigned char *pix = malloc(n * 3);
        if (!pix) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
        else {
            for (size_t i = 0; i < n; i++) map_pixel(ref, &g, i, r, scale, pix + 3 * i);
            rc = fs_write_png8(map, pix, g.w, g.h, 3);
            free(pix);
        }
    }
    free(ratio), free(absd);
    fs_gbuffer_free(&g);
    return rc;
}

int main(int argc, char **argv)
{
    const char *map = NULL;
    float scale = 4.0f;
    int a = 1;
    if (argc == 2 && !strcmp(argv[1], "--header")) return puts(header) < 0;
    for (; a < argc && argv[a][0] == '-'; a++) {
        if (!strcmp(argv[a], "--map") && a + 1 < argc) map = argv[++a];
        else if (!strcmp(argv[a], "--scale") && a + 1 < argc) {
            char *end;
            scale = strtof(argv[++a], &end);
            if (*end || !(scale > 0)) {
                fprintf(stderr, "thickness_error: --scale %s: expected a positive number\n", argv[a]);
                return FS_ERR_INPUT;
            }
        } else {
            fprintf(stderr, "thickness_error: unknown option %s\n", argv[a]);
            return FS_ERR_INPUT;
        }
    }
    if (argc - a < 2) {
        fprintf(stderr,
                "usage: thickness_error [--map OUT.png] [--scale S] REFERENCE.exr METHOD.exr...\n"
                "       thickness_error --header\n");
        return FS_ERR_INPUT;
    }
    fs_gbuffer ref;
    float *rgba = NULL, r = 0;
    int rc = fs_read_render(argv[a], &ref, &rgba, &r);
    free(rgba);
    if (!rc && !(r > 0)) {
        fs_gbuffer_free(&ref);
        rc = fs_fail(FS_ERR_INPUT, "%s: no fluidsurf:r attribute", argv[a]);
    }
    if (rc) {
        fprintf(stderr, "thickness_error: %s\n", fs_error_message());
        return rc;
    }
    for (int i = a + 1; i < argc && !rc; i++) {
        rc = compare(argv[i], &ref, r, i == a + 1 ? map : NULL, scale);
        if (rc) fprintf(stderr, "thickness_error: %s\n", fs_error_message());
    }
    fs_gbuffer_free(&ref);
    return rc;
}
