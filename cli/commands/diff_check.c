/* Whether two EXRs can be compared (diff.h): their provenance read from the files,
 * judged by the rule diff shares with the library (common/eval/comparable.h). */
#include "comparable.h"
#include "diff.h"
#include "fs_error.h"
#include "image_io.h"
#include <stdio.h>

enum { ATTR_MAX = 640 };

/* The string attribute name of both files into v ("" when absent); -1 when a file
 * cannot be read (fs_error_message says why). */
static int both_attrs(const char *const files[2], const char *name, char v[2][ATTR_MAX])
{
    for (int k = 0; k < 2; k++)
        if (fs_read_image_attr(files[k], name, v[k], ATTR_MAX) < 0) return -1;
    return 0;
}

int diff_check_comparable(const char *const files[2], const fs_gbuffer g[2], const float r[2], int strict,
                          int radius_given)
{
    char cam[2][ATTR_MAX], hash[2][ATTR_MAX];
    if (both_attrs(files, "fluidsurf:camera", cam) || both_attrs(files, "fluidsurf:scene_hash", hash))
        return FS_ERR_INPUT;
    fs_comparable im[2];
    for (int k = 0; k < 2; k++) im[k] = (fs_comparable){files[k], g[k].w, g[k].h, cam[k], hash[k], r[k]};
    const fs_comparable_rules rules = {strict ? "--strict" : NULL, 1, radius_given,
                                       radius_given ? "the --radius given" : "the first file's r"};
    fs_comparable_findings found;
    int rc = fs_comparable_check(im, &rules, &found);
    if (rc) return rc;
    for (int i = 0; i < found.n; i++) fprintf(stderr, "fluidsurf: warning: %s\n", found.text[i]);
    return FS_OK;
}
