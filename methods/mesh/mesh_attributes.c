/* Shepard interpolation of particle attributes at the vertices (mesh_attributes.h). */
#include "mesh_attributes.h"
#include "mesh_shepard.h"
#include "fs_error.h"
#include <stdlib.h>

/* What the Shepard sum reads: the particles' velocity (which 0) or colour (1). */
typedef struct {
    const fs_particles *p;
    const fs_grid *g;
    int which;
} attr_source;

/* Component a of the attribute of the particle in sorted slot s. */
static float attr(const void *ctx, uint32_t s, int a)
{
    const attr_source *src = ctx;
    uint32_t i = src->g->index[s];
    if (src->which == 0) return (a == 0 ? src->p->vx : a == 1 ? src->p->vy : src->p->vz)[i];
    return src->p->color[3 * (size_t)i + a];
}

static void interpolate(const fs_grid *g, const fs_field *f, const fs_particles *p, int which, const float x[3],
                        float out[3])
{
    attr_source src = {p, g, which};
    double mean[3];
    fs_mesh_shepard(g, f, x, attr, &src, 3, mean, NULL);
    for (int a = 0; a < 3; a++) out[a] = (float)mean[a];
}

static int fill(fs_trimesh *m, const fs_particles *p, const fs_grid *g, const fs_field *f, int which, float **dst)
{
    *dst = malloc((m->nv ? m->nv : 1) * 3 * sizeof **dst);
    if (!*dst) return fs_fail(FS_ERR_RUNTIME, "mesh: out of memory for %zu vertex attributes", m->nv);
    long nv = (long)m->nv;
#pragma omp parallel for schedule(dynamic, 256)
    for (long v = 0; v < nv; v++) interpolate(g, f, p, which, m->pos + 3 * v, *dst + 3 * v);
    return FS_OK;
}

int fs_mesh_attributes(fs_trimesh *m, const fs_particles *p, const fs_grid *g, const fs_field *f)
{
    int rc = FS_OK;
    if (p->vx && p->vy && p->vz) rc = fill(m, p, g, f, 0, &m->vel);
    if (!rc && p->color) rc = fill(m, p, g, f, 1, &m->col);
    return rc;
}
