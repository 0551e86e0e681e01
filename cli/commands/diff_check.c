/* Whether two EXRs can be compared, from their size and provenance (diff.h). */
#include "diff.h"
#include "fs_error.h"
#include "image_io.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { ATTR_MAX = 640, SOFT_MAX = 3, SOFT_LEN = 400 }; /* at most one soft finding each: camera, scene, r */

/* Numbers within a relative 1e-6: the same camera written by two runs. */
static int close_enough(double x, double y) { return fabs(x - y) <= 1e-6 * fmax(1, fmax(fabs(x), fabs(y))); }

/* Two comma lists of numbers ("1.5,1.08,0.82") hold the same values. */
static int same_numbers(const char *a, const char *b)
{
    for (;;) {
        char *ea, *eb;
        double x = strtod(a, &ea), y = strtod(b, &eb);
        if (ea == a || eb == b) return !strcmp(a, b);
        if (!close_enough(x, y)) return 0;
        if (*ea != ',' || *eb != ',') return *ea == *eb;
        a = ea + 1, b = eb + 1;
    }
}

/* The value of key in a "key=value;key=value" string into out ("" when absent). */
static void camera_value(const char *cam, const char *key, char *out, size_t size)
{
    size_t n = strlen(key);
    out[0] = 0;
    for (const char *p = cam; p && *p; p = strchr(p, ';') ? strchr(p, ';') + 1 : NULL)
        if (!strncmp(p, key, n) && p[n] == '=') {
            const char *end = strchr(p, ';');
            snprintf(out, size, "%.*s", (int)(end ? (size_t)(end - p - n - 1) : strlen(p + n + 1)), p + n + 1);
            return;
        }
}

/* The first of eye, target, up, fov that differs between two fluidsurf:camera
 * values, as "eye 1,2,3 vs 4,5,6" into why; 0 when they agree. */
static int camera_differs(const char *ca, const char *cb, char *why, size_t size)
{
    static const char *const keys[] = {"eye", "target", "up", "fov"};
    char va[ATTR_MAX], vb[ATTR_MAX];
    for (int k = 0; k < 4; k++) {
        camera_value(ca, keys[k], va, sizeof va);
        camera_value(cb, keys[k], vb, sizeof vb);
        if (!same_numbers(va, vb)) {
            snprintf(why, size, "%s %.200s vs %.200s", keys[k], va[0] ? va : "(none)", vb[0] ? vb : "(none)");
            return 1;
        }
    }
    return 0;
}

/* The string attribute name of both files; the count of files that have it
 * (-1: a file could not be read, fs_error_message says why). */
static int both_attrs(const char *const files[2], const char *name, char v[2][ATTR_MAX])
{
    int have = 0;
    for (int k = 0; k < 2; k++) {
        int got = fs_read_image_attr(files[k], name, v[k], ATTR_MAX);
        if (got < 0) return -1;
        have += got;
    }
    return have;
}

/* "A has no NAME" or "neither A nor B has NAME" (have: how many files have it). */
static void missing(char *out, const char *const files[2], int first_has, int have, const char *name, const char *what)
{
    if (have == 1) snprintf(out, SOFT_LEN, "%s has no %s: %s cannot be checked", files[first_has ? 1 : 0], name, what);
    else snprintf(out, SOFT_LEN, "neither %s nor %s has %s: %s cannot be checked", files[0], files[1], name, what);
}

/* What tells two images apart for good: size and camera. */
static int hard_checks(const char *const files[2], const fs_gbuffer g[2], char soft[][SOFT_LEN], int *nsoft)
{
    if (g[0].w != g[1].w || g[0].h != g[1].h)
        return fs_fail(FS_ERR_INPUT, "%s is %dx%d but %s is %dx%d: images of different sizes cannot be compared",
                       files[0], g[0].w, g[0].h, files[1], g[1].w, g[1].h);
    char cam[2][ATTR_MAX], why[2 * ATTR_MAX];
    int have = both_attrs(files, "fluidsurf:camera", cam);
    if (have < 0) return FS_ERR_INPUT;
    if (have == 2 && camera_differs(cam[0], cam[1], why, sizeof why))
        return fs_fail(FS_ERR_INPUT, "%s and %s were rendered with different cameras (%s): they cannot be compared",
                       files[0], files[1], why);
    if (have < 2) missing(soft[(*nsoft)++], files, cam[0][0] != 0, have, "fluidsurf:camera", "the camera");
    return FS_OK;
}

/* What may differ on purpose: the scene and r (warnings, or refusals under --strict). */
static int soft_checks(const char *const files[2], const float r[2], int radius_given, int strict,
                       char soft[][SOFT_LEN], int *nsoft)
{
    char hash[2][ATTR_MAX];
    int have = both_attrs(files, "fluidsurf:scene_hash", hash);
    if (have < 0) return FS_ERR_INPUT;
    if (have == 2 && strcmp(hash[0], hash[1]))
        snprintf(soft[(*nsoft)++], SOFT_LEN, "%s and %s are of different scenes (scene_hash %.40s vs %.40s)", files[0],
                 files[1], hash[0], hash[1]);
    else if (have < 2) missing(soft[(*nsoft)++], files, hash[0][0] != 0, have, "fluidsurf:scene_hash", "the scene");
    int rhave = (r[0] > 0) + (r[1] > 0);
    if (rhave == 2 && !close_enough(r[0], r[1]))
        snprintf(soft[(*nsoft)++], SOFT_LEN, "%s has r = %g but %s has r = %g%s", files[0], r[0], files[1], r[1],
                 strict             ? ""
                     : radius_given ? "; depth errors are in the --radius given"
                                    : "; depth errors are in the first file's r");
    else if (rhave < 2 && !radius_given) missing(soft[(*nsoft)++], files, r[0] > 0, rhave, "fluidsurf:r", "the radius");
    return FS_OK;
}

int diff_check_comparable(const char *const files[2], const fs_gbuffer g[2], const float r[2], int strict,
                          int radius_given)
{
    char soft[SOFT_MAX][SOFT_LEN];
    int nsoft = 0, rc = hard_checks(files, g, soft, &nsoft);
    if (!rc) rc = soft_checks(files, r, radius_given, strict, soft, &nsoft);
    if (rc) return rc;
    if (strict && nsoft) return fs_fail(FS_ERR_INPUT, "%s (refused under --strict)", soft[0]);
    for (int i = 0; i < nsoft; i++) fprintf(stderr, "fluidsurf: warning: %s\n", soft[i]);
    return FS_OK;
}
