/* `fluidsurf compare`: the state shared by the run (cmd_compare.c) and the
 * writers of its outputs (compare_outputs.c). */
#ifndef FS_COMPARE_H
#define FS_COMPARE_H
#include "gbuffer.h"
#include "metrics.h"
#include "provenance.h"
#include "ref_cache.h"
#include "run.h"
#include "scene.h"
#include "sweep.h"
#include "timing.h"
#include <stdio.h>

#define CMP_MAX_ENTRIES 64
#define CMP_MAX_REFS 4
#define CMP_MAX_FRAMES 256
#define CMP_MAX_RUNS 64

/* A view of one frame: its G-buffer and shaded image. */
typedef fs_run_image cmp_view;

/* A reference: "reference", "reference:p=v,..." (the reference method with
 * those parameters) or "analytic" (the ideal shape of a synthetic scene). */
typedef struct cmp_ref {
    char spec[160];
    char label[160];     /* file-safe */
    int analytic;
    fs_variant v;        /* the reference method's parameters */
    cmp_view *frames;    /* nframes */
    fs_stages stages;    /* the first frame's (timings.csv) */
    cli_cache_view *made; /* nframes: loaded from the cache or rendered, and the entry */
    int hits;            /* frames loaded from the cache */
} cmp_ref;

/* A method variant or an imported EXR. */
typedef struct cmp_entry {
    fs_variant v;        /* v.m NULL for an import */
    char name[64];       /* method name, or the import's NAME */
    char label[200];     /* file-safe, [A-Za-z0-9_-] (fs_label_value) */
    char variant[200];
    int imported;
    const char *file;    /* an import's EXR (argv) */
    cmp_view first;      /* the first frame's view, kept for the panel and heatmaps */
    fs_metrics *metrics; /* [nrefs][nframes] */
    double *frame_ms;    /* nframes; NAN for imports */
    fs_stages *runs;     /* the first frame's timed runs, nruns */
    int nruns;
    char renderer[256];
    double temporal_deg; /* mean normal change between consecutive frames */
    double temporal_err_deg, temporal_err_depth_r; /* that change against the first reference's (compare_temporal.h) */
    fs_stages *counts;   /* with --counters: nframes, the counting render's stages */
} cmp_entry;

struct cmp_merge; /* compare_merge.h */

typedef struct cmp_run {
    fs_scene scene;
    char radius_note[1024]; /* fs_scene_adopt_frame's note, printed after success */
    char outdir[1024];
    char command[4096];
    int nentries, nrefs, nframes, first_frame, repeat, quiet, sequence;
    int made_outdir; /* this run made outdir: a failure before any output removes it */
    int counters;        /* --counters: a counting render per variant and frame */
    int resume, resumed; /* --resume; the work items it loaded */
    int force;           /* --force: an earlier run's files are removed first (compare_outdir.h) */
    char pcols[FS_MAX_SWEEPS][64]; /* metrics.csv's parameter columns: each swept parameter's name once */
    int npcols;
    int shard_k, shard_n; /* --shard K/N; 0/0 renders every work item */
    int *owner;          /* with --shard: each work item's shard, 1..N (cmp_item_id) */
    struct cmp_merge *merge; /* fluidsurf merge: every item comes from a shard's folder */
    int argc;            /* the command line, for a shard's manifest */
    char **argv;
    cmp_entry entries[CMP_MAX_ENTRIES];
    cmp_ref refs[CMP_MAX_REFS];
    double normal_scale_deg, depth_scale_r; /* heatmap scales, the same for every entry */
    double ref_temporal_deg;
    fs_provenance prov;
    cli_cache cache;     /* for the references */
} cmp_run;

/* The work items, one view of one frame: reference k's, then entry i's
 * (imports are no work items), nframes ids each. */
static inline int cmp_item_id(const cmp_run *r, int is_ref, int index, int f)
{
    return ((is_ref ? 0 : r->nrefs) + index) * r->nframes + f;
}
static inline int cmp_item_count(const cmp_run *r) { return (r->nrefs + r->nentries) * r->nframes; }
/* 1 when this process renders item id: not a merge, and no shard or this shard's item. */
static inline int cmp_renders(const cmp_run *r, int id)
{
    return !r->merge && (!r->owner || r->owner[id] == r->shard_k);
}

/* DIR/name opened through a temporary file; cmp_close checks every write and
 * the close, then renames it into place (or removes it). */
typedef struct cmp_file { char final[1400], tmp[1500]; FILE *f; } cmp_file;
int cmp_open(const cmp_run *r, const char *name, cmp_file *cf);
int cmp_close(cmp_file *cf);

/* Writers (compare_outputs.c); each writes DIR/NAME atomically. */
int cmp_write_metrics(const cmp_run *r);
int cmp_write_timings(const cmp_run *r);
int cmp_write_temporal(const cmp_run *r);
int cmp_write_diffs(const cmp_run *r);
int cmp_write_panel(const cmp_run *r);
int cmp_write_report(const cmp_run *r);
int cmp_write_counters(const cmp_run *r);
/* DIR/name into buf. */
void cmp_path(const cmp_run *r, const char *name, char *buf, int size);
/* dir/LABEL[_fNNNN][SUFFIX].EXT, an item's file (_fNNNN in a sequence); dir NULL: the output folder. */
void cmp_view_path(const cmp_run *r, const char *dir, const char *label, int frame, const char *suffix,
                   const char *ext, char *path, int size);

#endif
