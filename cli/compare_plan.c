/* compare's plan from its command line (compare.h): the scene, the variants,
 * the references and imports, the output folder, the frames. */
#include "cli.h"
#include "compare.h"
#include "compare_outdir.h"
#include "fs_error.h"
#include "method_params.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int make_outdir(const char *dir, int *made)
{
    struct stat st;
    if (stat(dir, &st) != 0) {
        if (mkdir(dir, 0755) != 0)
            return fs_fail(FS_ERR_INPUT, "%s: cannot create the output folder: %s", dir, strerror(errno));
        *made = 1;
    } else if (!S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_INPUT, "%s: exists and is not a folder", dir);
    if (access(dir, W_OK) != 0) return fs_fail(FS_ERR_INPUT, "%s: output folder is not writable", dir);
    return FS_OK;
}

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
static int plan_variants(cmp_run *r, const cmp_options *o)
{
    fs_scene sc;
    int rc = cli_scene_from_arg(&sc, o->input);
    if (rc) return cli_error(rc);
    cli_scene_opts_apply(&sc, &o->field);
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
    int repeat = r->s.repeat;
    fs_study_init(&r->s, &sc);
    r->s.repeat = repeat, r->s.counters = o->counters, r->s.measure = !r->shard_n;
    if ((rc = add_variants(&r->s, o->methods, sweeps, nsweeps))) return rc;
    fs_study_param_columns(&r->s, sweeps, nsweeps);
    for (int i = 0; o->counters && i < r->s.nentries; i++)
        if ((rc = fs_run_check_counters(r->s.entries[i].v.m))) return cli_error(rc);
    double check[FS_MAX_PARAMS]; /* every plain --set must name a real method and parameter */
    if ((rc = fs_method_params_resolve(fs_method_at(0), &r->s.scene, check))) return cli_error(rc);
    return FS_OK;
}

/* References and imports, then the output folder: all input is checked before it is made. */
static int plan_references(cmp_run *r, const cmp_options *o)
{
    fs_study *s = &r->s;
    int rc = FS_OK;
    for (int i = 0; i < o->nrefspecs && !rc; i++) rc = fs_study_add_reference(s, o->refspecs[i]);
    if (!rc && !o->nrefspecs) rc = fs_study_add_reference(s, "reference");
    if (!rc && o->nimports && s->scene.frame_first >= 0 && s->scene.frame_last > s->scene.frame_first)
        rc = fs_fail(FS_ERR_INPUT, "--import needs a single-frame scene");
    for (int i = 0; i < o->nimports && !rc; i++) rc = fs_study_add_import(s, o->imports[i]);
    if (!rc) rc = fs_study_check_labels(s);
    if (!rc) rc = fs_study_set_frames(s);
    if (!rc) rc = make_outdir(r->outdir, &r->made_outdir);
    /* a merge writes into its fresh staging folder; merge itself checks the output */
    if (!rc && !r->made_outdir && !r->merge) rc = cmp_outdir_claim(r->outdir, "compare", r->resume, r->force);
    return rc ? cli_error(rc) : FS_OK;
}

int cmp_plan(cmp_run *r, const cmp_options *o)
{
    int rc = plan_variants(r, o);
    return rc ? rc : plan_references(r, o);
}

void cmp_quote_command(char *buf, int size, int argc, char **argv)
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
