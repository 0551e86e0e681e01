/* compare's output folder: the list of the files it wrote, and the refusal of a
 * folder that holds another run's outputs (outputs_list.h). */
#include "outputs_list.h"
#include "fs_error.h"
#include "image_io.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define HEADER "fluidsurf-outputs 1"

/* The names found in a folder: what refuses it, and what --force removes. */
typedef struct found {
    char **name;
    int n, cap;
} found;

static int add(found *f, const char *name)
{
    if (f->n == f->cap) {
        int cap = f->cap ? 2 * f->cap : 64;
        char **grown = realloc(f->name, cap * sizeof *grown);
        if (!grown) return fs_fail(FS_ERR_RUNTIME, "out of memory");
        f->name = grown, f->cap = cap;
    }
    return (f->name[f->n] = strdup(name)) ? (f->n++, FS_OK) : fs_fail(FS_ERR_RUNTIME, "out of memory");
}

static void free_found(found *f)
{
    for (int i = 0; i < f->n; i++) free(f->name[i]);
    free(f->name);
}

/* 1 when dir/name is a regular file (never a link: we write none). */
static int is_file(const char *dir, const char *name)
{
    char path[4200];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return lstat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* A plain name in the folder itself: no '/', not "." or "..". */
static int plain_name(const char *name)
{
    return *name && !strchr(name, '/') && strcmp(name, ".") && strcmp(name, "..");
}

/* The manifest's names that are still files: 1 when dir has a manifest, 0 when not. */
static int read_manifest(const char *dir, found *out, int *rc)
{
    char path[4200], *line = NULL;
    size_t cap = 0;
    ssize_t len;
    snprintf(path, sizeof path, "%s/%s", dir, FS_OUTPUTS_LIST);
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    int nline = 0, ours = 0;
    while (!*rc && (len = getline(&line, &cap, f)) > 0) {
        if (line[len - 1] != '\n') break; /* a line cut short by a kill: not a name */
        line[--len] = 0;
        if (nline++ == 0) {
            ours = !strcmp(line, HEADER);
            if (!ours) break;
            continue;
        }
        if (plain_name(line) && strcmp(line, FS_OUTPUTS_LIST) && is_file(dir, line)) *rc = add(out, line);
    }
    free(line);
    fclose(f);
    return ours;
}

/* The first line of dir/name starts with prefix (and holds need, when given). */
static int first_line_is(const char *dir, const char *name, const char *prefix, const char *need)
{
    char path[4200], line[4096] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    int ok = fgets(line, sizeof line, f) && !strncmp(line, prefix, strlen(prefix)) && (!need || strstr(line, need));
    fclose(f);
    return ok;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && !strcmp(s + n - k, suffix);
}

/* The images of an older run: each EXR with fluidsurf's provenance, and the PNGs
 * compare names after it (LABEL.png, LABEL_own.png, diff_LABEL.png; a sequence's
 * LABEL_fNNNN.exr has its heatmap as diff_LABEL.png). */
static int legacy_images(const char *dir, found *out)
{
    DIR *d = opendir(dir);
    if (!d) return FS_OK;
    int rc = FS_OK;
    for (struct dirent *de; !rc && (de = readdir(d));) {
        char path[4200], commit[128], stem[1024], name[1100];
        if (!ends_with(de->d_name, ".exr") || strlen(de->d_name) >= sizeof stem) continue;
        snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
        if (!is_file(dir, de->d_name) || fs_read_image_attr(path, "fluidsurf:commit", commit, sizeof commit) != 1)
            continue;
        snprintf(stem, sizeof stem, "%.*s", (int)(strlen(de->d_name) - 4), de->d_name);
        rc = add(out, de->d_name);
        const char *png[] = {"%s.png", "%s_own.png", "diff_%s.png"};
        for (int k = 0; k < 3 && !rc; k++) {
            snprintf(name, sizeof name, png[k], stem);
            if (is_file(dir, name)) rc = add(out, name);
        }
        size_t n = strlen(stem); /* LABEL_fNNNN */
        if (!rc && n > 6 && !strncmp(stem + n - 6, "_f", 2) && strspn(stem + n - 4, "0123456789") == 4) {
            snprintf(name, sizeof name, "diff_%.*s.png", (int)(n - 6), stem);
            if (is_file(dir, name)) rc = add(out, name); /* may repeat: removing twice is harmless */
        }
    }
    closedir(d);
    return rc;
}

/* An older fluidsurf's outputs, recognised by their fixed names and contents. */
static int read_legacy(const char *dir, found *out)
{
    static const char *const csvs[] = {"metrics.csv", "timings.csv", "temporal.csv", "counters.csv"};
    int rc = FS_OK, compare_run = 0;
    for (int i = 0; i < 4 && !rc; i++)
        if (first_line_is(dir, csvs[i], "# ", "commit=")) rc = add(out, csvs[i]), compare_run = 1;
    if (!rc && first_line_is(dir, "report.md", "# fluidsurf compare", NULL))
        rc = add(out, "report.md"), compare_run = 1;
    if (!rc && first_line_is(dir, "shard.txt", "fluidsurf-shard\t", NULL)) {
        rc = add(out, "shard.txt"), compare_run = 1;
        if (!rc && first_line_is(dir, "DONE", "shard ", "finished")) rc = add(out, "DONE");
    }
    if (!rc && compare_run && is_file(dir, "panel.png")) rc = add(out, "panel.png");
    if (!rc && compare_run) rc = legacy_images(dir, out);
    return rc;
}

static int remove_found(const char *dir, const found *f, int manifest)
{
    char path[4200];
    for (int i = 0; i < f->n; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, f->name[i]);
        if (unlink(path) != 0 && errno != ENOENT)
            return fs_fail(FS_ERR_RUNTIME, "%s: cannot remove: %s", path, strerror(errno));
    }
    snprintf(path, sizeof path, "%s/%s", dir, FS_OUTPUTS_LIST);
    if (manifest && unlink(path) != 0 && errno != ENOENT)
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot remove: %s", path, strerror(errno));
    return FS_OK;
}

int fs_outputs_claim(const char *dir, const char *what, int resume, int force)
{
    found f = {0};
    int rc = FS_OK, manifest = read_manifest(dir, &f, &rc);
    if (!rc && !manifest) rc = read_legacy(dir, &f);
    if (!rc && f.n && !resume) {
        if (!force)
            rc = fs_fail(FS_ERR_INPUT,
                         "%s: holds another run's outputs (%s%s): --force removes fluidsurf's files there "
                         "first, --resume keeps what matches",
                         dir, f.name[0], f.n > 1 ? " and more" : "");
        else if (!(rc = remove_found(dir, &f, manifest)))
            fs_note("%s: --force: removed %d file(s) of an earlier %s run", dir, f.n, what);
    }
    free_found(&f);
    return rc;
}

/* 1 when the EXR name is one of the views': LABEL.exr, or LABEL_fNNNN.exr in a sequence. */
static int exr_of_views(const char *name, const char *const *labels, int n)
{
    size_t len = strlen(name) - 4;
    for (int i = 0; i < n; i++) {
        size_t k = strlen(labels[i]);
        if (strncmp(name, labels[i], k)) continue;
        if (len == k) return 1;
        if (len == k + 6 && !strncmp(name + k, "_f", 2) && strspn(name + k + 2, "0123456789") >= 4) return 1;
    }
    return 0;
}

int fs_outputs_resume_check(const char *dir, const char *const *labels, int n)
{
    found f = {0};
    int rc = FS_OK, manifest = read_manifest(dir, &f, &rc);
    if (!rc && !manifest) rc = read_legacy(dir, &f);
    char other[512] = "";
    int nother = 0;
    for (int i = 0; i < f.n && !rc; i++) {
        if (!ends_with(f.name[i], ".exr") || exr_of_views(f.name[i], labels, n)) continue;
        size_t l = strlen(other);
        if (nother++ < 4) snprintf(other + l, sizeof other - l, "%s%s", l ? ", " : "", f.name[i]);
    }
    if (!rc && nother)
        rc = fs_fail(FS_ERR_INPUT,
                     "%s: --resume: the earlier run there has views this one does not make (%s%s): resume it with its "
                     "methods and settings, or --force to start afresh",
                     dir, other, nother > 4 ? ", ..." : "");
    free_found(&f);
    return rc;
}

int fs_outputs_record(const char *path)
{
    char list[4200];
    const char *slash = strrchr(path, '/'), *name = slash ? slash + 1 : path;
    if (slash) snprintf(list, sizeof list, "%.*s/%s", (int)(slash - path), path, FS_OUTPUTS_LIST);
    else snprintf(list, sizeof list, "%s", FS_OUTPUTS_LIST);
    int fresh = access(list, F_OK) != 0;
    FILE *f = fopen(list, "a");
    if (!f) return fs_fail(FS_ERR_RUNTIME, "%s: cannot write: %s", list, strerror(errno));
    if (fresh) fprintf(f, "%s\n", HEADER);
    fprintf(f, "%s\n", name);
    int ok = !ferror(f);
    ok &= fclose(f) == 0;
    return ok ? FS_OK : fs_fail(FS_ERR_RUNTIME, "%s: write failed", list);
}
