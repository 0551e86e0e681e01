/* merge's work items (merge.h): each view and its record taken from the
 * shard that made it, its files linked into the output; the staging folder
 * published or removed. */
#include "merge.h"
#include "outputs_list.h"
#include "resume.h"
#include "shard.h"
#include "fs_error.h"
#include "output_file.h"
#include "render_output.h"
#include "stage_counts.h"
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* src to dst by a hard link, else a copy through a temporary file. */
static int link_or_copy(const char *src, const char *dst)
{
    if (link(src, dst) == 0) return FS_OK;
    char tmp[1500], buf[1 << 16];
    int rc = fs_output_begin(dst, tmp, sizeof tmp);
    if (rc) return rc;
    int in = open(src, O_RDONLY), out = open(tmp, O_WRONLY | O_TRUNC), ok = in >= 0 && out >= 0;
    ssize_t n;
    while (ok && (n = read(in, buf, sizeof buf)) != 0) ok = n > 0 && write(out, buf, n) == n;
    if (in >= 0) close(in);
    if (out >= 0) ok &= close(out) == 0;
    rc = fs_output_end(dst, tmp, ok);
    return rc ? rc : ok ? FS_OK : fs_fail(FS_ERR_RUNTIME, "%s: cannot copy to %s", src, dst);
}

/* An item's files from its shard's folder into the output: the PNG, the
 * method's own appearance where there is one, the EXR; the view from the EXR. */
static int take_view(fs_study_dir *r, const char *dir, const char *label, int frame, fs_run_image *v)
{
    static const char *const files[][2] = {{"", "png"}, {"_own", "png"}, {"", "exr"}};
    for (int j = 0; j < 3; j++) {
        char src[1400], dst[1400];
        fs_study_dir_view_path(r, dir, label, frame, files[j][0], files[j][1], src, sizeof src);
        fs_study_dir_view_path(r, NULL, label, frame, files[j][0], files[j][1], dst, sizeof dst);
        if (j == 1 && access(src, F_OK) != 0) continue;
        int rc = fs_outputs_record(dst);
        if (!rc) rc = link_or_copy(src, dst);
        if (rc) return rc;
    }
    char exr[1400];
    float radius;
    fs_study_dir_view_path(r, dir, label, frame, "", "exr", exr, sizeof exr);
    memset(v, 0, sizeof *v);
    return fs_read_render(exr, &v->g, &v->rgba, &radius);
}

/* The record of item id, split into fd (a copy in buf). */
static const fs_shard_dir *record(const fs_study_dir *r, int id, char *buf, int size, char **fd)
{
    snprintf(buf, size, "%s", r->merge->record[id]);
    fs_merge_split(buf, fd);
    return &r->merge->shards[r->merge->from[id]];
}

static int bad_record(const fs_shard_dir *d, char **fd, const char *what)
{
    return fs_fail(FS_ERR_INPUT, "%s/%s: %s, frame %s: %s", d->dir, FS_SHARD_MANIFEST, fd[2], fd[3], what);
}

/* Counts text ("-": none) into st when the run counts. */
static int take_counts(const fs_study_dir *r, const char *text, fs_stages *st)
{
    if (!r->s->counters) return FS_OK;
    return !strcmp(text, "-") ? FS_ERR_INPUT : fs_stage_counts_parse(text, st);
}

int fs_merge_ref(fs_study_dir *r, int k, int f, fs_run_image *v)
{
    char buf[8192], *fd[FS_MERGE_MAX_FIELDS];
    fs_study_ref *ref = &r->s->refs[k];
    const fs_shard_dir *d = record(r, fs_study_item_id(r->s, 1, k, f), buf, sizeof buf, fd);
    /* ref ID SPEC FRAME HIT ENTRY STAGES COUNTS */
    fs_study_made *made = &ref->made[f];
    made->hit = !strcmp(fd[4], "1");
    snprintf(made->entry, sizeof made->entry, "%s", strcmp(fd[5], "-") ? fd[5] : "");
    ref->hits += made->hit;
    if (f == 0 && fs_runs_parse(fd[6], &ref->stages, 1) != 1) return bad_record(d, fd, "unreadable timings");
    if (!ref->analytic && take_counts(r, fd[7], &made->counts)) return bad_record(d, fd, "unreadable work counts");
    return take_view(r, d->dir, ref->label, fs_study_frame(r->s, f), v);
}

int fs_merge_entry(fs_study_dir *r, int i, int f, fs_run_image *v)
{
    char buf[8192], *fd[FS_MERGE_MAX_FIELDS], *end;
    fs_study_entry *e = &r->s->entries[i];
    const fs_shard_dir *d = record(r, fs_study_item_id(r->s, 0, i, f), buf, sizeof buf, fd);
    /* entry ID LABEL FRAME FRAME_MS RUNS RENDERER COUNTS */
    e->frame_ms[f] = strtod(fd[4], &end);
    if (*end) return bad_record(d, fd, "unreadable frame time");
    if (f == 0 && (e->nruns = fs_runs_parse(fd[5], e->runs, r->s->repeat)) <= 0)
        return bad_record(d, fd, "unreadable timings");
    if (f == 0) snprintf(e->renderer, sizeof e->renderer, "%s", fd[6]);
    if (take_counts(r, fd[7], &e->counts[f])) return bad_record(d, fd, "unreadable work counts");
    return take_view(r, d->dir, e->label, fs_study_frame(r->s, f), v);
}

/* Each file of the staging folder renamed into out (ok), or removed. */
static int empty_staging(fs_merge *m, int ok)
{
    DIR *dir = opendir(m->staging);
    if (!dir) return ok ? fs_fail(FS_ERR_RUNTIME, "%s: cannot read: %s", m->staging, strerror(errno)) : FS_OK;
    int rc = FS_OK;
    for (struct dirent *de; (de = readdir(dir));) {
        if (!strcmp(de->d_name, ".") || !strcmp(de->d_name, "..")) continue;
        char from[1500], to[1500];
        snprintf(from, sizeof from, "%s/%s", m->staging, de->d_name);
        snprintf(to, sizeof to, "%s/%s", m->out, de->d_name);
        if (!ok) unlink(from);
        else if (!rc && rename(from, to) != 0)
            rc = fs_fail(FS_ERR_RUNTIME, "%s: cannot move into %s: %s", from, m->out, strerror(errno));
    }
    closedir(dir);
    return rc;
}

int fs_merge_publish(fs_merge *m, int ok)
{
    if (ok && mkdir(m->out, 0755) != 0 && errno != EEXIST)
        return fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", m->out_arg, strerror(errno));
    int rc = empty_staging(m, ok);
    if (rc) empty_staging(m, 0);
    rmdir(m->staging);
    return rc;
}
