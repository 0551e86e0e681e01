/* compare --shard K/N: the split of the work items and the shard's manifest (shard.h). */
#include "shard.h"
#include "resume.h"
#include "fs_error.h"
#include "particle_io.h"
#include "stage_counts.h"
#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int fs_shard_parse(const char *text, int *k, int *n)
{
    const char *slash = strchr(text, '/');
    int ok = slash && isdigit((unsigned char)text[0]) && isdigit((unsigned char)slash[1]);
    char *end;
    long a = ok ? strtol(text, &end, 10) : 0;
    ok = ok && end == slash;
    long b = ok ? strtol(slash + 1, &end, 10) : 0;
    ok = ok && !*end;
    if (!ok) return fs_fail(FS_ERR_INPUT, "--shard %s: expected K/N, two whole numbers", text);
    if (b < 1 || b > FS_MAX_SHARDS) return fs_fail(FS_ERR_INPUT, "--shard %s: N must be 1 to %d", text, FS_MAX_SHARDS);
    if (a < 1 || a > b) return fs_fail(FS_ERR_INPUT, "--shard %s: K must be 1 to N = %ld", text, b);
    *k = (int)a, *n = (int)b;
    return FS_OK;
}

/* One view's estimated cost relative to spheres: the method's declared cost
 * (fs_method.cost); the analytic reference (m NULL), an exact shape, half a
 * spheres view. Only the balance of the shards depends on it. */
static int view_cost(const fs_method *m, double *cost)
{
    *cost = m ? m->cost : 0.5;
    if (!(*cost > 0))
        return fs_fail(FS_ERR_RUNTIME, "method '%s' declares no cost (fs_method.cost): --shard cannot split it",
                       m->name);
    return FS_OK;
}

/* A frame's particle count, estimated by its file's size (the same format and
 * attributes every frame); 1 for a synthetic scene, a single file or a frame
 * that is not there (loading it will say so). */
static double frame_particles(const fs_study_dir *r, int f)
{
    char path[FS_PATH_MAX];
    struct stat st;
    if (!r->s->sequence || r->s->scene.synth.shape) return 1;
    if (fs_frame_path(path, sizeof path, r->s->scene.source, fs_study_frame(r->s, f)) || stat(path, &st)) return 1;
    return st.st_size > 0 ? (double)st.st_size : 1;
}

typedef struct {
    int id;
    double cost;
} item_cost;

static int by_cost(const void *a, const void *b)
{
    const item_cost *x = a, *y = b;
    if (x->cost != y->cost) return x->cost > y->cost ? -1 : 1;
    return x->id - y->id;
}

/* The cost of every work item into c, their number into *n; imports get none
 * (they are no work items). */
static int item_costs(const fs_study_dir *r, item_cost *c, int *n)
{
    double pixels = (double)r->s->scene.camera.width * r->s->scene.camera.height, w;
    int rc = FS_OK;
    *n = 0;
    for (int f = 0; f < r->s->nframes && !rc; f++) {
        double base = pixels * frame_particles(r, f);
        for (int k = 0; k < r->s->nrefs && !rc; k++)
            if (!(rc = view_cost(r->s->refs[k].analytic ? NULL : r->s->refs[k].v.m, &w)))
                c[(*n)++] = (item_cost){fs_study_item_id(r->s, 1, k, f), base * w};
        for (int i = 0; i < r->s->nentries && !rc; i++)
            if (!r->s->entries[i].imported && !(rc = view_cost(r->s->entries[i].v.m, &w)))
                c[(*n)++] = (item_cost){fs_study_item_id(r->s, 0, i, f), base * w};
    }
    return rc;
}

int fs_shard_plan(fs_study_dir *r)
{
    int total = fs_study_item_count(r->s);
    item_cost *c = malloc((size_t)total * sizeof *c);
    double *load = calloc(r->o->shard_n, sizeof *load);
    r->owner = calloc(total, sizeof *r->owner);
    if (!c || !load || !r->owner) {
        free(c), free(load);
        return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    int n, rc = item_costs(r, c, &n);
    if (rc) {
        free(c), free(load);
        return rc;
    }
    qsort(c, n, sizeof *c, by_cost);
    for (int j = 0; j < n; j++) {
        int best = 0;
        for (int s = 1; s < r->o->shard_n; s++)
            if (load[s] < load[best]) best = s;
        load[best] += c[j].cost;
        r->owner[c[j].id] = best + 1;
    }
    free(c), free(load);
    return FS_OK;
}

/* The header records: format, shard, commit, scene, working folder, command, provenance. */
static void write_header(const fs_study_dir *r, FILE *f)
{
    char cwd[4096];
    if (!getcwd(cwd, sizeof cwd)) snprintf(cwd, sizeof cwd, ".");
    fprintf(f, "fluidsurf-shard\t1\nshard\t%d\t%d\ncommit\t%s\nscene_hash\t%016llx\ncwd\t%s\n", r->o->shard_k,
            r->o->shard_n, fs_commit, r->s->scene.hash, cwd);
    for (int i = 0; i < r->o->argc; i++) fprintf(f, "arg\t%s\n", r->o->argv[i]);
    for (int i = 0; i < r->s->prov.n; i++) fprintf(f, "prov\t%s\t%s\n", r->s->prov.name[i], r->s->prov.value[i]);
}

static const char *or_dash(const char *s) { return s && s[0] ? s : "-"; }

/* The work counts of st as text, "-" without --counters. */
static const char *counts_text(const fs_study_dir *r, const fs_stages *st, char *buf, int size)
{
    if (!r->s->counters || fs_stage_counts_format(st, buf, size)) return "-";
    return buf;
}

static void write_ref_record(const fs_study_dir *r, FILE *f, int k, int fr)
{
    const fs_study_ref *ref = &r->s->refs[k];
    static char counts[FS_STAGE_COUNTS_MAX];
    char stages[640] = "";
    if (fr == 0) fs_runs_format(&ref->stages, 1, stages, sizeof stages);
    fprintf(f, "ref\t%d\t%s\t%d\t%d\t%s\t%s\t%s\n", fs_study_item_id(r->s, 1, k, fr), ref->spec,
            fs_study_frame(r->s, fr), ref->made[fr].hit, or_dash(ref->made[fr].entry), or_dash(stages),
            ref->analytic ? "-" : counts_text(r, &ref->made[fr].counts, counts, sizeof counts));
}

static void write_entry_record(const fs_study_dir *r, FILE *f, int i, int fr)
{
    const fs_study_entry *e = &r->s->entries[i];
    static char counts[FS_STAGE_COUNTS_MAX];
    char runs[640] = "";
    if (fr == 0) fs_runs_format(e->runs, e->nruns, runs, sizeof runs);
    fprintf(f, "entry\t%d\t%s\t%d\t%.17g\t%s\t%s\t%s\n", fs_study_item_id(r->s, 0, i, fr), e->label,
            fs_study_frame(r->s, fr), e->frame_ms[fr], or_dash(runs), or_dash(e->renderer),
            r->s->counters ? counts_text(r, &e->counts[fr], counts, sizeof counts) : "-");
}

static int write_manifest(const fs_study_dir *r, int with_items)
{
    fs_output cf;
    int rc = fs_study_dir_open(r, FS_SHARD_MANIFEST, &cf);
    if (rc) return rc;
    write_header(r, cf.f);
    for (int fr = 0; with_items && fr < r->s->nframes; fr++) {
        for (int k = 0; k < r->s->nrefs; k++)
            if (fs_study_dir_renders(r, fs_study_item_id(r->s, 1, k, fr))) write_ref_record(r, cf.f, k, fr);
        for (int i = 0; i < r->s->nentries; i++)
            if (!r->s->entries[i].imported && fs_study_dir_renders(r, fs_study_item_id(r->s, 0, i, fr)))
                write_entry_record(r, cf.f, i, fr);
    }
    if (with_items) fputs("end\n", cf.f);
    return fs_study_dir_close(&cf);
}

int fs_shard_start(const fs_study_dir *r)
{
    char done[1400];
    fs_study_dir_path(r, FS_SHARD_DONE, done, sizeof done);
    if (unlink(done) != 0 && errno != ENOENT)
        return fs_fail(FS_ERR_INPUT, "%s: cannot remove: %s", done, strerror(errno));
    for (int i = 0; i < r->o->argc; i++)
        if (strpbrk(r->o->argv[i], "\t\n"))
            return fs_fail(FS_ERR_INPUT,
                           "--shard: argument %d holds a tab or newline, which the manifest cannot record", i);
    return FS_OK;
}

int fs_shard_write(const fs_study_dir *r, int finished)
{
    int rc = write_manifest(r, finished);
    if (rc || !finished) return rc;
    fs_output cf;
    if ((rc = fs_study_dir_open(r, FS_SHARD_DONE, &cf))) return rc;
    fprintf(cf.f, "shard %d/%d finished\n", r->o->shard_k, r->o->shard_n);
    return fs_study_dir_close(&cf);
}
