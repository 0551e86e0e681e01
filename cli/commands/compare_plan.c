/* compare's plan from its command line (compare.h): the scene, the variants,
 * the references and imports, the frames. */
#include "cli.h"
#include "compare.h"
#include "fs_error.h"
#include "method_params.h"
#include <stdio.h>
#include <string.h>

/* The variants of every method of the comma list (all registered when NULL);
 * a name is checked here first for the command line's message. */
static int add_variants(fs_study *s, const char *methods, const fs_sweep *sweeps, int nsweeps)
{
    char mlist[1024];
    snprintf(mlist, sizeof mlist, "%s", methods ? methods : "");
    for (char *tok = strtok(mlist, ","); tok; tok = strtok(NULL, ","))
        if (!fs_method_find(tok)) return cli_unknown_method("compare", "--methods", tok);
    int rc = fs_study_add_methods(s, methods, sweeps, nsweeps);
    return rc ? cli_error(rc) : FS_OK;
}

/* The scene and the variants: plain settings go to the scene, comma lists become sweeps. */
static int plan_variants(fs_study *s, const compare_args *o)
{
    fs_scene sc;
    int rc = cli_scene_from_arg(&sc, o->input);
    if (rc) return cli_error(rc);
    cli_scene_opts_apply(&sc, &o->field);
    if ((rc = cli_scene_pattern("compare", &sc, o->input, o->frames))) return rc;
    if ((rc = cli_scene_camera("compare", &sc, o->camera, o->camera_from))) return rc;
    if (o->w) sc.camera.width = o->w;
    if (o->h) sc.camera.height = o->h;
    if ((long)sc.camera.width * sc.camera.height > 16384L * 16384L / 4)
        return cli_usage("compare", "%dx%d pixels is too large", sc.camera.width, sc.camera.height);
    if (o->radius > 0) sc.radius = o->radius;
    fs_sweep sweeps[FS_MAX_SWEEPS];
    int nsweeps = 0;
    for (int i = 0; i < o->nsets; i++) {
        fs_param_setting split;
        if ((rc = fs_param_split(o->sets[i], &split))) return cli_error(rc);
        rc = strchr(split.value, ',') ? fs_sweep_add(sweeps, &nsweeps, o->sets[i]) : fs_scene_add_set(&sc, o->sets[i]);
        if (rc) return cli_error(rc);
    }
    fs_study_init(s, &sc);
    s->repeat = o->repeat, s->counters = o->counters;
    if ((rc = add_variants(s, o->methods, sweeps, nsweeps))) return rc;
    fs_study_param_columns(s, sweeps, nsweeps);
    for (int i = 0; o->counters && i < s->nentries; i++)
        if ((rc = fs_run_check_counters(s->entries[i].v.m))) return cli_error(rc);
    double check[FS_MAX_PARAMS]; /* every plain --set must name a real method and parameter */
    if ((rc = fs_method_params_resolve(fs_method_at(0), &s->scene, check))) return cli_error(rc);
    return FS_OK;
}

/* Every --set is for a method that runs: a variant's, or the reference's when a
 * reference is rendered (not analytic). */
static int check_sets_run(const fs_study *s, const compare_args *o)
{
    const fs_method *run[FS_STUDY_MAX_ENTRIES + 1];
    int n = 0;
    for (int i = 0; i < s->nentries; i++) {
        int seen = !s->entries[i].v.m; /* an import runs nothing */
        for (int k = 0; k < n; k++) seen |= run[k] == s->entries[i].v.m;
        if (!seen) run[n++] = s->entries[i].v.m;
    }
    const fs_method *ref = fs_method_find("reference");
    int ref_runs = 0, listed = 0;
    for (int i = 0; i < s->nrefs; i++) ref_runs |= !s->refs[i].analytic;
    for (int k = 0; k < n; k++) listed |= run[k] == ref;
    if (ref_runs && !listed && ref) run[n++] = ref;
    return cli_sets_run(o->sets, o->nsets, run, n);
}

/* References and imports, the labels, the frames: all input is checked before the folder is made. */
static int plan_references(fs_study *s, const compare_args *o)
{
    int rc = FS_OK;
    for (int i = 0; i < o->nrefspecs && !rc; i++) rc = fs_study_add_reference(s, o->refspecs[i]);
    if (!rc && !o->nrefspecs) rc = fs_study_add_reference(s, "reference");
    if (!rc && o->nimports && s->scene.frame_first >= 0 && s->scene.frame_last > s->scene.frame_first)
        rc = fs_fail(FS_ERR_INPUT, "--import needs a single-frame scene");
    for (int i = 0; i < o->nimports && !rc; i++) rc = fs_study_add_import(s, o->imports[i]);
    if (!rc) rc = check_sets_run(s, o);
    if (!rc) rc = fs_study_check_labels(s);
    if (!rc) rc = fs_study_set_frames(s);
    return rc ? cli_error(rc) : FS_OK;
}

int compare_plan(fs_study *s, const compare_args *a)
{
    int rc = plan_variants(s, a);
    return rc ? rc : plan_references(s, a);
}

void compare_quote_command(char *buf, int size, int argc, char **argv)
{
    int n = snprintf(buf, size, "fluidsurf");
    for (int i = 0; i < argc && n < size; i++) {
        const char *a = argv[i];
        int plain = *a != 0;
        for (const char *c = a; *c; c++)
            if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=,:@%+", *c)) plain = 0;
        if (plain) n += snprintf(buf + n, size - n, " %s", a);
        else {
            n += snprintf(buf + n, size - n, " '");
            for (const char *c = a; *c && n < size; c++)
                n += *c == '\'' ? snprintf(buf + n, size - n, "'\\''") : snprintf(buf + n, size - n, "%c", *c);
            n += snprintf(buf + n, size - n, "'");
        }
    }
}
