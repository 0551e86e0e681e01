/* fluidsurf merge (docs/DESIGN.md, "Sharded studies"): the shards of one
 * compare --shard K/N study joined into what one process writes. merge checks
 * the shards' manifests (shard.h), then runs the shards' compare
 * command with every work item loaded from the shard that made it instead of
 * rendered: metrics, temporal stability, heatmaps and the panel are computed
 * from the same G-buffers by the same code. Everything is written into a
 * staging folder beside the output and moved into it only when complete. */
#ifndef FS_MERGE_H
#define FS_MERGE_H
#include "study_dir_state.h"

typedef struct fs_shard_dir {
    char dir[1100]; /* absolute */
    int k, n;
    char commit[128], scene_hash[40], cwd[4096];
    char renderer[256], gl_version[256], threads[32];
    int argc;
    char **argv; /* the compare command line, without --shard K/N */
    int nlines;
    char **lines; /* the item records */
} fs_shard_dir;

typedef struct fs_merge {
    int n; /* shards, indexed K-1 once checked */
    fs_shard_dir *shards;
    char out[990];      /* the output folder, absolute */
    char out_arg[1100]; /* as given, for report.md's command line */
    char staging[1024]; /* out.merging-PID */
    char **record;      /* per work item: its record (into a shard's lines) */
    int *from;          /* per work item: its shard, 0-based */
} fs_merge;

/* Reads DIRS' manifests and checks that they are the N complete shards of one
 * study (one format, shard count, commit, scene, command; each K once; DONE).
 * Every refusal is one line naming the folder. out: the output folder. */
int fs_merge_read(fs_merge *m, int ndirs, const char *const *dirs, const char *out);
/* After fs_merge_read: the output folder (made absolute; when it exists, a
 * writable folder, none of the shards', holding no other run's outputs unless
 * force, outputs_list.h) and the staging folder beside it made. */
int fs_merge_open(fs_merge *m, int force);
/* Once the command is planned: the scene still hashes as the shards', and each
 * work item has exactly one record naming the same view. */
int fs_merge_map(fs_merge *m, const fs_study_dir *r);
/* The shards' renderers, GL versions and thread counts ("a | b" where they
 * differ) and their number, in place of this process's. */
void fs_merge_provenance(const fs_merge *m, fs_provenance *p);
/* Work item (reference k or entry i, frame index f) from its shard: the view,
 * its record's timings, cache note and counts; its files linked (or copied)
 * into the output. */
int fs_merge_ref(fs_study_dir *r, int k, int f, fs_run_image *v);
int fs_merge_entry(fs_study_dir *r, int i, int f, fs_run_image *v);
/* A manifest line's tab-separated fields into field (at most FS_MERGE_MAX_FIELDS); their count. */
#define FS_MERGE_MAX_FIELDS 9
int fs_merge_split(char *line, char **field);
/* ok: moves the staging folder's files into the output folder; else removes them. */
int fs_merge_publish(fs_merge *m, int ok);
void fs_merge_free(fs_merge *m);

#endif
