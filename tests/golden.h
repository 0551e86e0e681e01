/* Golden-image regression check (modelled on cairo's test suite).
 * Reference: tests/golden/NAME.png (8-bit sRGB RGBA). The output is sRGB-encoded
 * and compared channel by channel on the 0..255 scale; it fails when the mean
 * absolute difference exceeds max_mean_abs or the fraction of pixels with any
 * channel off by more than 16 exceeds max_pixel_frac. On failure it writes
 * FS_TEST_OUT/NAME.out.png and NAME.diff.png (difference x8) and prints both.
 * A missing reference, or FS_UPDATE_GOLDEN=1 in the environment, (re)writes the
 * reference; that counts as a failure unless FS_UPDATE_GOLDEN=1, so a missing
 * golden never passes silently. FS_GOLDEN_DIR overrides the folder of the
 * references (the helper's own test uses it). Returns 0 when the check passes. */
#ifndef FS_GOLDEN_H
#define FS_GOLDEN_H

int fs_golden_check(const char *name, const float *rgba_linear, int w, int h, double max_mean_abs,
                    double max_pixel_frac);

#endif
