/* fluidsurf merge DIR_1 ... DIR_N -o DIR: the shards of a compare --shard K/N
 * study joined into what one compare process writes (compare_merge.h). */
#include "cli.h"
#include "compare_merge.h"
#include "compare_outdir.h"
#include "compare_shard.h"
#include "fs_error.h"
#include "options.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char epilogue[] =
    "Each DIR_K is the output folder of one 'fluidsurf compare ... --shard K/N'.\n"
    "merge refuses shards of different studies (shard count, commit, scene, command),\n"
    "names any missing or unfinished shard (no DONE marker), and writes nothing then.\n"
    "DIR receives what the compare command without --shard writes; only the timings,\n"
    "the reference-cache notes and the provenance (fluidsurf:shards, the shards'\n"
    "renderers) can differ. It runs in the shards' working folder, where their paths hold.\n";

/* path made absolute against the current folder (it need not exist). */
static int absolute(const char *path, char *out, int size)
{
    char cwd[4096];
    if (path[0] == '/') return snprintf(out, size, "%s", path) < size ? FS_OK : FS_ERR_INPUT;
    if (!getcwd(cwd, sizeof cwd)) return fs_fail(FS_ERR_RUNTIME, "cannot read the current folder: %s", strerror(errno));
    if (snprintf(out, size, "%s/%s", cwd, path) >= size) return fs_fail(FS_ERR_INPUT, "%s: path too long", path);
    return FS_OK;
}

/* DIR, when it exists, is a writable folder, none of the shards' and holds no
 * other run's outputs (with force: they are removed, compare_outdir.h). */
static int check_out(const cmp_merge *m, int force)
{
    struct stat st;
    char real[4096];
    if (stat(m->out, &st) == 0) {
        if (!S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: exists and is not a folder", m->out_arg);
        if (access(m->out, W_OK) != 0) return fs_fail(FS_ERR_INPUT, "%s: output folder is not writable", m->out_arg);
        for (int s = 0; realpath(m->out, real) && s < m->n; s++)
            if (!strcmp(real, m->shards[s].dir))
                return fs_fail(FS_ERR_INPUT, "%s: is shard %d's folder; merge into another", m->out_arg, s + 1);
        return cmp_outdir_claim(m->out_arg, "merge", 0, force);
    }
    return FS_OK; /* made once the staging folder beside it could be */
}

/* The first shard's command with --shard K/N and --resume left out and -o naming DIR. */
static char **merged_argv(const cmp_merge *m, int *argc)
{
    const cmp_shard_dir *d = &m->shards[0];
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
    const char *dirs[CMP_MAX_SHARDS + 1], *out = NULL;
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
                             {dirs, &ndirs, CMP_MAX_SHARDS, "more than 1024 shard folders"},
                             epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_note_quiet(quiet);
    if (!ndirs) return cli_usage("merge", "no shard folders given");
    if (!out) return cli_usage("merge", "no output folder given (-o DIR)");
    static cmp_merge m;
    rc = cmp_merge_read(&m, ndirs, dirs, out);
    if (!rc) rc = absolute(out, m.out, sizeof m.out);
    if (!rc) rc = check_out(&m, force);
    if (!rc) snprintf(m.staging, sizeof m.staging, "%s.merging-%ld", m.out, (long)getpid());
    if (!rc && mkdir(m.staging, 0755) != 0)
        rc = fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", out, strerror(errno));
    if (!rc && chdir(m.shards[0].cwd) != 0) {
        rc = fs_fail(FS_ERR_INPUT, "%s: the shards' working folder is gone: %s", m.shards[0].cwd, strerror(errno));
        rmdir(m.staging);
    }
    if (rc) {
        cmp_merge_free(&m);
        return cli_error(rc);
    }
    int cargc;
    char **cargv = merged_argv(&m, &cargc);
    rc = cargv ? cmp_compare_merged(cargc, cargv, &m) : cli_error(fs_fail(FS_ERR_RUNTIME, "out of memory"));
    free(cargv);
    cmp_merge_free(&m);
    return rc;
}
