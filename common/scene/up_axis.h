/* Which axis is up for a particle file that does not say (docs/DESIGN.md,
 * "The up axis"): `--up auto`, the default for a bare particle file. */
#ifndef FS_UP_AXIS_H
#define FS_UP_AXIS_H
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Extents within this factor of the smallest are "about as small": the
 * particles' pile-up then decides between them. */
#define FS_UP_EXTENT_TIE 1.5f
/* A skewness lead below this is no sign of gravity. */
#define FS_UP_SKEW_LEAD 0.25f

/* The up axis (0 x, 1 y, 2 z) of p read from path: the file format's own
 * convention where it has one (Houdini's BGEO: y), else the axis along which
 * the 1%..99% quantile box is smallest; among axes within FS_UP_EXTENT_TIE of
 * the smallest, the one along which the particles pile up at the low end
 * (the largest skewness, by FS_UP_SKEW_LEAD or more: a fluid rests on its
 * floor), else y if it is one of them, else the smallest. why receives the
 * reason, for the note. */
int fs_up_axis_guess(const fs_particles *p, const char *path, char *why, int size);

#ifdef __cplusplus
}
#endif
#endif
