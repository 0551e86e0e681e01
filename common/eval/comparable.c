/* Whether two images can be compared (comparable.h): diff's rule, written once. */
#include "comparable.h"
#include "fs_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { VALUE_MAX = 640 };

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
    char va[VALUE_MAX], vb[VALUE_MAX];
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

static int has(const char *v) { return v && v[0]; }

/* A new finding's text buffer (NULL when full: at most one per kind fits). */
static char *finding(fs_comparable_findings *f) { return f->n < FS_COMPARABLE_MAX_FINDINGS ? f->text[f->n++] : NULL; }

/* "A has no NAME: WHAT cannot be checked" or "neither A nor B has NAME: ..." (have: how many have it). */
static void missing(fs_comparable_findings *f, const fs_comparable im[2], int first_has, int have, const char *name,
                    const char *what)
{
    char *out = finding(f);
    if (!out) return;
    if (have == 1)
        snprintf(out, FS_COMPARABLE_FINDING_LEN, "%s has no %s: %s cannot be checked", im[first_has ? 1 : 0].name, name,
                 what);
    else
        snprintf(out, FS_COMPARABLE_FINDING_LEN, "neither %s nor %s has %s: %s cannot be checked", im[0].name,
                 im[1].name, name, what);
}

/* What tells two images apart for good: size and camera. */
static int hard_checks(const fs_comparable im[2], const fs_comparable_rules *rules, fs_comparable_findings *f)
{
    if (im[0].w != im[1].w || im[0].h != im[1].h)
        return fs_fail(FS_ERR_INPUT, "%s is %dx%d but %s is %dx%d: images of different sizes cannot be compared",
                       im[0].name, im[0].w, im[0].h, im[1].name, im[1].w, im[1].h);
    int have = has(im[0].camera) + has(im[1].camera);
    char why[2 * VALUE_MAX];
    if (have == 2 && camera_differs(im[0].camera, im[1].camera, why, sizeof why))
        return fs_fail(FS_ERR_INPUT, "%s and %s were rendered with different cameras (%s): they cannot be compared",
                       im[0].name, im[1].name, why);
    if (have < 2 && rules->report_missing) missing(f, im, has(im[0].camera), have, "fluidsurf:camera", "the camera");
    return FS_OK;
}

/* What may differ on purpose: the scene and r. */
static void soft_checks(const fs_comparable im[2], const fs_comparable_rules *rules, fs_comparable_findings *f)
{
    int have = has(im[0].scene_hash) + has(im[1].scene_hash);
    char *out;
    if (have == 2 && strcmp(im[0].scene_hash, im[1].scene_hash) && (out = finding(f)))
        snprintf(out, FS_COMPARABLE_FINDING_LEN, "%s and %s are of different scenes (scene_hash %.40s vs %.40s)",
                 im[0].name, im[1].name, im[0].scene_hash, im[1].scene_hash);
    else if (have < 2 && rules->report_missing)
        missing(f, im, has(im[0].scene_hash), have, "fluidsurf:scene_hash", "the scene");
    int rhave = (im[0].r > 0) + (im[1].r > 0);
    if (rhave == 2 && !close_enough(im[0].r, im[1].r) && (out = finding(f)))
        snprintf(out, FS_COMPARABLE_FINDING_LEN, "%s has r = %g but %s has r = %g%s%s", im[0].name, im[0].r, im[1].name,
                 im[1].r, rules->strict || !rules->r_which ? "" : "; depth errors are in ",
                 rules->strict || !rules->r_which ? "" : rules->r_which);
    else if (rhave < 2 && rules->report_missing && !rules->radius_given)
        missing(f, im, im[0].r > 0, rhave, "fluidsurf:r", "the radius");
}

int fs_comparable_check(const fs_comparable im[2], const fs_comparable_rules *rules, fs_comparable_findings *found)
{
    found->n = 0;
    int rc = hard_checks(im, rules, found);
    if (rc) return rc;
    soft_checks(im, rules, found);
    if (rules->strict && found->n) return fs_fail(FS_ERR_INPUT, "%s (refused under %s)", found->text[0], rules->strict);
    return FS_OK;
}
