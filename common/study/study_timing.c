/* The timing protocol (docs/DESIGN.md, "Timing"), written once for compare,
 * the library, Python and render_bench. */
#include "study.h"
#include "fs_error.h"
#include "stats.h"

int fs_study_time_renders(fs_run *run, const fs_camera *cam, fs_run_image *im, int repeat, fs_stages *runs,
                          double *median_ms)
{
    if (repeat < 1 || repeat > FS_STUDY_MAX_RUNS)
        return fs_fail(FS_ERR_INPUT, "repeat %d: expected 1 to %d timed renders", repeat, FS_STUDY_MAX_RUNS);
    double times[FS_STUDY_MAX_RUNS];
    for (int k = 0; k <= repeat; k++) { /* run 0 is the warm-up */
        fs_stages st = {0};
        int rc = fs_run_render(run, cam, im, &st);
        if (rc) return rc;
        if (k == 0) continue;
        times[k - 1] = fs_stages_total(&st);
        if (runs) runs[k - 1] = st;
    }
    *median_ms = fs_median(times, repeat);
    return FS_OK;
}

int fs_study_render_once(fs_run *run, const fs_scene *s, const fs_particles *p, const fs_grid *g, fs_run_image *im,
                         fs_stages *st)
{
    int rc = fs_run_upload(run, p, g, st);
    if (!rc) rc = fs_run_render(run, &s->camera, im, st);
    if (!rc) rc = fs_run_shade(run, &s->camera, im, FS_APPEARANCE_SHARED, st);
    return rc;
}
