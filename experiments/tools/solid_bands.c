/* solid_bands: normal and depth error of rendered G-buffers against a reference
 * one in a scene with obstacles, split by where the reference surface point lies:
 * within BAND of an obstacle's surface (the fluid-solid interface, xu2022 Fig. 5)
 * or farther. Pixels an obstacle hides are left out, as the compare metrics do.
 *
 *   solid_bands [--band R_MULT] SCENE.json REFERENCE.exr METHOD.exr...
 *
 * The camera is the scene's (it must give one), at the EXR's size. Prints CSV rows
 * file,region,pixels,mean_deg,p95_deg,depth_mean_r. Regions: visible (both cover,
 * no obstacle in front), interface (visible, < BAND from an obstacle), away
 * (visible, >= BAND). depth_mean_r: mean |depth - reference depth| in r. */
#include "camera.h"
#include "fs_error.h"
#include "image_io.h"
#include "metrics.h"
#include "obstacle_mask.h"
#include "render_output.h"
#include "scene.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { R_VISIBLE, R_INTERFACE, R_AWAY, R_COUNT };
static const char *region_names[R_COUNT] = {"visible", "interface", "away"};

/* Per reference pixel: distance from its surface point to the nearest obstacle
 * (INFINITY where the reference is empty). */
static void solid_distance(const fs_scene *s, const fs_camera *cam, const fs_gbuffer *ref, float *dist)
{
    float right[3], up[3], fwd[3], dir[3];
    fs_camera_basis(cam, right, up, fwd);
    for (int y = 0; y < ref->h; y++)
        for (int x = 0; x < ref->w; x++) {
            int i = y * ref->w + x;
            dist[i] = INFINITY;
            if (ref->coverage[i] < 0.5f || !isfinite(ref->depth[i])) continue;
            fs_camera_ray(cam, x + 0.5f, y + 0.5f, dir);
            float t = ref->depth[i] / (dir[0] * fwd[0] + dir[1] * fwd[1] + dir[2] * fwd[2]), p[3];
            for (int a = 0; a < 3; a++) p[a] = cam->eye[a] + t * dir[a];
            for (int k = 0; k < s->obstacles.n; k++)
                dist[i] = fminf(dist[i], fabsf(fs_obstacle_distance(&s->obstacles.o[k], p)));
        }
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* One region's row: mean and 95th percentile (nearest rank) of the angle, mean depth error. */
static void print_region(const char *path, int reg, const float *deg, const float *derr, const float *dist,
                         const unsigned char *hidden, size_t n, float band, float *vals)
{
    size_t m = 0;
    double sum = 0, dsum = 0;
    for (size_t i = 0; i < n; i++) {
        if (isnan(deg[i]) || hidden[i]) continue;
        if ((reg == R_INTERFACE && !(dist[i] < band)) || (reg == R_AWAY && dist[i] < band)) continue;
        vals[m++] = deg[i];
        sum += deg[i];
        dsum += derr[i];
    }
    if (m) qsort(vals, m, sizeof *vals, cmp_float);
    double p95 = m ? vals[(size_t)ceil(0.95 * m) - 1] : NAN;
    printf("%s,%s,%zu,%.4f,%.4f,%.4f\n", path, region_names[reg], m, m ? sum / m : NAN, p95, m ? dsum / m : NAN);
}

static int report(const char *path, const fs_gbuffer *ref, const float *dist, const unsigned char *hidden, float band,
                  float r)
{
    fs_gbuffer g;
    float *rgba = NULL, rr = 0;
    int rc = fs_read_render(path, &g, &rgba, &rr);
    if (rc) return rc;
    free(rgba);
    if (g.w != ref->w || g.h != ref->h) {
        fs_gbuffer_free(&g);
        return fs_fail(FS_ERR_INPUT, "%s: %dx%d, the reference is %dx%d", path, g.w, g.h, ref->w, ref->h);
    }
    size_t n = (size_t)g.w * g.h;
    float *deg = malloc(n * sizeof *deg), *derr = malloc(n * sizeof *derr), *vals = malloc(n * sizeof *vals);
    if (deg && derr && vals) {
        fs_normal_error_map(&g, ref, deg);
        fs_depth_error_map(&g, ref, r, 0.0, derr); /* |a - b| in r, no bias removed */
        for (int reg = 0; reg < R_COUNT; reg++) print_region(path, reg, deg, derr, dist, hidden, n, band, vals);
    } else rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    free(deg), free(derr), free(vals);
    fs_gbuffer_free(&g);
    return rc;
}

int main(int argc, char **argv)
{
    float band_r = 3.0f;
    int a = 1;
    if (a + 1 < argc && !strcmp(argv[a], "--band")) {
        char *end;
        band_r = strtof(argv[a + 1], &end);
        if (*end || !(band_r > 0)) {
            fprintf(stderr, "solid_bands: --band %s: expected a positive number\n", argv[a + 1]);
            return FS_ERR_INPUT;
        }
        a += 2;
    }
    if (argc - a < 3) {
        fprintf(stderr, "usage: solid_bands [--band R_MULT] SCENE.json REFERENCE.exr METHOD.exr...\n");
        return FS_ERR_INPUT;
    }
    fs_scene s;
    fs_gbuffer ref;
    float *rgba = NULL, r = 0;
    int rc = fs_scene_load(&s, argv[a]);
    if (!rc && (!s.has_camera || !s.obstacles.n))
        rc = fs_fail(FS_ERR_INPUT, "%s: needs a camera with \"eye\" and \"target\", and obstacles", argv[a]);
    if (!rc) rc = fs_read_render(argv[a + 1], &ref, &rgba, &r);
    if (rc) {
        fprintf(stderr, "solid_bands: %s\n", fs_error_message());
        return rc;
    }
    free(rgba);
    s.camera.width = ref.w;
    s.camera.height = ref.h;
    size_t n = (size_t)ref.w * ref.h;
    float *dist = malloc(n * sizeof *dist);
    unsigned char *hidden = malloc(n);
    rc = dist && hidden ? fs_obstacle_hidden_mask(&s, &s.camera, &ref, hidden)
                        : fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc) {
        solid_distance(&s, &s.camera, &ref, dist);
        printf("# solid_bands: scene %s, reference %s, band %g r (%g)\n", argv[a], argv[a + 1], band_r,
               band_r * s.radius);
        printf("file,region,pixels,mean_deg,p95_deg,depth_mean_r\n");
    }
    for (int i = a + 2; i < argc && !rc; i++) rc = report(argv[i], &ref, dist, hidden, band_r * s.radius, s.radius);
    if (rc) fprintf(stderr, "solid_bands: %s\n", fs_error_message());
    free(dist), free(hidden);
    fs_gbuffer_free(&ref);
    return rc;
}
