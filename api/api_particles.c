/* Particle sets of the library: the caller's arrays in place, or a file read. */
#include "api_internal.h"
#include "fs_error.h"
#include "particle_io.h"

#include <stdlib.h>
#include <string.h>

static fluidsurf_particles *new_set(void)
{
    fluidsurf_particles *p = calloc(1, sizeof *p);
    if (!p) fs_fail(FS_ERR_RUNTIME, "out of memory");
    return p;
}

int fluidsurf_particles_wrap(size_t n, const float *x, const float *y, const float *z, fluidsurf_particles **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out")) || (rc = fs_api_check(x, "x")) || (rc = fs_api_check(y, "y")) ||
        (rc = fs_api_check(z, "z")))
        return rc;
    *out = NULL;
    if (!n) return fs_fail(FS_ERR_INPUT, "particles: no particles (n = 0)");
    fluidsurf_particles *p = new_set();
    if (!p) return FS_ERR_RUNTIME;
    /* in place: the library only reads them (the struct's pointers are not const) */
    p->p.n = n;
    p->p.x = (float *)x, p->p.y = (float *)y, p->p.z = (float *)z;
    *out = p;
    return FLUIDSURF_OK;
}

int fluidsurf_particles_set_color(fluidsurf_particles *p, const float *rgb)
{
    int rc = fs_api_check(p, "particles");
    if (rc) return rc;
    if (p->owned) return fs_fail(FS_ERR_INPUT, "particles: colours can be set on wrapped arrays only");
    p->p.color = (float *)rgb;
    return FLUIDSURF_OK;
}

int fluidsurf_particles_read(const char *path, const char *format, fluidsurf_particles **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out")) || (rc = fs_api_check(path, "path"))) return rc;
    fs_api_init();
    *out = NULL;
    fluidsurf_particles *p = new_set();
    if (!p) return FS_ERR_RUNTIME;
    if ((rc = fs_particles_read(&p->p, path, format && format[0] ? format : NULL))) {
        free(p);
        return rc;
    }
    p->owned = 1;
    *out = p;
    return FLUIDSURF_OK;
}

size_t fluidsurf_particles_count(const fluidsurf_particles *p) { return p ? p->p.n : 0; }
double fluidsurf_particles_radius(const fluidsurf_particles *p) { return p ? p->p.radius : 0; }

const void *fluidsurf_particles_column(const fluidsurf_particles *p, const char *name, int *ncomp)
{
    if (ncomp) *ncomp = 0;
    if (!p || !name) return NULL;
    const struct {
        const char *name;
        const void *data;
        int ncomp;
    } cols[] = {
        {"x", p->p.x, 1},   {"y", p->p.y, 1},   {"z", p->p.z, 1},         {"vx", p->p.vx, 1},
        {"vy", p->p.vy, 1}, {"vz", p->p.vz, 1}, {"color", p->p.color, 3}, {"phase", p->p.phase, 1},
    };
    for (size_t i = 0; i < sizeof cols / sizeof *cols; i++)
        if (!strcmp(cols[i].name, name) && cols[i].data) {
            if (ncomp) *ncomp = cols[i].ncomp;
            return cols[i].data;
        }
    return NULL;
}

int fluidsurf_particles_array_count(const fluidsurf_particles *p) { return p ? p->p.narrays : 0; }

const void *fluidsurf_particles_array(const fluidsurf_particles *p, int i, const char **name, int *ncomp, int *type)
{
    static const int types[] = {[FS_ARRAY_F32] = FLUIDSURF_ARRAY_F32,
                                [FS_ARRAY_F64] = FLUIDSURF_ARRAY_F64,
                                [FS_ARRAY_I32] = FLUIDSURF_ARRAY_I32,
                                [FS_ARRAY_U32] = FLUIDSURF_ARRAY_U32};
    if (name) *name = NULL;
    if (ncomp) *ncomp = 0;
    if (type) *type = 0;
    if (!p || i < 0 || i >= p->p.narrays) return NULL;
    const fs_point_array *a = &p->p.arrays[i];
    if (name) *name = a->name;
    if (ncomp) *ncomp = a->ncomp;
    if (type) *type = types[a->type];
    return a->data;
}

void fluidsurf_particles_free(fluidsurf_particles *p)
{
    if (!p) return;
    if (p->owned) fs_particles_free(&p->p);
    free(p);
}
