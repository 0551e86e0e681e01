/* `fluidsurf compare` and `merge`: the command line parsed (cmd_compare.c) and
 * planned into a study (compare_plan.c); the study folder layer
 * (common/study_dir) runs it into its folder. */
#ifndef FS_COMPARE_H
#define FS_COMPARE_H
#include "cli.h"
#include "study.h"

struct fs_merge;

/* compare's parsed command line. */
typedef struct compare_args {
    const char *input, *out, *methods, *cache_dir, *shard, *camera, *camera_from, *frames;
    const char *refspecs[FS_STUDY_MAX_REFS + 1], *imports[FS_STUDY_MAX_ENTRIES + 1], *sets[FS_MAX_SETS];
    int nrefspecs, nimports, nsets, w, h, repeat, counters;
    int no_cache, resume, force, quiet, require_gpu;
    float radius, nscale, dscale;
    cli_scene_opts field;
    fs_ctx_kind ctx_kind;
} compare_args;

/* The study's plan from the command line: the scene, the variants, the
 * references and imports, the frames; errors are printed. */
int compare_plan(fs_study *s, const compare_args *a);
/* The command line as a shell would take it back, for report.md. */
void compare_quote_command(char *buf, int size, int argc, char **argv);
/* compare's run with m's shards as the source of every work item (merge). */
int compare_merged(int argc, char **argv, struct fs_merge *m);

#endif
