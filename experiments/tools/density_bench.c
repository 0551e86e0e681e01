/* density_bench: the density grid of a scene's particles built by the exact CPU
 * sum (neighbour grid build + fs_density_grid_exact) and by iwasaki2006's slice
 * splatting, timed per run, the splat grid compared with the exact one.
 *
 *   density_bench SCENE.json LABEL RES [RUNS [CLUSTERS]]
 *
 * The grid spans the particles' bounding box padded by the support H, with RES
 * points along its longest axis; planes are stacked along the scene's up axis.
 * Prints CSV rows without a header:
 *   label,particles,res,dims,method,run,ms,rel_l2_vs_exact,disks,renderer,threads,gpu_ms,gl_version
 * method exact_cpu: neighbour grid build + exact sum (OpenMP over planes);
 * method slice_splat: clustering + upload + every 4-plane pass + read back, on
 * the OSMesa context (GL_RENDERER in the row). Each splat run is compared with
 * the first exact grid; each exact run with the first (should be 0). gpu_ms: the
 * GL clock (gl_stage.h) of a splat run, empty for the CPU builder. */
#include "density_splat.h"
#include "frame_source.h"
#include "fs_error.h"
#include "gl_context.h"
#include "gl_stage.h"
#include "scene.h"
#include "timing.h"
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: density_bench SCENE.json LABEL RES [RUNS [CLUSTERS]]\n");
        return 2;
    }
    const char *label = argv[2];
    int res = atoi(argv[3]), runs = argc > 4 ? atoi(argv[4]) : 3, clusters = argc > 5 ? atoi(argv[5]) : 16;
    if (runs < 1) runs = 1;
    fs_scene sc;
    fs_particles p;
    int rc = fs_scene_load(&sc, argv[1]);
    if (!rc) rc = fs_scene_load_frame(&sc, 0, &p);
    if (rc) {
        fprintf(stderr, "density_bench: %s\n", fs_error_message());
        return rc;
    }
    fs_particles_bounds(&p);
    fs_field f = {sc.radius, sc.volume_scale * 8 * sc.radius * sc.radius * sc.radius, sc.kernel,
                  sc.support_r * sc.radius, sc.iso};
    fs_density_grid ex, cur;
    rc = fs_density_grid_init(&ex, p.bmin, p.bmax, f.H, res);
    if (!rc) rc = fs_density_grid_init(&cur, p.bmin, p.bmax, f.H, res);
    if (rc) {
        fprintf(stderr, "density_bench: %s\n", fs_error_message());
        return rc;
    }
    char dims[64];
    snprintf(dims, sizeof dims, "%dx%dx%d", ex.dim[0], ex.dim[1], ex.dim[2]);
    int threads = omp_get_max_threads();
    /* first touch of the grids' pages outside every timing */
    memset(ex.data, 0, fs_density_grid_points(&ex) * sizeof(float));
    memset(cur.data, 0, fs_density_grid_points(&cur) * sizeof(float));

    for (int r = 0; r < runs; r++) {
        fs_density_grid *g = r == 0 ? &ex : &cur;
        double t0 = fs_now_ms();
        fs_grid ng;
        rc = fs_grid_build(&ng, &p, f.H);
        if (!rc) rc = fs_density_grid_exact(g, &p, &ng, &f);
        double ms = fs_now_ms() - t0;
        fs_grid_free(&ng);
        if (rc) {
            fprintf(stderr, "density_bench: %s\n", fs_error_message());
            return rc;
        }
        printf("%s,%zu,%d,%s,exact_cpu,%d,%.2f,%.3g,,CPU (C + OpenMP),%d,,\n", label, p.n, res, dims, r + 1, ms,
               fs_density_grid_rel_l2(g, &ex), threads);
        fflush(stdout);
    }

    fs_gl_context ctx;
    if (fs_gl_context_create(&ctx, fs_gl_context_default_kind(), 16, 16)) {
        fprintf(stderr, "density_bench: %s\n", fs_error_message());
        return 1;
    }
    fs_slice_splat *ss = fs_slice_splat_create();
    if (!ss) {
        fprintf(stderr, "density_bench: %s\n", fs_error_message());
        return 1;
    }
    for (int r = 0; r < runs + 1; r++) { /* run 0 warms up (shader JIT, first allocation), not printed */
        fs_stages st = {0};
        double t0 = fs_gl_stage_start();
        rc = fs_slice_splat_run(ss, &cur, &p, &f, sc.up_axis, clusters);
        fs_gl_stage_end(&st, "slice_splat", t0); /* the run ends with a read back: nothing left in flight */
        double ms = st.ms[0];
        if (rc) {
            fprintf(stderr, "density_bench: %s\n", fs_error_message());
            return rc;
        }
        if (r == 0) continue;
        char gpu[32] = ""; /* empty when the context has no GL clock */
        if (!isnan(st.gpu_ms[0])) snprintf(gpu, sizeof gpu, "%.2f", st.gpu_ms[0]);
        printf("%s,%zu,%d,%s,slice_splat,%d,%.2f,%.3g,%zu,\"%s\",%d,%s,\"%s\"\n", label, p.n, res, dims, r, ms,
               fs_density_grid_rel_l2(&cur, &ex), fs_slice_splat_disks(ss), ctx.renderer, threads, gpu, ctx.version);
        fflush(stdout);
    }
    fs_slice_splat_destroy(ss);
    fs_gl_context_destroy(&ctx);
    fs_density_grid_free(&ex);
    fs_density_grid_free(&cur);
    fs_particles_free(&p);
    return 0;
}
