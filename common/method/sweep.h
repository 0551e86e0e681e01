/* Parameter sweeps of a study: "M.P=v1,v2" settings; each method runs once
 * per combination of its swept values (a variant). */
#ifndef FS_SWEEP_H
#define FS_SWEEP_H
#include "method.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MAX_SWEEPS 8
#define FS_MAX_SWEEP_VALUES 16

typedef struct fs_sweep {
    const fs_method *m;
    int param; /* index in m->params */
    int nvalues;
    char values[FS_MAX_SWEEP_VALUES][48];
} fs_sweep;

typedef struct fs_variant {
    const fs_method *m;
    double params[FS_MAX_PARAMS];
    int nswept;
    int sweep_index[2], value_index[2]; /* first two swept parameters, for grids */
    char label[200];   /* file-safe, [A-Za-z0-9_-] only: "spheres" or "spheres_radius_scale-0p5_thickness-off" */
    char variant[200]; /* metrics.csv: "radius_scale=0.5;thickness=off", "" when none */
} fs_variant;

/* Adds a "M.P=v1,v2,..." sweep (validated: method, parameter, every value). */
int fs_sweep_add(fs_sweep *sweeps, int *nsweeps, const char *spec);
/* A value as part of a file label (fs_label_value): letters, digits and '_' are
 * kept, '.' becomes 'p', '-' becomes 'm', '+' is left out, anything else becomes
 * 'x' ("0.8" -> "0p8", "-1e-3" -> "m1em3"). A variant's label is the method, then
 * "_PARAM-VALUE" per swept parameter. */
void fs_label_value(const char *value, char *out, int size);
/* 1 when text is a non-empty label of [A-Za-z0-9_-] only. */
int fs_label_is_safe(const char *text);
/* Expands the variants of method m (1 when it has no sweep) into out[max];
 * returns the count, or -(error code). Scene settings apply first, sweeps last. */
int fs_sweep_variants(const fs_method *m, const fs_scene *s, const fs_sweep *sweeps, int nsweeps, fs_variant *out,
                      int max);

#ifdef __cplusplus
}
#endif
#endif
