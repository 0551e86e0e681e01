/* edge_bands: normal error of rendered G-buffers against the `analytic` one of a
 * synthetic slab or box, split by where the ideal surface point lies: on a
 * face at least BAND from every ideal edge, or within BAND of an edge (where
 * two faces of the ideal box meet). The compare harness's interior mask keeps
 * the rounded edge band of a block, so its mean mixes the two.
 *
 *   edge_bands [--band R_MULT] [--profile] [--map OUT.png] SCENE.json ANALYTIC.exr METHOD.exr...
 *
 * The world point of each analytic pixel comes from its depth and the camera in
 * the EXR's provenance; the ideal box from the scene (lattice without jitter,
 * +- r). Prints CSV rows: file,region,pixels,mean_deg,p95_deg. Regions:
 *   interior     the harness's interior mask (both cover, >= 3 px from silhouettes)
 *   face         interior and >= BAND from every ideal edge (all faces)
 *   top          face, and on the face whose outward normal is +up
 *   edge_band    both cover and < BAND from an ideal edge (silhouette edges too)
 *   edge_band_interior  edge_band and interior
 * --profile adds rows edge_dist_A-Br: the interior mean in 0.5 r bins of the distance
 * to the nearest ideal edge (0 to 8 r; p95 left empty).
 * --map writes, for the first METHOD, the angle error (white = 0, black >= 10 deg)
 * with the edge band tinted red. */
#include "camera.h"
#include "fs_error.h"
#include "image_io.h"
#include "metrics.h"
#include "particles.h"
#include "render_output.h"
#include "scene.h"
#include "synthetic.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { R_INTERIOR, R_FACE, R_TOP, R_EDGE, R_EDGE_INTERIOR, R_COUNT };
static const char *region_names[R_COUNT] = {"interior", "face", "top", "edge_band", "edge_band_interior"};

static int parse_camera(const char *path, fs_camera *c)
{
    char buf[640];
    if (fs_read_image_attr(path, "fluidsurf:camera", buf, sizeof buf) != 1)
        return fs_fail(FS_ERR_INPUT, "%s: no fluidsurf:camera attribute", path);
    memset(c, 0, sizeof *c);
    if (sscanf(buf, "eye=%f,%f,%f;target=%f,%f,%f;up=%f,%f,%f;fov=%f;size=%dx%d", &c->eye[0], &c->eye[1], &c->eye[2],
               &c->target[0], &c->target[1], &c->target[2], &c->up[0], &c->up[1], &c->up[2], &c->fovy_deg, &c->width,
               &c->height) != 12)
        return fs_fail(FS_ERR_INPUT, "%s: cannot parse fluidsurf:camera '%s'", path, buf);
    return FS_OK;
}

/* Ideal box of a slab/box scene: lattice centres without jitter, grown by r. */
static int ideal_box(const char *scene_path, fs_scene *s, double lo[3], double hi[3])
{
    int rc = fs_scene_load(s, scene_path);
    if (rc) return rc;
    if (s->synth.shape != FS_SYNTH_SLAB && s->synth.shape != FS_SYNTH_BOX)
        return fs_fail(FS_ERR_INPUT, "%s: not a synthetic slab or box", scene_path);
    fs_scene flat = *s;
    flat.synth.jitter = 0;
    fs_particles p;
    rc = fs_synthetic_generate(&flat, 0, &p);
    if (rc) return rc;
    double mn[3] = {INFINITY, INFINITY, INFINITY}, mx[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < p.n; i++) {
        double v[3] = {p.x[i], p.y[i], p.z[i]};
        for (int a = 0; a < 3; a++) {
            if (v[a] < mn[a]) mn[a] = v[a];
            if (v[a] > mx[a]) mx[a] = v[a];
        }
    }
    for (int a = 0; a < 3; a++) {
        lo[a] = mn[a] - s->radius;
        hi[a] = mx[a] + s->radius;
    }
    fs_particles_free(&p);
    return FS_OK;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Per analytic pixel: distance (scene units) from its ideal surface point to the
 * nearest ideal edge, and whether the point lies on the +up face. */
static void classify(const fs_gbuffer *g, const fs_camera *cam, const double lo[3], const double hi[3], int up,
                     float *edge_dist, unsigned char *on_top)
{
    float right[3], upv[3], fwd[3], dir[3];
    fs_camera_basis(cam, right, upv, fwd);
    for (int y = 0; y < g->h; y++)
        for (int x = 0; x < g->w; x++) {
            int i = y * g->w + x;
            edge_dist[i] = INFINITY;
            on_top[i] = 0;
            if (g->coverage[i] < 0.5f) continue;
            fs_camera_ray(cam, x + 0.5f, y + 0.5f, dir);
            double t = g->depth[i] / (dir[0] * fwd[0] + dir[1] * fwd[1] + dir[2] * fwd[2]);
            double p[3];
            for (int a = 0; a < 3; a++) p[a] = cam->eye[a] + t * dir[a];
            /* The face the point lies on: the box plane it is closest to. */
            int face = 0, face_hi = 0;
            double best = INFINITY;
            for (int a = 0; a < 3; a++) {
                if (fabs(p[a] - lo[a]) < best) {
                    best = fabs(p[a] - lo[a]);
                    face = a;
                    face_hi = 0;
                }
                if (fabs(p[a] - hi[a]) < best) {
                    best = fabs(p[a] - hi[a]);
                    face = a;
                    face_hi = 1;
                }
            }
            double d = INFINITY;
            for (int b = 0; b < 3; b++)
                if (b != face) d = fmin(d, fmin(p[b] - lo[b], hi[b] - p[b]));
            edge_dist[i] = (float)d;
            on_top[i] = face == up && face_hi;
        }
}

static int report(const char *path, const fs_gbuffer *ana, const fs_camera *cam, const float *edge_dist,
                  const unsigned char *on_top, float band, float r_scene, int profile, const char *map_path)
{
    fs_gbuffer g;
    float *rgba = NULL, r = 0;
    int rc = fs_read_render(path, &g, &rgba, &r);
    if (rc) return rc;
    free(rgba);
    if (g.w != ana->w || g.h != ana->h) {
        fs_gbuffer_free(&g);
        return fs_fail(FS_ERR_INPUT, "%s: %dx%d, the analytic G-buffer is %dx%d", path, g.w, g.h, ana->w, ana->h);
    }
    size_t n = (size_t)g.w * g.h;
    float *deg = malloc(n * sizeof *deg), *vals = malloc(n * sizeof *vals);
    unsigned char *interior = malloc(n);
    if (!deg || !vals || !interior) {
        free(deg), free(vals), free(interior);
        fs_gbuffer_free(&g);
        return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    fs_normal_error_map(&g, ana, deg);
    fs_interior_mask(&g, ana, 3, interior);
    for (int reg = 0; reg < R_COUNT; reg++) {
        size_t m = 0;
        double sum = 0;
        for (size_t i = 0; i < n; i++) {
            if (isnan(deg[i])) continue;
            int edge = edge_dist[i] < band, keep = 0;
            switch (reg) {
            case R_INTERIOR: keep = interior[i]; break;
            case R_FACE: keep = interior[i] && !edge; break;
            case R_TOP: keep = interior[i] && !edge && on_top[i]; break;
            case R_EDGE: keep = edge; break;
            case R_EDGE_INTERIOR: keep = edge && interior[i]; break;
            }
            if (!keep) continue;
            vals[m++] = deg[i];
            sum += deg[i];
        }
        if (m) qsort(vals, m, sizeof *vals, cmp_float);
        double p95 = m ? vals[(size_t)ceil(0.95 * m) - 1] : NAN; /* nearest rank */
        printf("%s,%s,%zu,%.4f,%.4f\n", path, region_names[reg], m, m ? sum / m : NAN, p95);
    }
    if (profile) {
        /* Mean error against the distance to the nearest ideal edge, 0.5 r bins. */
        enum { NB = 16 };
        double bsum[NB] = {0};
        size_t bcnt[NB] = {0};
        for (size_t i = 0; i < n; i++) {
            if (isnan(deg[i]) || !interior[i]) continue;
            int b = (int)(edge_dist[i] / (0.5f * r_scene));
            if (b < 0 || b >= NB) continue;
            bsum[b] += deg[i];
            bcnt[b]++;
        }
        for (int b = 0; b < NB; b++)
            printf("%s,edge_dist_%.1f-%.1fr,%zu,%.4f,\n", path, 0.5 * b, 0.5 * (b + 1), bcnt[b],
                   bcnt[b] ? bsum[b] / bcnt[b] : NAN);
    }
    if (map_path) {
        unsigned char *pix = calloc(n * 3, 1);
        if (pix) {
            for (size_t i = 0; i < n; i++) {
                if (isnan(deg[i])) {
                    pix[3 * i] = pix[3 * i + 1] = 60, pix[3 * i + 2] = 90;
                    continue;
                }
                float v = 1.0f - fminf(deg[i] / 10.0f, 1.0f);
                unsigned char c = (unsigned char)(255 * v);
                int edge = edge_dist[i] < band;
                pix[3 * i] = c;
                pix[3 * i + 1] = (unsigned char)(edge ? c * 0.55f : c);
                pix[3 * i + 2] = (unsigned char)(edge ? c * 0.55f : c);
            }
            rc = fs_write_png8(map_path, pix, g.w, g.h, 3);
            free(pix);
        }
    }
    (void)cam;
    free(deg), free(vals), free(interior);
    fs_gbuffer_free(&g);
    return rc;
}

int main(int argc, char **argv)
{
    float band_r = 2.0f;
    const char *map = NULL;
    int a = 1, profile = 0;
    for (; a < argc && argv[a][0] == '-'; a++) {
        if (!strcmp(argv[a], "--band") && a + 1 < argc) {
            char *end;
            band_r = strtof(argv[++a], &end);
            if (*end || !(band_r > 0)) {
                fprintf(stderr, "edge_bands: --band %s: expected a positive number\n", argv[a]);
                return FS_ERR_INPUT;
            }
        } else if (!strcmp(argv[a], "--profile")) {
            profile = 1;
        } else if (!strcmp(argv[a], "--map") && a + 1 < argc) {
            map = argv[++a];
        } else {
            fprintf(stderr, "edge_bands: unknown option %s\n", argv[a]);
            return FS_ERR_INPUT;
        }
    }
    if (argc - a < 3) {
        fprintf(
            stderr,
            "usage: edge_bands [--band R_MULT] [--profile] [--map OUT.png] SCENE.json ANALYTIC.exr METHOD.exr...\n");
        return FS_ERR_INPUT;
    }
    fs_scene s;
    double lo[3], hi[3];
    fs_camera cam;
    fs_gbuffer ana;
    float *rgba = NULL, r = 0;
    int rc = ideal_box(argv[a], &s, lo, hi);
    if (!rc) rc = parse_camera(argv[a + 1], &cam);
    if (!rc) rc = fs_read_render(argv[a + 1], &ana, &rgba, &r);
    if (rc) {
        fprintf(stderr, "edge_bands: %s\n", fs_error_message());
        return rc;
    }
    free(rgba);
    if (cam.width != ana.w || cam.height != ana.h) {
        fprintf(stderr, "edge_bands: %s: camera size %dx%d but image %dx%d\n", argv[a + 1], cam.width, cam.height,
                ana.w, ana.h);
        return FS_ERR_INPUT;
    }
    size_t n = (size_t)ana.w * ana.h;
    float *edge_dist = malloc(n * sizeof *edge_dist);
    unsigned char *on_top = malloc(n);
    if (!edge_dist || !on_top) {
        fprintf(stderr, "edge_bands: out of memory\n");
        return FS_ERR_RUNTIME;
    }
    classify(&ana, &cam, lo, hi, s.up_axis, edge_dist, on_top);
    printf("# edge_bands: scene %s, analytic %s, band %g r (%g), ideal box [%g %g %g]..[%g %g %g]\n", argv[a],
           argv[a + 1], band_r, band_r * s.radius, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    printf("file,region,pixels,mean_deg,p95_deg\n");
    for (int i = a + 2; i < argc && !rc; i++) {
        rc = report(argv[i], &ana, &cam, edge_dist, on_top, band_r * s.radius, s.radius, profile,
                    i == a + 2 ? map : NULL);
        if (rc) fprintf(stderr, "edge_bands: %s\n", fs_error_message());
    }
    free(edge_dist), free(on_top);
    fs_gbuffer_free(&ana);
    return rc;
}
