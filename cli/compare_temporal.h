/* Temporal stability of a sequence in compare (docs/DESIGN.md, "References and
 * metrics"): how much a view changes between consecutive frames, and how much
 * of that change is not the true motion. */
#ifndef FS_COMPARE_TEMPORAL_H
#define FS_COMPARE_TEMPORAL_H
#include "gbuffer.h"

/* Mean angle between a's and b's normals over the pixels both cover; NAN if none. */
double cmp_normal_change(const fs_gbuffer *a, const fs_gbuffer *b);

/* Flicker against the true motion, frame t to t+1, over the pixels that the
 * method (m0, m1) and the reference (r0, r1) all cover: the mean of
 * |(n_m(t+1) - n_m(t)) - (n_ref(t+1) - n_ref(t))| as a vector, so opposite
 * rotations do not cancel, reported as the angle of a chord that long
 * (2 asin(|v| / 2)); and the mean |(d_m(t+1) - d_m(t)) - (d_ref(t+1) - d_ref(t))|
 * in r. Against a static reference both equal the method's own change. NAN
 * when no pixel counts. */
typedef struct cmp_temporal_error { double normal_deg, depth_r; } cmp_temporal_error;
cmp_temporal_error cmp_temporal_error_of(const fs_gbuffer *m0, const fs_gbuffer *m1, const fs_gbuffer *r0,
                                         const fs_gbuffer *r1, float radius);

#endif
