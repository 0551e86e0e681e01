/* The density-grid methods' frame and its grid (density_frame.h). */
#include "density_frame.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_stage.h"

void fs_density_frame_free(fs_density_frame *d)
{
    if (d->has_own) fs_grid_free(&d->own);
    if (d->dropped) fs_particles_free(&d->bulk);
    d->has_own = 0, d->dropped = 0, d->p = d->all = NULL, d->ng = NULL;
}

int fs_density_frame_upload(fs_density_frame *d, const fs_particles *p, const fs_grid *g, float H, int fit,
                            const char *method, const char *what)
{
    if (d->dropped) fs_particles_free(&d->bulk);
    d->p = d->all = NULL;
    int rc = fs_density_grid_keep(p, g->bulk_lo, g->bulk_hi, H, &d->bulk, &d->dropped);
    if (rc) {
        d->dropped = 0;
        return rc;
    }
    if (d->dropped)
        fs_note("%s: %zu far stray particle(s) outside the bulk are left out of %s", method, d->dropped, what);
    d->p = &d->bulk;
    d->all = p;
    d->ng = g;
    if (!fit) return FS_OK;
    return fs_grid_fit(g, p, H, &d->own, &d->has_own, &d->ng);
}

/* The build itself: GL splatting, or a CPU-side grid uploaded when there is a texture. */
static int build(const fs_density_builder *b, const fs_density_frame *d, const fs_field *f, fs_density_grid *dg,
                 unsigned tex3d)
{
    if (b->build == FS_DENSITY_LAYERED) return fs_layered_splat_run(b->layered, dg, d->p, f, tex3d);
    int rc = b->build == FS_DENSITY_SLICE ? fs_slice_splat_run(b->slice, dg, d->p, f, b->up_axis, b->clusters)
                                          : fs_density_grid_exact(dg, d->all, d->ng, f);
    return !rc && tex3d ? fs_density_texture_upload(tex3d, dg) : rc;
}

int fs_density_frame_build(const fs_density_builder *b, const fs_density_frame *d, const fs_field *f,
                           fs_density_grid *dg, unsigned tex3d, fs_stages *t, const char *stage, double *t_end)
{
    double t0 = fs_gl_stage_start(), t1;
    int rc = build(b, d, f, dg, tex3d);
    if (rc || !t) return rc; /* untimed (an export) */
    if (b->gl_clock) {
        t1 = fs_gl_stage_end(t, stage, t0);
    } else { /* a CPU-side build: the GL clock would time the CPU */
        glFinish();
        t1 = fs_now_ms();
        fs_stages_add(t, stage, t1 - t0);
    }
    if (t_end) *t_end = t1;
    return FS_OK;
}
