/* fluidsurf merge: reading and checking the shards, loading their work items,
 * publishing the joined output (merge.h). */
#include "merge.h"
#include "outputs_list.h"
#include "resume.h"
#include "shard.h"
#include "fs_error.h"
#include "output_file.h"
#include "provenance.h"
#include "render_output.h"
#include "stage_counts.h"
#include <dirent.h>
#include <stddef.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Splits line at tabs in place into at most FS_MERGE_MAX_FIELDS fields; their count. */
int fs_merge_split(char *line, char **field)
{
    int n = 0;
    for (char *s = line; n < FS_MERGE_MAX_FIELDS;) {
        field[n++] = s;
        char *tab = strchr(s, '\t');
        if (!tab) break;
        *tab = 0;
        s = tab + 1;
    }
    return n;
}

static char *dup_or_null(const char *s) { return s ? strdup(s) : NULL; }

static int push(char ***v, int *n, const char *s)
{
    char **grown = realloc(*v, (*n + 1) * sizeof **v);
    if (!grown) return 0;
    *v = grown;
    return (grown[(*n)++] = dup_or_null(s)) != NULL;
}

/* One header record into d; the item lines are kept whole for fs_merge_map. */
static int header_record(fs_shard_dir *d, char **fd, int nf, const char *raw)
{
    const char *key = fd[0];
    if (!strcmp(key, "shard") && nf == 3) d->k = atoi(fd[1]), d->n = atoi(fd[2]);
    else if (!strcmp(key, "commit") && nf == 2) snprintf(d->commit, sizeof d->commit, "%s", fd[1]);
    else if (!strcmp(key, "scene_hash") && nf == 2) snprintf(d->scene_hash, sizeof d->scene_hash, "%s", fd[1]);
    else if (!strcmp(key, "cwd") && nf == 2) snprintf(d->cwd, sizeof d->cwd, "%s", fd[1]);
    else if (!strcmp(key, "arg") && nf == 2) return push(&d->argv, &d->argc, fd[1]);
    else if (!strcmp(key, "prov") && nf == 3) {
        if (!strcmp(fd[1], "fluidsurf:gl_renderer")) snprintf(d->renderer, sizeof d->renderer, "%s", fd[2]);
        if (!strcmp(fd[1], "fluidsurf:gl_version")) snprintf(d->gl_version, sizeof d->gl_version, "%s", fd[2]);
        if (!strcmp(fd[1], "fluidsurf:threads")) snprintf(d->threads, sizeof d->threads, "%s", fd[2]);
    } else if ((!strcmp(key, "ref") || !strcmp(key, "entry")) && nf == 8) return push(&d->lines, &d->nlines, raw);
    else return -1;
    return 1;
}

/* DIR/shard.txt into d: 1 when complete (its last record is "end"), 0 when
 * the shard did not finish, else an error. */
static int read_manifest(const char *dir, fs_shard_dir *d)
{
    char path[1200], *line = NULL, raw[8192];
    size_t cap = 0;
    snprintf(path, sizeof path, "%s/%s", dir, FS_SHARD_MANIFEST);
    FILE *f = fopen(path, "r");
    if (!f) return -fs_fail(FS_ERR_INPUT, "%s: not a shard folder of compare --shard (no %s)", dir, FS_SHARD_MANIFEST);
    int rc = FS_OK, complete = 0, nline = 0;
    ssize_t len;
    while (!rc && (len = getline(&line, &cap, f)) > 0) {
        if (line[len - 1] == '\n') line[--len] = 0;
        char *fd[FS_MERGE_MAX_FIELDS];
        snprintf(raw, sizeof raw, "%s", line);
        int nf = fs_merge_split(line, fd), ok = 1;
        if (complete) ok = -1; /* nothing follows "end" */
        else if (nline++ == 0) ok = !strcmp(fd[0], "fluidsurf-shard") && nf == 2 && !strcmp(fd[1], "1") ? 1 : -1;
        else if (!strcmp(fd[0], "end") && nf == 1) complete = 1;
        else ok = header_record(d, fd, nf, raw);
        if (ok < 0) rc = fs_fail(FS_ERR_INPUT, "%s: line %d is not a shard record", path, nline);
        else if (!ok) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    free(line);
    fclose(f);
    if (!rc && (d->k < 1 || d->n < 1 || d->k > d->n || !d->argc || !d->cwd[0]))
        rc = fs_fail(FS_ERR_INPUT, "%s: the manifest lacks its shard, command or folder", path);
    return rc ? -rc : complete;
}

/* The first shard's value of a header field against another's: a refusal naming both. */
static int same(const fs_shard_dir *a, const fs_shard_dir *b, const char *what, const char *va, const char *vb)
{
    if (!strcmp(va, vb)) return FS_OK;
    return fs_fail(FS_ERR_INPUT, "%s: not a shard of the same study as %s: %s %s, not %s", b->dir, a->dir, what, vb,
                   va);
}

/* How many of argv[i..] only steer the run (output, shard, resume, force, cache, quiet), not
 * what is computed: shards of one study may differ in them. */
static int run_control(char **argv, int argc, int i)
{
    static const char *with_value[] = {"--shard", "-o", "--cache"};
    static const char *flags[] = {"--resume", "--no-cache", "-q", "--force"};
    for (size_t k = 0; k < sizeof with_value / sizeof *with_value; k++)
        if (!strcmp(argv[i], with_value[k])) return i + 1 < argc ? 2 : 1;
    for (size_t k = 0; k < sizeof flags / sizeof *flags; k++)
        if (!strcmp(argv[i], flags[k])) return 1;
    return 0;
}

/* The next argument from *i on that defines the study, or NULL at the end. */
static const char *next_study_arg(char **argv, int argc, int *i)
{
    for (int skip; *i < argc && (skip = run_control(argv, argc, *i)); *i += skip) {}
    return *i < argc ? argv[(*i)++] : NULL;
}

static int same_command(const fs_shard_dir *a, const fs_shard_dir *b)
{
    int i = 0, j = 0;
    const char *x, *y;
    do {
        x = next_study_arg(a->argv, a->argc, &i);
        y = next_study_arg(b->argv, b->argc, &j);
    } while (x && y && !strcmp(x, y));
    if (!x && !y) return FS_OK;
    return fs_fail(FS_ERR_INPUT,
                   "%s: not a shard of the same study as %s: another compare command (%s where it has %s)", b->dir,
                   a->dir, y ? y : "(end)", x ? x : "(end)");
}

/* Belonging together: one shard count, commit, scene and command. */
static int check_peer(const fs_shard_dir *a, const fs_shard_dir *b)
{
    if (a->n != b->n)
        return fs_fail(FS_ERR_INPUT, "%s: not a shard of the same study as %s: shard %d/%d, not of %d", b->dir, a->dir,
                       b->k, b->n, a->n);
    int rc = same(a, b, "commit", a->commit, b->commit);
    if (!rc) rc = same(a, b, "scene hash", a->scene_hash, b->scene_hash);
    if (!rc)
        rc = strcmp(a->cwd, b->cwd)
            ? fs_fail(FS_ERR_INPUT, "%s: run in %s, but %s in %s", b->dir, b->cwd, a->dir, a->cwd)
            : FS_OK;
    return rc ? rc : same_command(a, b);
}

/* Each K once, none missing (all named), every shard finished. */
static int check_set(fs_merge *m, fs_shard_dir *got, const int *complete, int ndirs)
{
    int n = got[0].n;
    m->shards = calloc(n, sizeof *m->shards);
    if (!m->shards) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    m->n = n;
    for (int i = 0; i < ndirs; i++) {
        fs_shard_dir *slot = &m->shards[got[i].k - 1];
        if (slot->k) return fs_fail(FS_ERR_INPUT, "%s and %s are both shard %d/%d", slot->dir, got[i].dir, got[i].k, n);
        if (!complete[i])
            return fs_fail(FS_ERR_INPUT, "%s: shard %d/%d did not finish (no %s marker)", got[i].dir, got[i].k, n,
                           FS_SHARD_DONE);
        *slot = got[i];
        memset(&got[i], 0, sizeof got[i]); /* owned by the slot now */
    }
    char missing[1024] = "";
    int nmiss = 0, at = 0;
    for (int k = 0; k < n; k++)
        if (!m->shards[k].k && nmiss++ < 20)
            at += snprintf(missing + at, sizeof missing - at, "%s%d", at ? ", " : "", k + 1);
    if (nmiss)
        return fs_fail(FS_ERR_INPUT, "shard%s %s%s of %d %s missing: merge needs all %d shard folders",
                       nmiss > 1 ? "s" : "", missing, nmiss > 20 ? ", ..." : "", n, nmiss > 1 ? "are" : "is", n);
    if (strcmp(m->shards[0].commit, fs_commit))
        return fs_fail(FS_ERR_INPUT, "%s: made by fluidsurf %s; this merge is %s: merge with the same build",
                       m->shards[0].dir, m->shards[0].commit, fs_commit);
    return FS_OK;
}

static void free_dir(fs_shard_dir *d)
{
    for (int i = 0; i < d->argc; i++) free(d->argv[i]);
    for (int i = 0; i < d->nlines; i++) free(d->lines[i]);
    free(d->argv), free(d->lines);
}

/* A done shard's manifest is complete; one without DONE did not finish. */
static int read_dir(const char *dir, fs_shard_dir *d, int *complete)
{
    char done[1200];
    if (!realpath(dir, d->dir))
        return fs_fail(FS_ERR_INPUT, "%s: cannot open the shard folder: %s", dir, strerror(errno));
    int c = read_manifest(d->dir, d);
    if (c < 0) return -c;
    snprintf(done, sizeof done, "%s/%s", d->dir, FS_SHARD_DONE);
    *complete = c && access(done, F_OK) == 0;
    return FS_OK;
}

int fs_merge_read(fs_merge *m, int ndirs, const char *const *dirs, const char *out)
{
    memset(m, 0, sizeof *m);
    fs_shard_dir *got = calloc(ndirs, sizeof *got);
    int *complete = calloc(ndirs, sizeof *complete),
        rc = got && complete ? FS_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < ndirs && !rc; i++) rc = read_dir(dirs[i], &got[i], &complete[i]);
    for (int i = 1; i < ndirs && !rc; i++) rc = check_peer(&got[0], &got[i]);
    if (!rc) rc = check_set(m, got, complete, ndirs);
    for (int i = 0; got && i < ndirs; i++) free_dir(&got[i]);
    free(got), free(complete);
    snprintf(m->out_arg, sizeof m->out_arg, "%s", out);
    return rc;
}

/* The record's view: its kind, label and frame must be item id's in this plan. */
static int record_matches(const fs_study_dir *r, int id, char **fd)
{
    int per = r->s->nframes, is_ref = id / per < r->s->nrefs, index = is_ref ? id / per : id / per - r->s->nrefs,
        f = id % per;
    if (strcmp(fd[0], is_ref ? "ref" : "entry") || atoi(fd[3]) != fs_study_frame(r->s, f)) return 0;
    if (is_ref) return !strcmp(fd[2], r->s->refs[index].spec);
    return !r->s->entries[index].imported && !strcmp(fd[2], r->s->entries[index].label);
}

static int map_shard(fs_merge *m, const fs_study_dir *r, int s)
{
    const fs_shard_dir *d = &m->shards[s];
    int total = fs_study_item_count(r->s);
    for (int j = 0; j < d->nlines; j++) {
        char copy[8192], *fd[FS_MERGE_MAX_FIELDS];
        snprintf(copy, sizeof copy, "%s", d->lines[j]);
        fs_merge_split(copy, fd);
        char *end;
        long id = strtol(fd[1], &end, 10);
        if (*end || id < 0 || id >= total || !record_matches(r, (int)id, fd))
            return fs_fail(FS_ERR_INPUT, "%s: item %s (%s, frame %s) is not one of this study's", d->dir, fd[1], fd[2],
                           fd[3]);
        if (m->record[id])
            return fs_fail(FS_ERR_INPUT, "%s: item %s (%s, frame %s) was also made by %s", d->dir, fd[1], fd[2], fd[3],
                           m->shards[m->from[id]].dir);
        m->record[id] = d->lines[j];
        m->from[id] = s;
    }
    return FS_OK;
}

int fs_merge_map(fs_merge *m, const fs_study_dir *r)
{
    char hash[40];
    snprintf(hash, sizeof hash, "%016llx", r->s->scene.hash);
    if (strcmp(hash, m->shards[0].scene_hash))
        return fs_fail(FS_ERR_INPUT, "%s: the scene has changed since the shards ran (hash %s, shards %s)",
                       r->s->scene.path[0] ? r->s->scene.path : r->s->scene.source, hash, m->shards[0].scene_hash);
    int total = fs_study_item_count(r->s);
    m->record = calloc(total, sizeof *m->record);
    m->from = calloc(total, sizeof *m->from);
    if (!m->record || !m->from) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int s = 0; s < m->n; s++) {
        int rc = map_shard(m, r, s);
        if (rc) return rc;
    }
    for (int f = 0; f < r->s->nframes; f++)
        for (int i = -r->s->nrefs; i < r->s->nentries; i++) {
            int is_ref = i < 0, index = is_ref ? i + r->s->nrefs : i;
            if (!is_ref && r->s->entries[index].imported) continue;
            if (!m->record[fs_study_item_id(r->s, is_ref, index, f)])
                return fs_fail(FS_ERR_INPUT, "no shard made %s, frame %d: the shards were planned differently",
                               is_ref ? r->s->refs[index].spec : r->s->entries[index].label, fs_study_frame(r->s, f));
        }
    return FS_OK;
}

/* "a", or "a | b | ..." over the shards' distinct values of one field. */
static void joined(const fs_merge *m, size_t offset, char *buf, int size)
{
    int at = 0;
    buf[0] = 0;
    for (int s = 0; s < m->n && at < size; s++) {
        const char *v = (const char *)&m->shards[s] + offset;
        int seen = 0;
        for (int t = 0; t < s; t++) seen |= !strcmp(v, (const char *)&m->shards[t] + offset);
        if (!seen) at += snprintf(buf + at, size - at, "%s%s", at ? " | " : "", v);
    }
}

void fs_merge_provenance(const fs_merge *m, fs_provenance *p)
{
    char v[640];
    joined(m, offsetof(fs_shard_dir, renderer), v, sizeof v);
    fs_provenance_set(p, "gl_renderer", v);
    joined(m, offsetof(fs_shard_dir, gl_version), v, sizeof v);
    fs_provenance_set(p, "gl_version", v);
    joined(m, offsetof(fs_shard_dir, threads), v, sizeof v);
    fs_provenance_set(p, "threads", v);
    snprintf(v, sizeof v, "%d", m->n);
    fs_provenance_set(p, "shards", v);
}

void fs_merge_free(fs_merge *m)
{
    for (int s = 0; m->shards && s < m->n; s++) free_dir(&m->shards[s]);
    free(m->shards), free(m->record), free(m->from);
}

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
 * other run's outputs (with force: they are removed, outputs_list.h). */
static int check_out(const fs_merge *m, int force)
{
    struct stat st;
    char real[4096];
    if (stat(m->out, &st) == 0) {
        if (!S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: exists and is not a folder", m->out_arg);
        if (access(m->out, W_OK) != 0) return fs_fail(FS_ERR_INPUT, "%s: output folder is not writable", m->out_arg);
        for (int s = 0; realpath(m->out, real) && s < m->n; s++)
            if (!strcmp(real, m->shards[s].dir))
                return fs_fail(FS_ERR_INPUT, "%s: is shard %d's folder; merge into another", m->out_arg, s + 1);
        return fs_outputs_claim(m->out_arg, "merge", 0, force);
    }
    return FS_OK; /* made once the staging folder beside it could be */
}

int fs_merge_open(fs_merge *m, int force)
{
    int rc = absolute(m->out_arg, m->out, sizeof m->out);
    if (!rc) rc = check_out(m, force);
    if (!rc) snprintf(m->staging, sizeof m->staging, "%s.merging-%ld", m->out, (long)getpid());
    if (!rc && mkdir(m->staging, 0755) != 0)
        rc = fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", m->out_arg, strerror(errno));
    return rc;
}
