/* Shepard interpolation of particle attributes at the vertices (mesh_attributes.h),
 * over the 27 grid cells around each vertex (the cell is at least H). */
#include "mesh_attributes.h"
#include "fs_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The attribute of original particle i, component a (vel or col per `which`). */
static float attr(const fs_particles *p, int which, uint32_t i, int a)
{
    if (which == 0) return (a == 0 ? p->vx : a == 1 ? p->vy : p->vz)[i];
    return p->color[3 * (size_t)i + a];
}

static void interpolate(const fs_grid *g, const fs_field *f, const fs_particles *p, int which, const float x[3],
                        float out[3])
{
    double num[3] = {0, 0, 0}, den = 0;
    fs_grid_box b;
    fs_grid_box_around(&b, g, x);
    for (uint32_t s0, s1; fs_grid_box_next(&b, &s0, &s1);)
        for (uint32_t s = s0; s < s1; s++) {
            const float *y = g->pos4 + 4 * (size_t)s;
            float d[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
            float r = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (r >= f->H) continue;
            double W = fs_kernel_w(f->kernel, r, f->H);
            for (int a = 0; a < 3; a++) num[a] += W * attr(p, which, g->index[s], a);
            den += W;
        }
    for (int a = 0; a < 3; a++) out[a] = den > 0 ? (float)(num[a] / den) : 0;
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
