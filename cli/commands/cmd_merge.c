/* fluidsurf merge DIR_1 ... DIR_N -o DIR: the shards of a compare --shard K/N
 * study joined into what one compare process writes (merge.h). */
#include "cli.h"
#include "compare.h"
#include "fs_error.h"
#include "merge.h"
#include "options.h"
#include "shard.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char epilogue[] =
    "Each DIR_K is the output folder of one 'fluidsurf compare ... --shard K/N'.\n"
    "merge refuses shards of different studies (shard count, commit, scene, command),\n"
    "names any missing or unfinished shard (no DONE marker), and writes nothing then.\n"
    "DIR receives what the compare command without --shard writes; only the timings,\n"
    "the reference-cache notes and the provenance (fluidsurf:shards, the shards'\n"
    "renderers) can differ. It runs in the shards' working folder, where their paths hold.\n";

/* The first shard's command with --shard K/N and --resume left out and -o naming DIR. */
static char **merged_argv(const fs_merge *m, int *argc)
{
    const fs_shard_dir *d = &m->shards[0];
    char **v = calloc(d->argc + 1, sizeof *v);
    int n = 0;
    for (int i = 0; v && i < d->argc; i++) {
        if (!strcmp(d->argv[i], "--shard") && i + 1 < d->argc) {
            i++;
            continue;
        }
        if (!strcmp(d->argv[i], "--resume") || !strcmp(d->argv[i], "--force")) continue; /* the merge renders nothing */
        v[n++] = d->argv[i];
        if (!strcmp(d->argv[i], "-o") && i + 1 < d->argc) v[n++] = (char *)m->out_arg, i++;
    }
    *argc = n;
    return v;
}

int cmd_merge(int argc, char **argv)
{
    const char *dirs[FS_MAX_SHARDS + 1], *out = NULL;
    int ndirs = 0, quiet = 0, force = 0, rc;
    const cli_opt opts[] = {
        CLI_OPT_OUT(out, "DIR", "the merged output folder (made if missing)"),
        CLI_FLAG_OPT("--force", force,
                     "DIR holds another run's outputs: remove them first\n"
                     "(fluidsurf's own files only; without it merge refuses)"),
        CLI_OPT_QUIET(quiet),
        CLI_END,
    };
    const cli_command cmd = {"merge",
                             "DIR_1 ... DIR_N -o DIR",
                             opts,
                             {dirs, &ndirs, FS_MAX_SHARDS, "more than 1024 shard folders"},
                             epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_note_quiet(quiet);
    if (!ndirs) return cli_usage("merge", "no shard folders given");
    if (!out) return cli_usage("merge", "no output folder given (-o DIR)");
    static fs_merge m;
    rc = fs_merge_read(&m, ndirs, dirs, out);
    if (!rc) rc = fs_merge_open(&m, force);
    if (!rc && chdir(m.shards[0].cwd) != 0) {
        rc = fs_fail(FS_ERR_INPUT, "%s: the shards' working folder is gone: %s", m.shards[0].cwd, strerror(errno));
        rmdir(m.staging);
    }
    if (rc) {
        fs_merge_free(&m);
        return cli_error(rc);
    }
    int cargc;
    char **cargv = merged_argv(&m, &cargc);
    rc = cargv ? compare_merged(cargc, cargv, &m) : cli_error(fs_fail(FS_ERR_RUNTIME, "out of memory"));
    free(cargv);
    fs_merge_free(&m);
    return rc;
}
