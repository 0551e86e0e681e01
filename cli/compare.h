/* `fluidsurf compare`: the state shared by the run (cmd_compare.c) and the
 * writers of its outputs (compare_outputs.c). */
#ifndef FS_COMPARE_H
#define FS_COMPARE_H
#include "cli.h"
#include "gbuffer.h"
#include "gl_context.h"
#include "metrics.h"
#include "output_file.h"
#include "provenance.h"
#include "ref_cache.h"
#include "run.h"
#include "scene.h"
#include "study.h"
#include "sweep.h"
#include "timing.h"
#include <stdio.h>

#define CMP_MAX_ENTRIES FS_STUDY_MAX_ENTRIES
#define CMP_MAX_REFS FS_STUDY_MAX_REFS
#define CMP_MAX_RUNS FS_STUDY_MAX_RUNS

/* A view of one frame, a reference and an entry: the study's (study.h). */
typedef fs_run_image cmp_view;
typedef fs_study_ref cmp_ref;
typedef fs_study_entry cmp_entry;

struct cmp_merge; /* compare_merge.h */

/* The study and where its items come from and go to: the output folder, the
 * reference cache, --resume, --shard and merge (compare_io.c). */
typedef struct cmp_run {
    fs_study s;             /* the plan and its results table */
    char radius_note[1024]; /* fs_scene_adopt_frame's note, printed after success */
    char outdir[1024];
    char command[4096];
    int quiet;
    int made_outdir;         /* this run made outdir: a failure before any output removes it */
    int resume, resumed;     /* --resume; the work items it loaded */
    int force;               /* --force: an earlier run's files are removed first (compare_outdir.h) */
    int shard_k, shard_n;    /* --shard K/N; 0/0 renders every work item */
    int *owner;              /* with --shard: each work item's shard, 1..N (cmp_item_id) */
    struct cmp_merge *merge; /* fluidsurf merge: every item comes from a shard's folder */
    int argc;                /* the command line, for a shard's manifest */
    char **argv;
    double normal_scale_deg, depth_scale_r; /* heatmap scales, the same for every entry */
    cli_cache cache;                        /* for the references */
} cmp_run;

static inline int cmp_item_id(const cmp_run *r, int is_ref, int index, int f)
{
    return fs_study_item_id(&r->s, is_ref, index, f);
}
static inline int cmp_item_count(const cmp_run *r) { return fs_study_item_count(&r->s); }
/* 1 when this process renders item id: not a merge, and no shard or this shard's item. */
static inline int cmp_renders(const cmp_run *r, int id)
{
    return !r->merge && (!r->owner || r->owner[id] == r->shard_k);
}
/* The parsed command line. */
typedef struct cmp_options {
    const char *input, *methods;
    const char *const *refspecs;
    int nrefspecs;
    const char *const *imports;
    int nimports;
    const char *const *sets;
    int nsets, w, h;
    float radius, nscale, dscale;
    cli_scene_opts field;
    fs_ctx_kind ctx_kind;
    const char *cache_dir; /* NULL: the default folder */
    int no_cache;
    int counters;
} cmp_options;

/* The study's plan from the command line, the output folder claimed
 * (compare_plan.c); errors are printed. */
int cmp_plan(cmp_run *r, const cmp_options *o);
/* The command line as a shell would take it back, for report.md. */
void cmp_quote_command(char *buf, int size, int argc, char **argv);

/* The study's hooks for this run (compare_io.c). */
fs_study_io cmp_io(cmp_run *r);

/* DIR/name opened through a temporary file; cmp_close checks every write and
 * the close, then renames it into place (or removes it). */
typedef fs_output cmp_file;
int cmp_open(const cmp_run *r, const char *name, cmp_file *cf);
int cmp_close(cmp_file *cf);

/* Writers (compare_outputs.c, compare_report.c); each writes DIR/NAME atomically. */
int cmp_write_table(const cmp_run *r, const char *name); /* NAME.csv: metrics, timings, temporal, counters */
int cmp_write_diffs(const cmp_run *r);
int cmp_write_panel(const cmp_run *r);
int cmp_write_report(const cmp_run *r);
/* DIR/name into buf. */
void cmp_path(const cmp_run *r, const char *name, char *buf, int size);
/* dir/LABEL[_fNNNN][SUFFIX].EXT, an item's file (_fNNNN in a sequence); dir NULL: the output folder. */
void cmp_view_path(const cmp_run *r, const char *dir, const char *label, int frame, const char *suffix, const char *ext,
                   char *path, int size);

#endif
