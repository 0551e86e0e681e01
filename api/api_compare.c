/* fluidsurf_compare: a study through the same engine as `fluidsurf compare`
 * (common/study), its tables returned as the CSV text compare writes;
 * fluidsurf_compare_to_dir: the same study run into its folder by the layer
 * under compare (common/study_dir), which writes the same files. */
#include "api_internal.h"
#include "fs_error.h"
#include "gl_context.h"
#include "method_params.h"
#include "scene_provenance.h"
#include "study.h"
#include "study_dir.h"
#include "study_tables.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const table_names[] = {"metrics", "timings", "temporal", "counters"};
#define NTABLES 4

struct fluidsurf_study {
    fs_study s;
    fs_particles *given;  /* the caller's frames (structs copied, arrays borrowed) */
    char *table[NTABLES]; /* CSV text; NULL for a table the study has not */
};

/* Settings: "m.p=v" to the scene, "m.p=v1,v2" a sweep (as --set). */
static int apply_sets(fs_scene *sc, const char *const *sets, int nsets, fs_sweep *sweeps, int *nsweeps)
{
    if (nsets < 0 || (nsets > 0 && !sets)) return fs_fail(FS_ERR_INPUT, "sets: %d settings but no list", nsets);
    for (int i = 0; i < nsets; i++) {
        fs_param_setting split;
        if (!sets[i]) return fs_fail(FS_ERR_INPUT, "sets[%d] is NULL", i);
        int rc = fs_param_split(sets[i], &split);
        if (!rc) rc = strchr(split.value, ',') ? fs_sweep_add(sweeps, nsweeps, sets[i]) : fs_scene_add_set(sc, sets[i]);
        if (rc) return rc;
    }
    return FS_OK;
}

/* The plan: variants, references (default "reference"), frames, labels. */
static int plan(fluidsurf_study *st, const char *methods, const fs_sweep *sweeps, int nsweeps, const char *const *refs,
                int nrefs)
{
    fs_study *s = &st->s;
    if (nrefs < 0 || (nrefs > 0 && !refs)) return fs_fail(FS_ERR_INPUT, "references: %d specs but no list", nrefs);
    int rc = fs_study_add_methods(s, methods, sweeps, nsweeps);
    for (int i = 0; i < nrefs && !rc; i++)
        rc = refs[i] ? fs_study_add_reference(s, refs[i]) : fs_fail(FS_ERR_INPUT, "references[%d] is NULL", i);
    if (!rc && !nrefs) rc = fs_study_add_reference(s, "reference");
    if (!rc) fs_study_param_columns(s, sweeps, nsweeps);
    if (!rc) rc = fs_study_check_labels(s);
    for (int i = 0; s->counters && i < s->nentries && !rc; i++) rc = fs_run_check_counters(s->entries[i].v.m);
    return rc ? rc : fs_study_set_frames(s);
}

/* The caller's frames as the study's (validated when they are used). */
static int take_frames(fluidsurf_study *st, const fluidsurf_particles *const *frames, int nframes)
{
    if (!frames) return nframes ? fs_fail(FS_ERR_INPUT, "frames: %d frames but no list", nframes) : FS_OK;
    if (nframes < 1) return fs_fail(FS_ERR_INPUT, "frames: %d frames", nframes);
    if (!(st->given = calloc(nframes, sizeof *st->given))) return fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < nframes; i++) {
        if (!frames[i]) return fs_fail(FS_ERR_INPUT, "frames[%d] is NULL", i);
        st->given[i] = frames[i]->p;
    }
    st->s.given = st->given, st->s.ngiven = nframes;
    return FS_OK;
}

static int gl_acquire(void *user, const fs_gl_context **ctx)
{
    (void)user;
    int rc = fs_api_gl_acquire();
    *ctx = rc ? NULL : fs_api_gl();
    return rc;
}

/* Every item rendered (into dir when given), with the render lock and (for GL
 * methods) the shared context. */
static int execute(fluidsurf_study *st, float radius, const char *dir, int flags)
{
    fs_study_dir_opts o = {.dir = dir,
                           .command = "fluidsurf_compare_to_dir (the C API: no command line)",
                           .radius = radius,
                           .resume = (flags & FLUIDSURF_STUDY_RESUME) != 0,
                           .force = (flags & FLUIDSURF_STUDY_FORCE) != 0,
                           .quiet = 1,
                           .gl_acquire = gl_acquire};
    fs_api_lock(1);
    int rc = fs_study_dir_run(&st->s, &o);
    fs_api_lock(0);
    return rc;
}

static int write_tables(fluidsurf_study *st)
{
    for (int t = 0; t < NTABLES; t++) {
        if ((t == 2 && st->s.nframes < 2) || (t == 3 && !st->s.counters)) continue;
        size_t size;
        FILE *f = open_memstream(&st->table[t], &size);
        if (!f) return fs_fail(FS_ERR_RUNTIME, "out of memory");
        int rc = fs_study_write_table(&st->s, table_names[t], f);
        if (fclose(f) != 0 && !rc) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
        if (rc) return rc;
    }
    return FS_OK;
}

/* The study of fluidsurf_compare, into dir when it is given. */
static int compare(const fluidsurf_scene *s, const fluidsurf_particles *const *frames, int nframes, const char *methods,
                   const char *const *sets, int nsets, const char *const *references, int nreferences, int repeat,
                   int flags, const char *dir, fluidsurf_study **out)
{
    int rc;
    if ((rc = fs_api_check(out, "out"))) return rc;
    *out = NULL;
    if ((rc = fs_api_check(s, "scene"))) return rc;
    if (repeat < 0 || repeat > FS_STUDY_MAX_RUNS)
        return fs_fail(FS_ERR_INPUT, "repeat %d: expected 0 (3) to %d", repeat, FS_STUDY_MAX_RUNS);
    fs_api_init();
    fluidsurf_study *st = calloc(1, sizeof *st);
    fs_scene *sc = malloc(sizeof *sc);
    fs_sweep sweeps[FS_MAX_SWEEPS];
    int nsweeps = 0;
    if (!st || !sc) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc) *sc = s->s, rc = apply_sets(sc, sets, nsets, sweeps, &nsweeps);
    if (!rc) {
        fs_study_init(&st->s, sc);
        st->s.repeat = repeat ? repeat : 3;
        st->s.counters = (flags & FLUIDSURF_STUDY_COUNTERS) != 0;
        rc = take_frames(st, frames, nframes);
    }
    if (!rc) rc = plan(st, methods, sweeps, nsweeps, references, nreferences);
    if (!rc) rc = execute(st, s->radius_set ? (float)s->s.radius : 0, dir, flags);
    if (!rc) rc = write_tables(st);
    free(sc);
    if (rc) {
        fluidsurf_study_free(st);
        return rc;
    }
    *out = st;
    return FLUIDSURF_OK;
}

int fluidsurf_compare(const fluidsurf_scene *s, const fluidsurf_particles *const *frames, int nframes,
                      const char *methods, const char *const *sets, int nsets, const char *const *references,
                      int nreferences, int repeat, int flags, fluidsurf_study **out)
{
    return compare(s, frames, nframes, methods, sets, nsets, references, nreferences, repeat, flags, NULL, out);
}

int fluidsurf_compare_to_dir(const fluidsurf_scene *s, const fluidsurf_particles *const *frames, int nframes,
                             const char *methods, const char *const *sets, int nsets, const char *const *references,
                             int nreferences, int repeat, int flags, const char *dir, fluidsurf_study **out)
{
    int rc = fs_api_check(dir, "dir");
    return rc ? rc
              : compare(s, frames, nframes, methods, sets, nsets, references, nreferences, repeat, flags, dir, out);
}

const char *fluidsurf_study_table(const fluidsurf_study *st, const char *name)
{
    for (int t = 0; st && name && t < NTABLES; t++)
        if (!strcmp(name, table_names[t])) return st->table[t];
    return NULL;
}

void fluidsurf_study_free(fluidsurf_study *st)
{
    if (!st) return;
    fs_study_free(&st->s);
    for (int t = 0; t < NTABLES; t++) free(st->table[t]);
    free(st->given);
    free(st);
}
