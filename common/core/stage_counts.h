/* The work counts of a run's stages as one line of text, for the reference
 * cache's entries (docs/DESIGN.md, "Reference cache"):
 *   "1:STAGE=v0,v1,...;STAGE=..."  (format 1, FS_NCOUNTERS values in enum order)
 * One or more stages, no trailing ';'; a value is decimal digits without a sign,
 * spaces or leading zeros, below 2^64; stage names are distinct, 1 to
 * FS_STAGE_NAME_MAX characters, without '=', ',' or ';'. */
#ifndef FS_STAGE_COUNTS_H
#define FS_STAGE_COUNTS_H
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_STAGE_NAME_MAX 31
/* The longest text and its NUL: "1:", then per stage its name, '=', and each
 * value's 20 digits with a ',' or ';' after it (the last value has the NUL). */
#define FS_STAGE_COUNTS_MAX (2 + FS_MAX_STAGES * (FS_STAGE_NAME_MAX + 1 + FS_NCOUNTERS * 21))

/* FS_OK, or FS_ERR_RUNTIME when it does not fit in size bytes or a stage's
 * name could not be read back (see above). */
int fs_stage_counts_format(const fs_stages *st, char *buf, int size);
/* Fills st's names and counts (times 0) from text; FS_ERR_INPUT for text that
 * is empty or not exactly of this format (another counter list: counted
 * again), or whose totals over the stages would wrap 2^64. */
int fs_stage_counts_parse(const char *text, fs_stages *st);

#ifdef __cplusplus
}
#endif
#endif
