/* The study layer (docs/DESIGN.md, "The study layer"): one comparison engine
 * under `compare`, `merge`, the C API, Python and the benchmarks.
 *
 *   plan      method variants x references x frames -> work items (study_plan.c)
 *   execute   every item through fs_run, frame by frame (study_exec.c): one
 *             upload, a warm-up, `repeat` timed renders, their median (the
 *             timing protocol, study_timing.c), shading, metrics in the scene
 *             (solids masked), temporal measures (study_temporal.c)
 *   results   the table in fs_study: metrics, timings, counters, temporal,
 *             with the provenance
 *
 * Frames stream: the executor holds one frame's particles and grid, each
 * view's current and previous G-buffer and the first frame's (panel,
 * heatmaps), so memory does not grow with the sequence.
 *
 * Where items come from and go to is the caller's (fs_study_io): the
 * reference cache, --resume, --shard and merge are hooks, not modes. The
 * layer prints nothing and never exits: errors are codes with one message. */
#ifndef FS_STUDY_H
#define FS_STUDY_H
#include "gbuffer_cache.h"
#include "gl_context.h"
#include "metrics.h"
#include "provenance.h"
#include "run.h"
#include "scene.h"
#include "sweep.h"
#include "timing.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_STUDY_MAX_ENTRIES 64
#define FS_STUDY_MAX_REFS 4
#define FS_STUDY_MAX_RUNS 64

/* How a reference view of one frame was made: from a cache (hit) or rendered
 * (and stored in entry), with its work counts when counting. */
typedef struct fs_study_made {
    int hit;
    char entry[FS_GCACHE_PATH]; /* the cache entry; "" without a cache */
    fs_stages counts;
} fs_study_made;

/* A reference: "reference", "reference:p=v,..." (the reference method with
 * those parameters) or "analytic" (the ideal shape of a synthetic scene). */
typedef struct fs_study_ref {
    char spec[160];
    char label[160]; /* file-safe */
    int analytic;
    fs_variant v;        /* the reference method's parameters */
    fs_run_image first;  /* the first frame's view (panel, heatmaps) */
    fs_stages stages;    /* the first frame's (timings.csv) */
    fs_study_made *made; /* nframes */
    int hits;            /* frames from the cache */
} fs_study_ref;

/* A method variant or an imported EXR: its plan and its results. */
typedef struct fs_study_entry {
    fs_variant v;    /* v.m NULL for an import */
    char name[64];   /* method name, or the import's NAME */
    char label[200]; /* file-safe, [A-Za-z0-9_-] (fs_label_value) */
    char variant[200];
    int imported;
    const char *file;    /* an import's EXR */
    fs_run_image first;  /* the first frame's view, kept for the panel and heatmaps */
    fs_metrics *metrics; /* [nrefs][nframes] */
    double *frame_ms;    /* nframes; NAN for imports */
    fs_stages *runs;     /* the first frame's timed runs, nruns */
    int nruns;
    char renderer[256];
    double temporal_deg;                           /* mean normal change between consecutive frames */
    double temporal_err_deg, temporal_err_depth_r; /* that change against the first reference's */
    fs_stages *counts;                             /* with counters: nframes, the counting render's stages */
} fs_study_entry;

typedef struct fs_study {
    fs_scene scene;
    int nentries, nrefs, nframes, first_frame, frame_step, sequence;
    int repeat;                    /* timed renders after one warm-up (default 3) */
    int counters;                  /* a counting render per variant and frame */
    int measure;                   /* metrics and temporal against the references (0: a shard, which has not all) */
    char pcols[FS_MAX_SWEEPS][64]; /* metrics.csv's parameter columns: each swept parameter's name once */
    int npcols;
    const fs_method *swept[FS_MAX_SWEEPS]; /* sweep k's method, whose rows fill column swept_col[k] */
    int swept_col[FS_MAX_SWEEPS], nswept;
    fs_study_entry entries[FS_STUDY_MAX_ENTRIES];
    fs_study_ref refs[FS_STUDY_MAX_REFS];
    double ref_temporal_deg; /* the first reference's own mean normal change */
    fs_provenance prov;
    fs_particles frame0;       /* the first frame, loaded by fs_study_load_first */
    const fs_particles *given; /* the caller's frames in place of the scene's source (borrowed), ngiven */
    int ngiven;
} fs_study;

/* Work items, one view of one frame: reference k's, then entry i's (imports
 * are no work items), nframes ids each. */
static inline int fs_study_item_id(const fs_study *s, int is_ref, int index, int f)
{
    return ((is_ref ? 0 : s->nrefs) + index) * s->nframes + f;
}
/* The number of the f-th frame the study renders (0 <= f < nframes). */
static inline int fs_study_frame(const fs_study *s, int f) { return s->first_frame + f * s->frame_step; }
static inline int fs_study_item_count(const fs_study *s) { return (s->nrefs + s->nentries) * s->nframes; }

/* --- the plan (study_plan.c) --- */

/* An empty study of scene sc (copied): repeat 3, measuring. */
void fs_study_init(fs_study *s, const fs_scene *sc);
/* Every variant of m under the sweeps (fs_sweep_variants). */
int fs_study_add_method(fs_study *s, const fs_method *m, const fs_sweep *sweeps, int nsweeps);
/* "reference" | "reference:p=v,q=w" | "analytic". */
int fs_study_add_reference(fs_study *s, const char *spec);
/* "NAME=FILE.exr": a G-buffer rendered elsewhere, at the study's size. */
int fs_study_add_import(fs_study *s, const char *spec);
/* metrics.csv's parameter columns: each swept parameter's name once, in order. */
void fs_study_param_columns(fs_study *s, const fs_sweep *sweeps, int nsweeps);
/* Two views whose files would collide, or a label like a summary file's. */
int fs_study_check_labels(const fs_study *s);
/* The scene's frames, or the ngiven frames set before (no cap: frames
 * stream); imports need one frame. */
int fs_study_set_frames(fs_study *s);
/* Adds the variants of each method of a comma list (when NULL every registered
 * one but the reference, which is a method of the study only when named) and
 * checks that each sweep is of one of them. */
int fs_study_add_methods(fs_study *s, const char *methods, const fs_sweep *sweeps, int nsweeps);
/* Loads the first frame and adopts its radius and camera for the whole study
 * (fs_scene_adopt_frame; note gets its message, "" when none). */
int fs_study_load_first(fs_study *s, float radius, char *note, int size);
/* The result arrays, once the plan is complete. */
int fs_study_alloc(fs_study *s);
void fs_study_free(fs_study *s);

/* --- the executor (study_exec.c) --- */

/* Where a work item comes from. */
typedef enum {
    FS_ITEM_RENDER = 0, /* rendered here (an io->load may still supply it: --resume) */
    FS_ITEM_LOAD,       /* loaded through io->load (merge) */
    FS_ITEM_SKIP        /* another process's (--shard) */
} fs_item_where;

/* The caller's places items come from and go to; every hook may be NULL. */
typedef struct fs_study_io {
    void *user;
    fs_item_where (*where)(void *user, const fs_study *s, int item);
    /* Reference k's view of frame f in place of the plain render (the cache);
     * fills v, st and made. */
    int (*ref_view)(void *user, fs_study *s, int k, int f, fs_run *run, const fs_particles *p, const fs_grid *g,
                    fs_run_image *v, fs_stages *st, fs_study_made *made);
    /* An item loaded instead of rendered (entry: also its frame time and runs):
     * *got = 1 when loaded. prov: the item's provenance (NULL without a run). */
    int (*load)(void *user, fs_study *s, int is_ref, int index, int f, const fs_provenance *prov, fs_run_image *v,
                int *got);
    /* A finished view rendered here (its files); prov is the item's. */
    int (*store)(void *user, fs_study *s, int is_ref, int index, int f, const fs_run_image *v, fs_provenance *prov);
    /* One item done (a progress line). */
    void (*done)(void *user, const fs_study *s, const char *label, int f);
    /* A note for the user (the layer prints nothing itself). */
    void (*note)(void *user, const char *text);
} fs_study_io;

/* Runs every item, frame by frame: references first on each frame, then each
 * variant (metrics against every reference's view of that frame), imports
 * against the first frame. ctx: the GL context for GL methods (NULL when none
 * needs one). */
int fs_study_execute(fs_study *s, const fs_study_io *io, const fs_gl_context *ctx);
/* Where item (is_ref, index, frame index f) comes from: io's answer (io NULL:
 * rendered here); an import is no work item (skipped). */
fs_item_where fs_study_item_where(const fs_study *s, const fs_study_io *io, int is_ref, int index, int f);
/* 1 when some variant the study renders here needs GL. */
int fs_study_needs_gl(const fs_study *s, const fs_study_io *io);
/* The work items this process handles (renders or loads). */
long fs_study_items_here(const fs_study *s, const fs_study_io *io);

/* --- the timing protocol (study_timing.c), written once --- */

/* On the run's current frame: a warm-up render, then `repeat` timed renders
 * into im (each one's stages into runs[] when runs is not NULL); returns their
 * median total in *median_ms. */
int fs_study_time_renders(fs_run *run, const fs_camera *cam, fs_run_image *im, int repeat, fs_stages *runs,
                          double *median_ms);
/* Upload, render and shade once: a reference's view. */
int fs_study_render_once(fs_run *run, const fs_scene *s, const fs_particles *p, const fs_grid *g, fs_run_image *im,
                         fs_stages *st);

#ifdef __cplusplus
}
#endif
#endif
