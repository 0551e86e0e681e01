/* The bisection of a bracketed crossing and the crossing it gives, written once
 * for the marches that bisect (reference_plain.c, accel=off; reference_zb.c,
 * field=zhu_bridson; README.md, step 5). static inline with the field passed as
 * functions: each caller passes its own static functions, which the compiler
 * inlines here, so the hot loop makes no call through a pointer. */
#ifndef FS_REFERENCE_BISECT_H
#define FS_REFERENCE_BISECT_H
#include "reference.h"

/* The march's field at local t, signed so that >= 0 is inside (in double: Zhu &
 * Bridson's phi is summed in double); it counts its own sum. */
typedef double (*fs_ref_side_fn)(const void *ctx, float t);
/* A vector pointing out of the fluid at local t (the first hit's normal); it counts its own sum. */
typedef void (*fs_ref_outward_fn)(const void *ctx, float t, float out[3]);

/* Bisects [lo, hi] (lo on the march's current side, hi on the other) to 1e-4 r,
 * then records the crossing at ray distance t0 + its midpoint (fs_ref_cross;
 * the normal read only at the first entry). ctx is the field's, d the ray's
 * direction, w its counts (NULL when not counting). 1 when the ray is finished.
 * (The functions are passed as arguments, not in a struct: so the compiler
 * sees them at the call and inlines them.) */
static inline int fs_ref_bisect_cross(const reference *R, march *m, ray_result *res, fs_ref_side_fn side,
                                      fs_ref_outward_fn outward, const void *ctx, const float d[3], ray_work *w,
                                      float t0, float lo, float hi)
{
    float tol = 1e-4f * R->f.r;
    while (hi - lo > tol) {
        float mid = 0.5f * (lo + hi);
        if (mid <= lo || mid >= hi) break; /* floats cannot split it further (far along a huge cell) */
        if (w) {
            w->samples++;
            w->refine_evals++;
        }
        if ((side(ctx, mid) >= 0) == m->inside) lo = mid;
        else hi = mid;
    }
    float tc = 0.5f * (lo + hi), out[3] = {0, 0, 0};
    if (w) w->crossings++;
    if (!m->inside && !res->hit) outward(ctx, tc, out);
    return fs_ref_cross(R, m, res, t0 + tc, out, d);
}
#endif
