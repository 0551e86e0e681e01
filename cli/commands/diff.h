/* The parts of `fluidsurf diff` (cmd_diff.c): whether two EXRs can be compared
 * (diff_check.c) and the metrics as text or JSON (diff_print.c). */
#ifndef FS_CLI_DIFF_H
#define FS_CLI_DIFF_H
#include "gbuffer.h"
#include "metrics.h"
#include <stdio.h>

/* Checks from the images and their provenance (fluidsurf:camera, fluidsurf:r,
 * fluidsurf:scene_hash) that files[0] and files[1] can be compared.
 * A different size or camera: FS_ERR_INPUT, one line naming both files and what
 * differs. A different scene or r, or provenance that cannot tell: one warning
 * line each on stderr, or under strict FS_ERR_INPUT for the first of them.
 * radius_given: a --radius, said in the warning about r. */
int diff_check_comparable(const char *const files[2], const fs_gbuffer g[2], const float r[2], int strict,
                          int radius_given);

/* How many --fail-* thresholds diff has. */
#define DIFF_GATES 7
/* One threshold that was crossed, as the "FAIL ..." text says it. */
typedef struct diff_fail {
    char text[80];
} diff_fail;

/* "name value" lines (the metrics named as metrics.csv's columns), then a
 * "FAIL ..." line per crossed threshold. masked: the pixels left out as hidden by
 * solids (a "solids_masked_px N" line after r), -1 when the files carry no
 * solids' depth (no line). */
void diff_print_text(FILE *f, const char *const files[2], float r, long masked, const fs_metrics *m,
                     const diff_fail *fails, int nfails);
/* One JSON object: a, b, r, "solids_masked_px" (only when masked >= 0), every
 * metric, "failed": [the FAIL texts]. NaN is null, an infinity 1e999 / -1e999
 * (JSON parsers read infinity or the largest double). */
void diff_print_json(FILE *f, const char *const files[2], float r, long masked, const fs_metrics *m,
                     const diff_fail *fails, int nfails);

#endif
