/* Frame patterns: one file per frame, named by a printf pattern
 * ("frame_%04d.vtk") or with {} for the number ("frame_{}.vtk", splashsurf's
 * form); every command that reads or writes a sequence goes through these. */
#ifndef FS_FRAME_PATTERN_H
#define FS_FRAME_PATTERN_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* 1 when path names frames: it holds {} or a %d-style conversion. */
int fs_is_frame_pattern(const char *path);
/* The printf pattern of in: {} becomes %d (and a literal % %%), a printf
 * pattern stays as it is. FS_ERR_INPUT "in: ..." when the result has not
 * exactly one %d-style conversion or does not fit. */
int fs_frame_pattern(const char *in, char *out, size_t size);
/* Expands a printf pattern ("frame_%04d.vtk") for one frame. */
int fs_frame_path(char *out, int size, const char *pattern, int frame);
/* "FIRST:LAST" or "FIRST:LAST:STEP" (0 <= FIRST <= LAST <= 100000000, STEP >= 1,
 * STEP 1 when left out): 0, or -1 when text is not one. */
int fs_frame_range(const char *text, int *first, int *last, int *step);

#ifdef __cplusplus
}
#endif
#endif
