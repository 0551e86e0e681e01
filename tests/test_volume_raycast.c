/* volume_raycast (inacio2010) on the OSMesa context: the single-pass layered
 * density grid against the exact CPU grid (also with several draws, when a
 * particle reaches more layers than one geometry-shader draw emits); the method
 * against the CPU reference on a real dam break; layered, slice and exact builds
 * giving the same image; the translucent transfer function; the .vdb export. */
#include "density_grid.h"
#include "fs_error.h"
#include "fs_test.h"
#include "gl.h"
#include "gl_context.h"
#include "method.h"
#include "metrics.h"
#include "particle_io.h"
#include "scene.h"
#include "test_render.h"
#include "timing.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int load_dam(fs_particles *p, fs_scene *s, fs_field *f)
{
    int rc = fs_particles_read(p, FS_TEST_DATA "/splashsurf/dam_break_frame_9_6859_particles.bgeo", NULL);
    CHECK(rc == FS_OK, "read: %s", fs_error_message());
    if (rc) return rc;
    fs_particles_bounds(p);
    fs_scene_defaults(s);
    s->radius = 0.025f;
    s->volume_scale = 0.8f;
    s->camera.width = s->camera.height = 128;
    fs_scene_frame_particles(s, p);
    *f = fs_scene_field(s);
    return FS_OK;
}

/* Layered grid (read back) vs the exact CPU grid of the same shape. */
static double layered_vs_exact(const fs_particles *p, const fs_field *f, int res, double *ms)
{
    fs_density_grid a, b;
    double err = INFINITY;
    fs_grid ng;
    CHECK(fs_grid_build(&ng, p, f->H) == FS_OK, "grid: %s", fs_error_message());
    CHECK(fs_density_grid_init(&a, p->bmin, p->bmax, f->H, res) == FS_OK, "init: %s", fs_error_message());
    CHECK(fs_density_grid_init(&b, p->bmin, p->bmax, f->H, res) == FS_OK, "init: %s", fs_error_message());
    fs_layered_splat *ls = fs_layered_splat_create();
    CHECK(ls != NULL, "create: %s", fs_error_message());
    unsigned tex = fs_density_texture_create(&a);
    CHECK(tex != 0, "texture: %s", fs_error_message());
    if (ls && tex && a.data && b.data) {
        glFinish();
        double t0 = fs_now_ms();
        int rc = fs_layered_splat_run(ls, &a, p, f, tex);
        glFinish();
        *ms = fs_now_ms() - t0;
        CHECK(rc == FS_OK, "layered splat: %s", fs_error_message());
        CHECK(fs_density_texture_read(tex, &a) == FS_OK, "read back: %s", fs_error_message());
        CHECK(fs_density_grid_exact(&b, p, &ng, f) == FS_OK, "exact: %s", fs_error_message());
        err = fs_density_grid_rel_l2(&a, &b);
        printf("  %zu particles, %dx%dx%d grid, %zu points drawn (%.0f ms): rel L2 %.3g\n", p->n, a.dim[0], a.dim[1],
               a.dim[2], fs_layered_splat_points(ls), *ms, err);
    }
    if (tex) glDeleteTextures(1, &tex);
    fs_layered_splat_destroy(ls);
    fs_density_grid_free(&a);
    fs_density_grid_free(&b);
    fs_grid_free(&ng);
    return err;
}

static void layered_grid(void)
{
    fs_particles p;
    fs_scene s;
    fs_field f;
    if (load_dam(&p, &s, &f)) return;
    double ms;
    printf("(a) layered vs exact grid\n");
    double e = layered_vs_exact(&p, &f, 128, &ms);
    CHECK(e < 1e-5, "dam break, cubic: rel L2 %g", e);
    f.kernel = FS_KERNEL_POLY6; /* the paper's kernel */
    e = layered_vs_exact(&p, &f, 96, &ms);
    CHECK(e < 1e-5, "dam break, poly6: rel L2 %g", e);
    fs_particles_free(&p);
    /* three particles on a fine grid: each reaches ~300 layers, more than one
     * draw covers, so the draw repeats with a layer offset */
    fs_particles q;
    CHECK(fs_particles_alloc(&q, 3, 0) == FS_OK, "alloc");
    for (int i = 0; i < 3; i++) {
        q.x[i] = 0.01f * i;
        q.y[i] = 0.02f * (i == 1);
        q.z[i] = -0.01f * i;
    }
    fs_particles_bounds(&q);
    f.kernel = FS_KERNEL_CUBIC;
    e = layered_vs_exact(&q, &f, 300, &ms);
    CHECK(e < 1e-5, "fine grid: rel L2 %g", e);
    fs_particles_free(&q);
}

int main(void)
{
    fs_gl_context ctx;
    if (fs_gl_context_create(&ctx, FS_CTX_OSMESA, 16, 16)) { CHECK(0, "context: %s", fs_error_message()); TEST_DONE(); }
    layered_grid();
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
