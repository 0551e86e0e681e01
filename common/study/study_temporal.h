/* Temporal stability of a sequence in a study (docs/DESIGN.md, "References and
 * metrics"): how much a view changes between consecutive frames, and how much
 * of that change is not the true motion. */
#ifndef FS_STUDY_TEMPORAL_H
#define FS_STUDY_TEMPORAL_H
#include "gbuffer.h"
#include "scene.h"

/* Mean angle between a's and b's normals over the pixels both cover; NAN if none. */
double fs_study_normal_change(const fs_gbuffer *a, const fs_gbuffer *b);

/* Flicker against the true motion, frame t to t+1, over the pixels that the
 * method (m0, m1) and the reference (r0, r1) all cover: the mean of
 * |(n_m(t+1) - n_m(t)) - (n_ref(t+1) - n_ref(t))| as a vector, so opposite
 * rotations do not cancel, reported as the angle of a chord that long
 * (2 asin(|v| / 2)); and the mean |(d_m(t+1) - d_m(t)) - (d_ref(t+1) - d_ref(t))|
 * in r. Against a static reference both equal the method's own change. NAN
 * when no pixel counts. */
typedef struct fs_study_temporal_error {
    double normal_deg, depth_r;
} fs_study_temporal_error;
fs_study_temporal_error fs_study_temporal_error_of(const fs_gbuffer *m0, const fs_gbuffer *m1, const fs_gbuffer *r0,
                                                   const fs_gbuffer *r1, float radius);

/* A view's measures summed over frame pairs. */
typedef struct fs_study_temporal_sums {
    double change, err_normal, err_depth;
    int n_change, n_err;
} fs_study_temporal_sums;
/* Frames t (a) and t+1 (b) of a view: its change, and its error against the
 * reference's motion (ra, rb; NULL when not at hand). Pixels a solid hides in
 * front of the reference's surface (or, without it, the view's own) leave both. */
void fs_study_temporal_add(const fs_scene *s, const fs_gbuffer *a, const fs_gbuffer *b, const fs_gbuffer *ra,
                           const fs_gbuffer *rb, fs_study_temporal_sums *t);
/* The means: change, error in degrees and in r (NAN where no pair counted). */
void fs_study_temporal_means(const fs_study_temporal_sums *t, double *change, double *err_deg, double *err_depth_r);

#endif
