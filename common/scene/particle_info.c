/* The numbers `fluidsurf info` prints (particle_info.h). */
#include "particle_info.h"
#include "fs_error.h"
#include "particle_arrays.h"

#include <stdio.h>

int fs_particle_info_compute(const fs_particles *p, float radius, float volume_scale, fs_particle_info *out)
{
    float est = 0;
    /* No spacing to measure (many coincident particles) is an error only when nothing
     * else gives a radius: a simulator's clamp can pile particles on one point. */
    int rc = fs_particles_estimate_radius(p, &est);
    if (rc && p->n > 1 && !(radius > 0 || p->radius > 0)) return rc;
    if (rc) fs_error_clear();
    fs_scene s;
    fs_scene_defaults(&s);
    out->source = radius > 0 ? FS_R_OPTION : p->radius > 0 ? FS_R_FILE : est > 0 ? FS_R_ESTIMATED : FS_R_DEFAULT;
    s.radius = radius > 0 ? radius : p->radius > 0 ? p->radius : est > 0 ? est : s.radius;
    s.volume_scale = volume_scale;
    out->radius = s.radius, out->estimated = est > 0 ? est : 0, out->volume_scale = volume_scale;
    fs_field f = fs_scene_field(&s);
    return fs_particles_stats(p, &f, &out->st);
}

void fs_particle_info_arrays(const fs_particles *p, char *out, size_t size)
{
    size_t used = 0;
    if (!size) return;
    out[0] = '\0';
    for (int i = 0; i < p->narrays && used < size; i++) {
        const fs_point_array *a = &p->arrays[i];
        int k = snprintf(out + used, size - used, "%s%s (%d x %s)", i ? ", " : "", a->name, a->ncomp,
                         fs_array_type_name(a->type));
        if (k < 0) break;
        used += (size_t)k;
    }
}
