/* The counting render of the run layer (run.h, docs/DESIGN.md "Work counters"). */
#include "run.h"
#include "counters.h"
#include "fs_error.h"
#include "gl_counters.h"
#include <string.h>

int fs_run_check_counters(const fs_method *m)
{
    if (m->counters) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "--counters: method '%s' reports no work counters yet", m->name);
}

/* The totals over the stages (the CSV's "total" rows) must not wrap either. */
static int check_totals(const fs_stages *st)
{
    for (int c = 0; c < FS_NCOUNTERS; c++) {
        uint64_t t = 0;
        for (int i = 0; i < st->n; i++) {
            if (t + st->count[i][c] < t)
                return fs_fail(FS_ERR_RUNTIME, "work counter %s overflowed 2^64 in its total over the stages",
                               fs_counter_name(c));
            t += st->count[i][c];
        }
    }
    return FS_OK;
}

int fs_run_count(const fs_method *m, const fs_scene *s, const double *values, const fs_gl_context *ctx,
                 const fs_particles *p, const fs_grid *g, const fs_camera *cam, fs_run_image *im, fs_stages *st)
{
    int rc = fs_run_check_counters(m);
    if (rc) return rc;
    memset(st, 0, sizeof *st);
    fs_run *run = NULL;
    fs_counters_reset();
    fs_counting_set(1);
    rc = fs_run_open(&run, m, s, values, m->needs_gl ? ctx : NULL);
    int gl = !rc && m->needs_gl;
    if (gl) rc = fs_gl_counters_begin();
    if (!rc) rc = fs_run_upload(run, p, g, st);
    if (!rc) rc = fs_run_render(run, cam, im, st);
    if (gl) fs_gl_counters_end();
    fs_counting_set(0);
    fs_run_close(run);
    if (!rc) rc = fs_counters_check();
    if (!rc) rc = check_totals(st);
    fs_counters_reset();
    return rc;
}
