/* The state of one study run into its folder, shared by the layer's files
 * (study_dir.h): the study, the options, the shard plan and the cache. */
#ifndef FS_STUDY_DIR_STATE_H
#define FS_STUDY_DIR_STATE_H
#include "figure.h"
#include "output_file.h"
#include "ref_cache.h"
#include "study_dir.h"

typedef struct fs_study_dir {
    fs_study *s;
    const fs_study_dir_opts *o;
    char outdir[1024];                      /* o->dir, or a merge's staging folder */
    char radius_note[1024];                 /* fs_scene_adopt_frame's note, given before the work */
    int made_outdir;                        /* this run made outdir: a failure before any output removes it */
    int resumed;                            /* the work items --resume loaded */
    int *owner;                             /* with shards: each work item's shard, 1..N (fs_study_item_id) */
    struct fs_merge *merge;                 /* o->merge */
    double normal_scale_deg, depth_scale_r; /* heatmap scales, the same for every entry */
    fs_ref_cache cache;                     /* for the references */
} fs_study_dir;

/* 1 when this process renders item id: not a merge, and no shard or this shard's item. */
static inline int fs_study_dir_renders(const fs_study_dir *r, int id)
{
    return !r->merge && (!r->owner || r->owner[id] == r->o->shard_k);
}

/* The study's hooks for this run (study_io.c). */
fs_study_io fs_study_dir_io(fs_study_dir *r);

/* DIR/name into buf. */
void fs_study_dir_path(const fs_study_dir *r, const char *name, char *buf, int size);
/* dir/LABEL[_fNNNN][SUFFIX].EXT, an item's file (_fNNNN in a sequence); dir NULL: the output folder. */
void fs_study_dir_view_path(const fs_study_dir *r, const char *dir, const char *label, int frame, const char *suffix,
                            const char *ext, char *path, int size);
/* DIR/name listed (outputs_list.h) and opened through a temporary file;
 * fs_study_dir_close checks every write and the close, then renames it into place. */
int fs_study_dir_open(const fs_study_dir *r, const char *name, fs_output *cf);
int fs_study_dir_close(fs_output *cf);
/* An RGBA image as DIR/name (a PNG), listed. */
int fs_study_dir_write_rgba(const fs_study_dir *r, const char *name, const fs_rgba_image *im);

/* The writers; each writes DIR/NAME atomically. */
int fs_study_dir_write_table(const fs_study_dir *r, const char *name); /* NAME.csv (study_tables.h) */
int fs_study_dir_write_diffs(const fs_study_dir *r);                   /* heatmaps.c */
/* Entry e's normal-error heatmap against the first reference (heatmaps.c). */
int fs_study_dir_normal_heatmap(const fs_study_dir *r, const fs_study_entry *e, fs_rgba_image *out);
int fs_study_dir_write_panel(const fs_study_dir *r);  /* panel.c */
int fs_study_dir_write_report(const fs_study_dir *r); /* report.md, report_md.c */

#endif
