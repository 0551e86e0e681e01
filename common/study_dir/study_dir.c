/* A planned study run into its folder (study_dir.h): the folder claimed, the
 * shards planned or the merge mapped, every work item through the study, the
 * results written. */
#include "study_dir_state.h"
#include "fs_error.h"
#include "merge.h"
#include "outputs_list.h"
#include "progress.h"
#include "report_html.h"
#include "scene_provenance.h"
#include "shard.h"
#include "stats.h"
#include "timing.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static double since_s(double t0) { return (fs_now_ms() - t0) / 1000.0; }

static int make_outdir(const char *dir, int *made)
{
    struct stat st;
    if (stat(dir, &st) != 0) {
        if (mkdir(dir, 0755) != 0)
            return fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", dir, strerror(errno));
        *made = 1;
    } else if (!S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: exists and is not a folder", dir);
    if (access(dir, W_OK) != 0) return fs_fail(FS_ERR_INPUT, "%s: output folder is not writable", dir);
    return FS_OK;
}

/* --resume: the folder's earlier views are all this run's (fs_outputs_resume_check). */
static int resume_check(const fs_study_dir *r)
{
    const fs_study *s = r->s;
    const char *labels[FS_STUDY_MAX_REFS + FS_STUDY_MAX_ENTRIES];
    int n = 0;
    for (int k = 0; k < s->nrefs; k++) labels[n++] = s->refs[k].label;
    for (int i = 0; i < s->nentries; i++) labels[n++] = s->entries[i].label;
    return fs_outputs_resume_check(r->outdir, labels, n);
}

/* The output folder (a merge's staging folder), made or claimed. */
static int claim_folder(fs_study_dir *r)
{
    const char *dir = r->merge ? r->merge->staging : r->o->dir;
    if (strlen(dir) >= FS_STUDY_DIR_MAX) return fs_fail(FS_ERR_INPUT, "%s: output folder path too long", dir);
    snprintf(r->outdir, sizeof r->outdir, "%s", dir);
    int rc = make_outdir(r->outdir, &r->made_outdir);
    /* a merge writes into its fresh staging folder; merge itself checks the output */
    if (!rc && !r->made_outdir && !r->merge) rc = fs_outputs_claim(r->outdir, "compare", r->o->resume, r->o->force);
    if (!rc && !r->made_outdir && !r->merge && r->o->resume && !r->o->force) rc = resume_check(r);
    return rc;
}

/* Shards: the split and a fresh start; merge: every item's record. */
static int plan_shards(fs_study_dir *r)
{
    if (r->merge) return fs_merge_map(r->merge, r);
    if (!r->o->shard_n) return FS_OK;
    int rc = fs_shard_plan(r);
    return rc ? rc : fs_shard_start(r);
}

/* The provenance: a shard names itself; a merge names the shards' machines. */
static int provenance(fs_study_dir *r, const fs_gl_context *ctx)
{
    fs_provenance_init(&r->s->prov, &r->s->scene, ctx ? ctx->renderer : NULL, ctx ? ctx->version : NULL);
    if (r->merge) fs_merge_provenance(r->merge, &r->s->prov);
    if (!r->o->shard_n || r->merge) return FS_OK;
    char v[32];
    snprintf(v, sizeof v, "%d/%d", r->o->shard_k, r->o->shard_n);
    fs_provenance_set(&r->s->prov, "shard", v);
    return fs_shard_write(r, 0);
}

/* The first frame (it settles r and the camera), a GL context if any variant
 * needs one, the provenance, then every work item through the study. */
static int execute(fs_study_dir *r, const fs_study_io *io, int *have_ctx)
{
    const fs_study_dir_opts *o = r->o;
    const fs_gl_context *ctx = NULL;
    int rc = fs_study_load_first(r->s, o->radius, r->radius_note, sizeof r->radius_note);
    if (!rc && r->radius_note[0]) fs_note("%s", r->radius_note); /* before the work: what r and up it took */
    if (!rc && fs_study_needs_gl(r->s, io)) {
        rc = o->gl_acquire ? o->gl_acquire(o->gl_user, &ctx) : fs_fail(FS_ERR_RUNTIME, "no GL context to render in");
        *have_ctx = !rc;
    }
    if (!rc) rc = provenance(r, ctx);
    if (!rc) rc = fs_study_alloc(r->s);
    if (rc) return rc;
    fs_progress_begin(r->merge ? "merge" : "compare", r->merge ? "work items loaded" : "work items",
                      fs_study_items_here(r->s, io));
    rc = fs_study_execute(r->s, io, ctx);
    fs_progress_end();
    return rc;
}

/* Heatmap scales: fixed by option, else the largest 95th percentile over the
 * entries against the first reference, rounded up to 1/2/5 x 10^k. */
static void choose_scales(fs_study_dir *r)
{
    double nmax = 0, dmax = 0;
    for (int i = 0; i < r->s->nentries; i++) {
        const fs_metrics *mt = &r->s->entries[i].metrics[0];
        if (isfinite(mt->normal_p95_deg) && mt->normal_p95_deg > nmax) nmax = mt->normal_p95_deg;
        if (isfinite(mt->depth_p95_r) && mt->depth_p95_r > dmax) dmax = mt->depth_p95_r;
    }
    r->normal_scale_deg = r->o->normal_scale_deg > 0 ? r->o->normal_scale_deg : fs_nice_ceil(nmax > 0 ? nmax : 10);
    r->depth_scale_r = r->o->depth_scale_r > 0 ? r->o->depth_scale_r : fs_nice_ceil(dmax > 0 ? dmax : 1);
}

static int write_outputs(fs_study_dir *r)
{
    choose_scales(r);
    int rc = fs_study_dir_write_table(r, "metrics");
    if (!rc) rc = fs_study_dir_write_table(r, "timings");
    if (!rc && r->s->nframes > 1) rc = fs_study_dir_write_table(r, "temporal");
    if (!rc) rc = fs_study_dir_write_diffs(r);
    if (!rc) rc = fs_study_dir_write_panel(r);
    if (!rc && r->s->counters) rc = fs_study_dir_write_table(r, "counters");
    if (!rc) rc = fs_study_dir_write_report(r);
    if (!rc) rc = fs_report_html_write(r->outdir, 1); /* last: the page is built from the files above */
    return rc;
}

/* What one process says when it is done. */
static void done_notes(const fs_study_dir *r, const fs_study_io *io, double t_start)
{
    if (r->o->resume) fs_note("--resume: %d work item(s) loaded from %s/, the rest rendered", r->resumed, r->outdir);
    if (r->merge)
        fs_note("merge of %d shards done in %.1f s, outputs in %s/", r->merge->n, since_s(t_start), r->merge->out_arg);
    else if (r->o->shard_n)
        fs_note("shard %d/%d done in %.1f s: %ld work item(s), outputs in %s/", r->o->shard_k, r->o->shard_n,
                since_s(t_start), fs_study_items_here(r->s, io), r->outdir);
    else if (r->o->dir) fs_note("compare done in %.1f s, outputs in %s/", since_s(t_start), r->outdir);
}

/* The folder's side of the run, then the items and the outputs. */
static int run(fs_study_dir *r, int *have_ctx)
{
    int rc = r->o->dir || r->merge ? claim_folder(r) : FS_OK;
    if (!rc) rc = plan_shards(r);
    if (rc) return rc;
    fs_ref_cache_open(&r->cache, r->o->use_cache ? r->o->cache_dir : NULL, r->o->use_cache, r->o->quiet);
    r->cache.counters = r->s->counters; /* the references' counts come with their views */
    fs_study_io io = fs_study_dir_io(r);
    double t_start = fs_now_ms();
    rc = execute(r, r->o->dir || r->merge ? &io : NULL, have_ctx);
    if (!rc && (r->o->dir || r->merge)) rc = r->o->shard_n && !r->merge ? fs_shard_write(r, 1) : write_outputs(r);
    if (r->merge) {
        int prc = fs_merge_publish(r->merge, !rc);
        rc = rc ? rc : prc;
    }
    if (!rc) done_notes(r, &io, t_start);
    return rc;
}

int fs_study_dir_run(fs_study *s, const fs_study_dir_opts *o)
{
    fs_study_dir dir = {.s = s, .o = o, .merge = o->merge}, *r = &dir;
    s->measure = !o->shard_n; /* a shard has not every reference's view to measure against */
    int have_ctx = 0, rc = run(r, &have_ctx);
    if (rc && r->made_outdir) rmdir(r->outdir); /* only if still empty: a refused context left nothing */
    if (have_ctx && o->gl_release) o->gl_release(o->gl_user);
    free(r->owner);
    return rc;
}
