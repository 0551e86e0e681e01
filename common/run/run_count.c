/* The counting render of the run layer (run.h, docs/DESIGN.md "Work counters"). */
#include "caller_words.h"
#include "run.h"
#include "counters.h"
#include "fs_error.h"
#include "gl_counters.h"
#include <string.h>

int fs_run_check_counters(const fs_method *m)
{
    if (m->counters) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: method '%s' reports no work counters yet", fs_word("counters"), m->name);
}

/* The totals over the stages (the CSV's "total" rows) must not wrap either. */
static int check_totals(const fs_stages *st)
{
    uint64_t t;
    for (int c = 0; c < FS_NCOUNTERS; c++)
        if (fs_stages_count_total(st, c, &t))
            return fs_fail(FS_ERR_RUNTIME, "work counter %s overflowed 2^64 in its total over the stages",
                           fs_counter_name(c));
    return FS_OK;
}

/* Counts made after the last stage (or read from the GL buffer only by
 * fs_gl_counters_end) belong to no stage: an error, never dropped. */
static int check_attributed(const fs_method *m, const fs_stages *st)
{
    unsigned left = fs_counters_unattributed();
    if (!left) return FS_OK;
    int c = 0;
    while (!(left & FS_CNT_BIT(c))) c++;
    return fs_fail(FS_ERR_RUNTIME,
                   "method '%s': work counter %s was counted after its last stage (%s); no stage took it", m->name,
                   fs_counter_name(c), st->n ? st->name[st->n - 1] : "none");
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
    if (!rc) rc = check_attributed(m, st);
    if (!rc) rc = check_totals(st);
    fs_counters_reset();
    return rc;
}
