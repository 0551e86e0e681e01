/* A program of your own against the installed libfluidsurf: renders a particle
 * file with one method and with the exact reference, and prints the metrics
 * and the method's stage times; then the same comparison as a study
 * (fluidsurf_compare, the engine of `fluidsurf compare`), and its metrics table.
 *
 *   cc render_compare.c $(pkg-config --cflags --libs fluidsurf) -o render_compare
 *   ./render_compare PARTICLES METHOD [RADIUS [SIZE]]
 */
#include <fluidsurf/fluidsurf.h>

#include <stdio.h>
#include <stdlib.h>

static int fail(const char *what)
{
    fprintf(stderr, "render_compare: %s: %s\n", what, fluidsurf_last_error());
    return 1;
}

/* The method against the reference through compare's engine: 3 timed renders
 * after a warm-up, metrics.csv's columns. */
static int print_study(const fluidsurf_scene *s, fluidsurf_particles *p, const char *method)
{
    fluidsurf_study *st = NULL;
    const fluidsurf_particles *frames[1] = {p};
    if (fluidsurf_compare(s, frames, 1, method, NULL, 0, NULL, 0, 3, 0, &st)) return fail("compare");
    printf("study metrics (as fluidsurf compare writes metrics.csv):\n%s", fluidsurf_study_table(st, "metrics"));
    fluidsurf_study_free(st);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: render_compare PARTICLES METHOD [RADIUS [SIZE]]\n");
        return 2;
    }
    double radius = argc > 3 ? atof(argv[3]) : 0;
    int size = argc > 4 ? atoi(argv[4]) : 256;
    fluidsurf_particles *p = NULL;
    fluidsurf_scene *s = NULL;
    fluidsurf_image *im = NULL, *ref = NULL;
    fluidsurf_metrics m;
    int rc = 1;
    printf("libfluidsurf %s, API %d\n", fluidsurf_version(), fluidsurf_api_version());
    if (fluidsurf_particles_read(argv[1], NULL, &p)) fail("read");
    else if (fluidsurf_scene_new(&s) || fluidsurf_scene_set_size(s, size, size) ||
             (radius > 0 && fluidsurf_scene_set_radius(s, radius)))
        fail("scene");
    else if (fluidsurf_render(s, p, argv[2], NULL, 0, &im)) fail("render");
    else if (fluidsurf_reference(s, p, &ref)) fail("reference");
    else if (fluidsurf_metrics_compute(im, ref, 0, &m)) fail("metrics");
    else {
        printf("%zu particles, r = %g, %dx%d\n", fluidsurf_particles_count(p), fluidsurf_image_radius(im),
               fluidsurf_image_width(im), fluidsurf_image_height(im));
        printf("%s against reference: IoU %.4f, depth RMSE %.4f r, normal error %.3f deg\n", argv[2], m.mask_iou,
               m.depth_rmse_r, m.normal_mean_deg);
        for (int i = 0; i < fluidsurf_image_stage_count(im); i++)
            printf("  %-10s %9.3f ms  %s\n", fluidsurf_image_stage_name(im, i), fluidsurf_image_stage_ms(im, i),
                   fluidsurf_image_stage_renderer(im, i));
        rc = print_study(s, p, argv[2]);
    }
    fluidsurf_image_free(ref);
    fluidsurf_image_free(im);
    fluidsurf_scene_free(s);
    fluidsurf_particles_free(p);
    return rc;
}
