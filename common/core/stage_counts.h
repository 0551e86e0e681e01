/* The work counts of a run's stages as one line of text, for the reference
 * cache's entries (docs/DESIGN.md, "Reference cache"):
 *   "1:STAGE=v0,v1,...;STAGE=..."  (format 1, FS_NCOUNTERS values in enum order) */
#ifndef FS_STAGE_COUNTS_H
#define FS_STAGE_COUNTS_H
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

/* FS_OK, or FS_ERR_RUNTIME when it does not fit in size bytes. */
int fs_stage_counts_format(const fs_stages *st, char *buf, int size);
/* Fills st's names and counts (times 0) from text; FS_ERR_INPUT for text that
 * is empty or not of this format (another counter list: counted again). */
int fs_stage_counts_parse(const char *text, fs_stages *st);

#ifdef __cplusplus
}
#endif
#endif
