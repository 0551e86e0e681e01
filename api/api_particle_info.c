/* What `fluidsurf info` reports, for a particle set of the library: the radius
 * the spacing implies and the spacing and density statistics (particle_info.h). */
#include "api_internal.h"
#include "fs_error.h"
#include "particle_info.h"

#include <math.h>

/* p's particles validated, with their bounds, into q (the arrays stay p's). */
static int checked(const fluidsurf_particles *p, fs_particles *q)
{
    int rc = fs_api_check(p, "particles");
    if (rc) return rc;
    fs_api_init();
    *q = p->p;
    if ((rc = fs_particles_validate(q, "particles"))) return rc;
    fs_particles_bounds(q);
    return FLUIDSURF_OK;
}

int fluidsurf_particles_estimate_radius(const fluidsurf_particles *p, double *radius)
{
    fs_particles q;
    int rc = fs_api_check(radius, "radius");
    if (rc || (rc = checked(p, &q))) return rc;
    float r = 0;
    *radius = 0;
    if ((rc = fs_particles_estimate_radius(&q, &r))) return rc;
    *radius = r;
    return FLUIDSURF_OK;
}

int fluidsurf_particles_stats(const fluidsurf_particles *p, double radius, double volume_scale,
                              fluidsurf_particles_info *out)
{
    fs_particles q;
    int rc = fs_api_check(out, "out");
    if (rc || (rc = checked(p, &q))) return rc;
    if (!(radius >= 0 && radius <= 1e9))
        return fs_fail(FS_ERR_INPUT, "radius %g: must be 0 (none given) or positive and finite", radius);
    if (!(volume_scale > 0 && volume_scale <= 1e6))
        return fs_fail(FS_ERR_INPUT, "volume_scale %g: must be positive, at most 1e6", volume_scale);
    fs_particle_info in;
    if ((rc = fs_particle_info_compute(&q, (float)radius, (float)volume_scale, &in))) return rc;
    static const int source[] = {[FS_R_OPTION] = FLUIDSURF_R_GIVEN,
                                 [FS_R_FILE] = FLUIDSURF_R_FILE,
                                 [FS_R_ESTIMATED] = FLUIDSURF_R_ESTIMATED,
                                 [FS_R_DEFAULT] = FLUIDSURF_R_DEFAULT};
    *out = (fluidsurf_particles_info){q.n,
                                      {q.bmin[0], q.bmin[1], q.bmin[2]},
                                      {q.bmax[0], q.bmax[1], q.bmax[2]},
                                      in.radius,
                                      source[in.source],
                                      in.estimated,
                                      in.st.nn_median,
                                      in.st.density_median,
                                      volume_scale};
    return FLUIDSURF_OK;
}
