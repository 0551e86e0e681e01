/* fs_aniso_params from a method's parameter values (aniso_params.h). */
#include "aniso_params.h"

void fs_aniso_params_set(fs_aniso_params *ap, const fs_aniso_param_values *v, fs_kernel k, float r)
{
    fs_aniso_defaults(ap, k, r);
    ap->radius = (float)v->aniso_radius * r;
    ap->kappa = (float)v->kappa;
    ap->n_eps = v->n_eps;
    ap->scale = (float)v->aniso_scale;
    ap->per_particle = v->aniso_norm == FS_ANISO_NORM_VOLUME;
    ap->lambda = (float)v->lambda;
    ap->sigma_ref = (float)fs_aniso_sigma_ref(k, ap->radius, 2 * r);
}
