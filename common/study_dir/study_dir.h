/* The study folder layer (docs/DESIGN.md, "The study folder"): a planned study
 * (study.h) run into its output folder, whoever asks: `fluidsurf compare` and
 * `merge`, the C API's fluidsurf_compare_to_dir and Python's compare(out=DIR).
 *
 *   the folder      made or claimed (outputs_list.h), its files listed
 *   where items     rendered here, from the reference cache (ref_cache.h),
 *   come from       loaded (--resume, resume.h; merge, merge.h) or another
 *                   shard's (shard.h): the study's hooks (study_io.c)
 *   what is written each view's PNG and EXR, metrics.csv, timings.csv,
 *                   temporal.csv, counters.csv, the heatmaps, panel.png,
 *                   report.md and last report.html (report_html.h)
 *
 * The layer prints notes (fs_note, silenced in the library) and never exits:
 * errors are codes with one message. */
#ifndef FS_STUDY_DIR_H
#define FS_STUDY_DIR_H
#include "gl_context.h"
#include "study.h"

struct fs_merge; /* merge.h */

/* The longest output folder path: its files' names fit after it. */
#define FS_STUDY_DIR_MAX 724

/* How a study is run into its folder. Zero is a plain run: no folder (dir
 * NULL: every item rendered, nothing written), no cache, no shards. */
typedef struct fs_study_dir_opts {
    const char *dir;     /* the output folder, made if missing; NULL: none */
    const char *command; /* the command line report.md records */
    int argc;            /* the command's arguments, for a shard's manifest */
    char *const *argv;
    float radius;           /* > 0: r for the whole study (else the scene's, the file's, estimated) */
    int resume;             /* keep the items an earlier run of the same study finished (resume.h) */
    int force;              /* remove an earlier run's files first (outputs_list.h) */
    int quiet;              /* no note about a bad cache entry */
    int shard_k;            /* --shard K/N: render only shard K's items; 0: every item */
    int shard_n;            /* 0: no shards */
    struct fs_merge *merge; /* every item from these shards' folders (merge.h) */
    const char *cache_dir;  /* the reference cache's folder; NULL: the default one when use_cache */
    int use_cache;
    double normal_scale_deg, depth_scale_r; /* heatmap scales; 0: from the data */
    /* The GL context, when some variant rendered here needs one: made by the
     * caller (the command line its own, the library its shared one). */
    int (*gl_acquire)(void *user, const fs_gl_context **ctx);
    void (*gl_release)(void *user);
    void *gl_user;
} fs_study_dir_opts;

/* Runs the planned study s into o->dir: the folder claimed, the shards
 * planned (or the merge's items mapped), every work item rendered or loaded,
 * the results written; s holds the results after. On an error the folder
 * keeps no half-written file (a folder made here and left empty is removed). */
int fs_study_dir_run(fs_study *s, const fs_study_dir_opts *o);

#endif
