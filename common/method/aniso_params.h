/* The anisotropy parameters of a method that sums the anisotropic field
 * (field=anisotropic: the reference, mesh), one table for all of them so
 * every such method takes the same names, defaults and ranges. A method's
 * parameter struct holds an fs_aniso_param_values member `aniso`, and its
 * table lists FS_ANISO_PARAM_DEFS(its struct type). */
#ifndef FS_ANISO_PARAMS_H
#define FS_ANISO_PARAMS_H
#include "anisotropy.h"
#include "params.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* The `field` parameter of the methods that sum a field (the reference, mesh). */
typedef enum { FS_FIELD_ISOTROPIC, FS_FIELD_ANISOTROPIC, FS_FIELD_ZHU_BRIDSON } fs_field_choice;
/* aniso_norm: the stretch normalisation, as fs_aniso_params.per_particle */
typedef enum { FS_ANISO_NORM_GLOBAL, FS_ANISO_NORM_VOLUME } fs_aniso_norm;
typedef struct fs_aniso_param_values {
    double aniso_radius, kappa;
    int n_eps;
    double aniso_scale;
    fs_aniso_norm aniso_norm;
    double lambda;
} fs_aniso_param_values;

#define FS_ANISO_PARAM_(T, f) #f, offsetof(T, aniso.f), FS_PARAM_CTYPE(((T *)0)->aniso.f)
#define FS_ANISO_PARAM_DEFS(T)                                                                                         \
    {FS_ANISO_PARAM_(T, aniso_radius),          FS_PARAM_FLOAT, FS_ANISO_RADIUS_R, 1.0, 40.0, NULL,                    \
     "anisotropic: WPCA radius, multiples of r"},                                                                      \
        {FS_ANISO_PARAM_(T, kappa),                                                                                    \
         FS_PARAM_FLOAT,                                                                                               \
         FS_ANISO_KAPPA,                                                                                               \
         1.0,                                                                                                          \
         100.0,                                                                                                        \
         NULL,                                                                                                         \
         "anisotropic: largest/smallest eigenvalue limit"},                                                            \
        {FS_ANISO_PARAM_(T, n_eps),                                                                                    \
         FS_PARAM_INT,                                                                                                 \
         FS_ANISO_N_EPS,                                                                                               \
         0,                                                                                                            \
         10000,                                                                                                        \
         NULL,                                                                                                         \
         "anisotropic: at or below this many neighbours: isotropic"},                                                  \
        {FS_ANISO_PARAM_(T, aniso_scale), FS_PARAM_FLOAT, FS_ANISO_SCALE, 0.05, 20.0, NULL,                            \
         "anisotropic: stretch scale"},                                                                                \
        {FS_ANISO_PARAM_(T, aniso_norm),      FS_PARAM_ENUM, FS_ANISO_PER_PARTICLE, 0, 1, "global|volume",             \
         "anisotropic: stretch normalisation"},                                                                        \
    {                                                                                                                  \
        FS_ANISO_PARAM_(T, lambda), FS_PARAM_FLOAT, FS_ANISO_LAMBDA, 0.0, 1.0, NULL,                                   \
            "anisotropic: Laplacian smoothing of centres"                                                              \
    }

/* ap from the values, for kernel k and particle radius r (sigma_ref included). */
void fs_aniso_params_set(fs_aniso_params *ap, const fs_aniso_param_values *v, fs_kernel k, float r);

#ifdef __cplusplus
}
#endif
#endif
