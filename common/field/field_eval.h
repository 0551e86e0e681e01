/* phi and its gradient at one point (docs/DESIGN.md, "Units"): the isotropic
 * sum over a neighbour grid, or the anisotropic one over the kernels of
 * aniso_kernels.h. For code that needs the field at scattered points (mesh
 * vertices); the reference ray caster has its own gathered, vectorised sums. */
#ifndef FS_FIELD_EVAL_H
#define FS_FIELD_EVAL_H
#include "aniso_kernels.h"
#include "grid.h"
#include "kernels.h"
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_field_eval {
    fs_field f;
    const fs_grid *g;           /* isotropic: the particles' grid, cell >= H */
    const fs_aniso_kernels *ak; /* anisotropic: the kernels (their grid is used), else NULL */
} fs_field_eval;

/* phi(x) into *phi and grad phi(x) into grad; returns the kernel terms summed
 * (particles within reach), for the work counters. */
size_t fs_field_eval_at(const fs_field_eval *e, const float x[3], float *phi, float grad[3]);

#ifdef __cplusplus
}
#endif
#endif
