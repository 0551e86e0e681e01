/* Which axis is up for a particle file that does not say (docs/DESIGN.md,
 * "Axes, camera and images"): `--up auto`, the default for a bare particle file. */
#ifndef FS_UP_AXIS_H
#define FS_UP_AXIS_H
#include "particles.h"
#ifdef __cplusplus
extern "C" {
#endif

/* A floor by its share: along one axis this many times as many particles lie
 * within FS_UP_FLOOR_BAND r of the low end (the 0.1% quantile) as along any
 * other, and at least FS_UP_FLOOR_MIN of them. */
#define FS_UP_FLOOR_LEAD 1.5f
#define FS_UP_FLOOR_BAND 1.0f
#define FS_UP_FLOOR_MIN 9
/* A floor at 0: one axis's low end within FS_UP_ZERO_BAND r of 0 while the
 * other two 1%..99% boxes are centred on 0 (their centre within FS_UP_CENTRED
 * of their extent), as a modelling tool stands an object on its ground plane. */
#define FS_UP_ZERO_BAND 4.0f
#define FS_UP_CENTRED 0.05f
/* Extents within this factor of the smallest are "about as small": the
 * particles' pile-up then decides between them. */
#define FS_UP_EXTENT_TIE 1.5f
/* A skewness lead below this is no sign of gravity. */
#define FS_UP_SKEW_LEAD 0.25f

/* The up axis (0 x, 1 y, 2 z) of p read from path, r its particle radius (the
 * r its spacing implies, where known): the floor first, by its share, else at
 * 0; else the file format's own convention where it has one (Houdini's BGEO:
 * y); else the axis along which the 1%..99% quantile box is smallest; among
 * axes within FS_UP_EXTENT_TIE of the smallest, the one along which the
 * particles pile up at the low end (the largest skewness, by FS_UP_SKEW_LEAD
 * or more), else y if it is one of them, else the smallest. why receives the
 * reason, for the note. */
int fs_up_axis_guess(const fs_particles *p, const char *path, float r, char *why, int size);
/* The share of p's particles within FS_UP_FLOOR_BAND r of each axis's low end
 * (its 0.1% quantile): what the floor rule reads (fluidsurf info prints it). */
void fs_up_low_end_shares(const fs_particles *p, float r, double share[3]);

#ifdef __cplusplus
}
#endif
#endif
