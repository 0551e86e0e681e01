/* fluidsurf_compare (API version 4) as a program links it: a study of two
 * methods, one of them swept, on two frames against the reference. Its tables
 * have compare's columns and one row per variant, reference and frame; its
 * metrics of the first frame equal fluidsurf_render + fluidsurf_metrics_compute2
 * of the same item (one engine, one metrics function); its timings are
 * `repeat` runs; the same study twice gives the same metrics.
 * fluidsurf_compare_to_dir (version 5) writes the study's folder, whose
 * metrics.csv is the table returned; a used folder is refused unless forced.
 * (tests/python/test_fluidsurf.py holds the folder against the command line's.) */
#include "fluidsurf/fluidsurf.h"
#include "api_slab.h"
#include "fs_test.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define R 0.025f

/* A slab of particles on a lattice of spacing 2r, shifted by dx (a moving frame). */
static size_t slab(float *x, float *y, float *z, float dx) { return api_slab(x, y, z, 10, 4, 10, R, dx); }

/* Rows of a CSV table (the provenance line and the header left out). */
static int rows(const char *csv)
{
    int n = 0;
    for (const char *c = csv; c && *c; c++) n += *c == '\n';
    return csv ? n - 2 : -1;
}

/* The value of column col in the first data row whose first cells are method,variant. */
static double cell(const char *csv, const char *method, const char *variant, const char *col)
{
    const char *hdr = strchr(csv, '\n') + 1, *line = hdr;
    int idx = 0;
    for (const char *c = hdr; c < strstr(hdr, col); c++) idx += *c == ',';
    char want[128];
    snprintf(want, sizeof want, "%s,%s,", method, variant);
    while ((line = strchr(line, '\n')) && *++line)
        if (!strncmp(line, want, strlen(want))) {
            const char *c = line;
            for (int i = 0; i < idx; i++) c = strchr(c, ',') + 1;
            return atof(c);
        }
    return NAN;
}

/* path's whole text (NULL when it cannot be read); the caller frees it. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *buf = f ? calloc(1, 1 << 20) : NULL;
    if (buf) fread(buf, 1, (1 << 20) - 1, f);
    if (f) fclose(f);
    return buf;
}

/* The study into a folder: the files compare writes, metrics.csv the table
 * returned; the folder once used is refused, unless FLUIDSURF_STUDY_FORCE. */
static void to_dir(const fluidsurf_scene *s, const fluidsurf_particles *const *p)
{
    char tmp[] = "/tmp/fs_api_compareXXXXXX", dir[64], path[128];
    CHECK(mkdtemp(tmp) != NULL, "temporary folder");
    snprintf(dir, sizeof dir, "%s/study", tmp);
    fluidsurf_study *st = NULL, *bad = (fluidsurf_study *)1;
    int rc = fluidsurf_compare_to_dir(s, p, 2, "spheres", NULL, 0, NULL, 0, 1, 0, dir, &st);
    CHECK(!rc && st, "fluidsurf_compare_to_dir: %s", fluidsurf_last_error());
    snprintf(path, sizeof path, "%s/metrics.csv", dir);
    char *text = slurp(path);
    CHECK(text && st && !strcmp(text, fluidsurf_study_table(st, "metrics")), "metrics.csv is the table returned");
    free(text);
    const char *files[] = {"timings.csv", "temporal.csv",      "panel.png",        "report.md",
                           "report.html", "spheres_f0001.exr", "diff_spheres.png", "fluidsurf-outputs.txt"};
    for (int i = 0; i < 8; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[i]);
        CHECK(access(path, F_OK) == 0, "%s written", files[i]);
    }
    CHECK(fluidsurf_compare_to_dir(s, p, 2, "spheres", NULL, 0, NULL, 0, 1, 0, dir, &bad) == FLUIDSURF_ERR_INPUT &&
              !bad && strstr(fluidsurf_last_error(), "holds another run's outputs"),
          "a used folder is refused: %s", fluidsurf_last_error());
    fluidsurf_study_free(st);
    CHECK(!fluidsurf_compare_to_dir(s, p, 2, "spheres", NULL, 0, NULL, 0, 1, FLUIDSURF_STUDY_FORCE, dir, &st),
          "FLUIDSURF_STUDY_FORCE: %s", fluidsurf_last_error());
    CHECK(fluidsurf_compare_to_dir(s, p, 2, "spheres", NULL, 0, NULL, 0, 1, 0, path, &bad) == FLUIDSURF_ERR_INPUT &&
              strstr(fluidsurf_last_error(), "not a folder"),
          "a file as the folder: %s", fluidsurf_last_error());
    CHECK(fluidsurf_compare_to_dir(s, p, 2, "spheres", NULL, 0, NULL, 0, 1, 0, NULL, &bad) == FLUIDSURF_ERR_INPUT,
          "no folder: %s", fluidsurf_last_error());
    fluidsurf_study_free(st);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    CHECK(system(cmd) == 0, "clean up");
}

int main(void)
{
    static float x[2][400], y[2][400], z[2][400];
    fluidsurf_particles *p[2];
    fluidsurf_scene *s;
    for (int f = 0; f < 2; f++)
        CHECK(!fluidsurf_particles_wrap(slab(x[f], y[f], z[f], f * 0.5f * R), x[f], y[f], z[f], &p[f]), "wrap");
    CHECK(!fluidsurf_scene_new(&s) && !fluidsurf_scene_set_radius(s, R) && !fluidsurf_scene_set_size(s, 48, 40),
          "scene");
    CHECK(FLUIDSURF_API_VERSION >= 5 && fluidsurf_api_version() >= 5, "API version 5 or later: %d",
          fluidsurf_api_version());

    const char *sets[] = {"spheres.radius_scale=0.8,1.2"};
    fluidsurf_study *st = NULL, *again = NULL;
    int rc = fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 2, "spheres,reference", sets, 1, NULL, 0, 2, 0,
                               &st);
    CHECK(!rc, "fluidsurf_compare: %s", fluidsurf_last_error());
    if (rc) TEST_DONE();
    const char *m = fluidsurf_study_table(st, "metrics"), *t = fluidsurf_study_table(st, "timings");
    CHECK(m && !strncmp(m, "# ", 2) && strstr(m, "; commit=") && strchr(m, 0x0a) > strstr(m, "commit="),
          "metrics begins with the provenance");
    CHECK(strstr(m, "\nmethod,variant,radius_scale,reference,frame,mask_iou,"), "metrics has compare's columns");
    CHECK(rows(m) == 3 * 2, "3 variants x 1 reference x 2 frames: %d rows", rows(m));
    CHECK(fluidsurf_study_table(st, "temporal") && rows(fluidsurf_study_table(st, "temporal")) == 3,
          "temporal: one row per variant");
    CHECK(!fluidsurf_study_table(st, "counters") && !fluidsurf_study_table(st, "nope"),
          "no counters table without the flag");
    CHECK(t && strstr(t, "spheres,radius_scale=0.8,total,") && strstr(t, ",2,"), "timings: 2 runs per variant");
    CHECK_NEAR(cell(m, "reference", "", "mask_iou"), 1, 1e-12, "the reference against itself");

    /* every method by default, but the reference is no method of the study unless named:
     * the demo compared it with itself (issue 53) */
    fluidsurf_study *all = NULL;
    CHECK(!fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 1, NULL, NULL, 0, NULL, 0, 1, 0, &all),
          "fluidsurf_compare of every method: %s", fluidsurf_last_error());
    const char *am = all ? fluidsurf_study_table(all, "metrics") : NULL;
    CHECK(am && strstr(am, "\nspheres,") && strstr(am, "\nraycast_pca,") && !strstr(am, "\nreference,"),
          "every method but the reference has a row");
    fluidsurf_study_free(all);

    /* the same item through fluidsurf_render and the metrics of version 2 */
    fluidsurf_image *a, *ref;
    const char *par[] = {"radius_scale=0.8"};
    CHECK(!fluidsurf_render(s, p[0], "spheres", par, 1, &a) && !fluidsurf_reference(s, p[0], &ref), "render: %s",
          fluidsurf_last_error());
    fluidsurf_metrics mt;
    fluidsurf_depth_metrics dm;
    CHECK(!fluidsurf_metrics_compute2(a, ref, 0, &mt, &dm), "metrics");
    char v[16];
    snprintf(v, sizeof v, "%.6g", mt.normal_mean_deg);
    CHECK_NEAR(cell(m, "spheres", "radius_scale=0.8", "normal_mean_deg"), atof(v), 0,
               "normal_mean_deg as fluidsurf_render gives it");
    snprintf(v, sizeof v, "%.6g", mt.mask_iou);
    CHECK_NEAR(cell(m, "spheres", "radius_scale=0.8", "mask_iou"), atof(v), 0, "mask_iou as fluidsurf_render gives it");

    CHECK(!fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 2, "spheres,reference", sets, 1, NULL, 0, 1, 0,
                             &again),
          "again");
    const char *m2 = fluidsurf_study_table(again, "metrics");
    CHECK(m2 &&
              cell(m2, "spheres", "radius_scale=1.2", "depth_rmse_r") ==
                  cell(m, "spheres", "radius_scale=1.2", "depth_rmse_r"),
          "the same study twice: the same metrics");

    /* refusals: one line each, nothing returned */
    fluidsurf_study *bad = (fluidsurf_study *)1;
    CHECK(fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 2, "spheres,nosuch", NULL, 0, NULL, 0, 1, 0,
                            &bad) == FLUIDSURF_ERR_INPUT &&
              !bad && strstr(fluidsurf_last_error(), "nosuch"),
          "unknown method: %s", fluidsurf_last_error());
    const char *sweep_other[] = {"aniso_ssf.smoothing_iterations=1,2"};
    CHECK(fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 2, "spheres", sweep_other, 1, NULL, 0, 1, 0,
                            &bad) == FLUIDSURF_ERR_INPUT,
          "a sweep of a method not compared: %s", fluidsurf_last_error());
    /* a library message names the setting as written, with no command-line flag (the CLI says --set) */
    const char *trailing[] = {"spheres.radius_scale=0.8,"};
    CHECK(fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 2, "spheres", trailing, 1, NULL, 0, 1, 0, &bad) ==
                  FLUIDSURF_ERR_INPUT &&
              strstr(fluidsurf_last_error(), "spheres.radius_scale=0.8,") && !strstr(fluidsurf_last_error(), "--"),
          "a bad sweep, in the library's words: %s", fluidsurf_last_error());
    const char *badref[] = {"bogus"};
    CHECK(fluidsurf_compare(s, (const fluidsurf_particles *const *)p, 2, "spheres", NULL, 0, badref, 1, 1, 0, &bad) ==
                  FLUIDSURF_ERR_INPUT &&
              strstr(fluidsurf_last_error(), "bogus") && !strstr(fluidsurf_last_error(), "--"),
          "a bad reference, in the library's words: %s", fluidsurf_last_error());
    to_dir(s, (const fluidsurf_particles *const *)p);
    fluidsurf_image_free(a);
    fluidsurf_image_free(ref);
    fluidsurf_study_free(st);
    fluidsurf_study_free(again);
    fluidsurf_scene_free(s);
    for (int f = 0; f < 2; f++) fluidsurf_particles_free(p[f]);
    TEST_DONE();
}
