/* The study's plan (study.h): variants, references, imports, frames. */
#include "caller_words.h"
#include "study.h"
#include "frame_source.h"
#include "fs_error.h"
#include "method_params.h"
#include "render_output.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fs_study_init(fs_study *s, const fs_scene *sc)
{
    memset(s, 0, sizeof *s);
    s->scene = *sc;
    s->repeat = 3;
    s->measure = 1;
    s->frame_step = 1;
}

int fs_study_add_method(fs_study *s, const fs_method *m, const fs_sweep *sweeps, int nsweeps)
{
    static fs_variant vars[FS_STUDY_MAX_ENTRIES];
    int n = fs_sweep_variants(m, &s->scene, sweeps, nsweeps, vars, FS_STUDY_MAX_ENTRIES - s->nentries);
    if (n < 0) return -n;
    for (int k = 0; k < n; k++) {
        fs_study_entry *e = &s->entries[s->nentries + k];
        memset(e, 0, sizeof *e);
        e->v = vars[k];
        snprintf(e->name, sizeof e->name, "%s", m->name);
        memcpy(e->label, e->v.label, sizeof e->label);
        memcpy(e->variant, e->v.variant, sizeof e->variant);
    }
    s->nentries += n;
    return FS_OK;
}

int fs_study_add_methods(fs_study *s, const char *methods, const fs_sweep *sweeps, int nsweeps)
{
    char list[1024];
    int rc = FS_OK;
    if (methods) snprintf(list, sizeof list, "%s", methods);
    else fs_method_names(list, sizeof list);
    for (char *tok = strtok(list, ", "); tok && !rc; tok = strtok(NULL, ", ")) {
        const fs_method *m = fs_method_find(tok);
        if (!methods && m && !strcmp(m->name, "reference")) continue; /* a method of the study only when asked */
        rc = m ? fs_study_add_method(s, m, sweeps, nsweeps) : fs_method_fail_unknown(NULL, tok);
    }
    for (int i = 0; i < nsweeps && !rc; i++) {
        int used = 0;
        for (int k = 0; k < s->nentries; k++) used |= s->entries[k].v.m == sweeps[i].m;
        if (!used)
            rc = fs_fail(FS_ERR_INPUT, "%s.%s sweeps %s, which is not among the methods", sweeps[i].m->name,
                         sweeps[i].m->params[sweeps[i].param].name, sweeps[i].m->name);
    }
    return rc;
}

/* The reference method's parameters under scene sc's settings. */
static int reference_variant(const fs_scene *sc, fs_study_ref *ref)
{
    int n = fs_sweep_variants(fs_method_find("reference"), sc, NULL, 0, &ref->v, 1);
    return n < 0 ? -n : FS_OK;
}

/* The reference method's settings "p=v,q=w" into ref (its label gains _p-v per setting). */
static int reference_settings(fs_study *s, fs_study_ref *ref, const char *spec)
{
    fs_scene sc = s->scene;
    char buf[160];
    snprintf(buf, sizeof buf, "%s", spec + 10);
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        char set[200];
        snprintf(set, sizeof set, "reference.%s", tok);
        int rc = fs_scene_add_set(&sc, set);
        if (rc) return rc;
        char value[160];
        const char *eq = strchr(tok, '='); /* there is one: fs_scene_add_set checked */
        fs_label_value(eq + 1, value, sizeof value);
        size_t l = strlen(ref->label);
        if (snprintf(ref->label + l, sizeof ref->label - l, "_%.*s-%s", (int)(eq - tok), tok, value) >=
            (int)(sizeof ref->label - l))
            return fs_fail(FS_ERR_INPUT, "%s %s: too long", fs_word("reference"), spec);
    }
    return reference_variant(&sc, ref);
}

int fs_study_add_reference(fs_study *s, const char *spec)
{
    if (s->nrefs == FS_STUDY_MAX_REFS)
        return fs_fail(FS_ERR_INPUT, "%s %s: at most %d references", fs_word("reference"), spec, FS_STUDY_MAX_REFS);
    fs_study_ref *ref = &s->refs[s->nrefs];
    memset(ref, 0, sizeof *ref);
    snprintf(ref->spec, sizeof ref->spec, "%s", spec);
    if (!strcmp(spec, "analytic")) {
        if (!s->scene.synth.shape)
            return fs_fail(FS_ERR_INPUT, "%s analytic: needs a synthetic scene", fs_word("reference"));
        ref->analytic = 1;
        snprintf(ref->label, sizeof ref->label, "analytic");
        s->nrefs++;
        return FS_OK;
    }
    if (strncmp(spec, "reference", 9) || (spec[9] && spec[9] != ':'))
        return fs_fail(FS_ERR_INPUT, "%s %s: expected reference, reference:PARAM=V,... or analytic",
                       fs_word("reference"), spec);
    snprintf(ref->label, sizeof ref->label, "reference");
    int rc = spec[9] == ':' ? reference_settings(s, ref, spec) : reference_variant(&s->scene, ref);
    if (!rc) s->nrefs++;
    return rc;
}

int fs_study_add_import(fs_study *s, const char *spec)
{
    const char *eq = strchr(spec, '=');
    if (!eq || eq == spec || !eq[1] || eq - spec >= 64)
        return fs_fail(FS_ERR_INPUT, "%s %s: expected NAME=FILE.exr", fs_word("import"), spec);
    if (s->nentries == FS_STUDY_MAX_ENTRIES)
        return fs_fail(FS_ERR_INPUT, "%s %s: too many entries", fs_word("import"), spec);
    fs_study_entry *e = &s->entries[s->nentries];
    memset(e, 0, sizeof *e);
    snprintf(e->name, sizeof e->name, "%.*s", (int)(eq - spec), spec);
    if (!fs_label_is_safe(e->name))
        return fs_fail(FS_ERR_INPUT, "%s %s: NAME may hold only letters, digits, '_' and '-'", fs_word("import"), spec);
    strcpy(e->label, e->name); /* name is shorter than label */
    snprintf(e->variant, sizeof e->variant, "import");
    e->imported = 1;
    e->file = eq + 1;
    float rr;
    int rc = fs_read_render(eq + 1, &e->first.g, &e->first.rgba, &rr);
    if (rc) return rc;
    const fs_camera *cam = &s->scene.camera;
    if (e->first.g.w != cam->width || e->first.g.h != cam->height) {
        int w = e->first.g.w, h = e->first.g.h;
        fs_run_image_free(&e->first);
        return fs_fail(FS_ERR_INPUT, "%s: %dx%d, but the run renders %dx%d", eq + 1, w, h, cam->width, cam->height);
    }
    snprintf(e->renderer, sizeof e->renderer, "imported");
    s->nentries++;
    return FS_OK;
}

void fs_study_param_columns(fs_study *s, const fs_sweep *sweeps, int nsweeps)
{
    s->npcols = s->nswept = 0;
    for (int i = 0; i < nsweeps; i++) {
        const char *name = sweeps[i].m->params[sweeps[i].param].name;
        int c = 0;
        while (c < s->npcols && strcmp(s->pcols[c], name)) c++;
        if (c == s->npcols) snprintf(s->pcols[s->npcols++], sizeof s->pcols[0], "%s", name);
        s->swept[s->nswept] = sweeps[i].m, s->swept_col[s->nswept++] = c;
    }
}

/* The label of view i: the references first, then the entries. */
static const char *view_label(const fs_study *s, int i)
{
    return i < s->nrefs ? s->refs[i].label : s->entries[i - s->nrefs].label;
}

/* 1 when views i and j are one view: a reference and the entry that is it (same
 * method and parameters), which write the same files. */
static int same_view(const fs_study *s, int i, int j)
{
    if ((i < s->nrefs) == (j < s->nrefs)) return 0;
    const fs_study_ref *ref = &s->refs[i < s->nrefs ? i : j];
    const fs_study_entry *e = &s->entries[(i < s->nrefs ? j : i) - s->nrefs];
    return !ref->analytic && e->v.m == ref->v.m &&
        !memcmp(e->v.params, ref->v.params, ref->v.m->nparams * sizeof e->v.params[0]);
}

/* Every view's label names its files: two views alike would overwrite each
 * other's, and one called like a summary file (panel.png, diff_*.png) would
 * overwrite it. */
int fs_study_check_labels(const fs_study *s)
{
    int n = s->nrefs + s->nentries;
    for (int i = 0; i < n; i++) {
        const char *a = view_label(s, i);
        if (!strcmp(a, "panel") || !strncmp(a, "diff_", 5))
            return fs_fail(FS_ERR_INPUT, "%s: a view with this label would overwrite compare's own %s files", a,
                           a[0] == 'p' ? "panel" : "diff_*");
        for (int j = 0; j < i; j++)
            if (!strcmp(a, view_label(s, j)) && !same_view(s, i, j))
                return fs_fail(FS_ERR_INPUT,
                               "two views get the file label %s (a value given twice, or two that differ "
                               "only in characters a label cannot hold)",
                               a);
    }
    return FS_OK;
}

int fs_study_set_frames(fs_study *s)
{
    int last;
    fs_scene_frames(&s->scene, &s->first_frame, &last);
    s->sequence = s->scene.frame_first >= 0;
    s->nframes = fs_scene_frame_count(&s->scene);
    s->frame_step = s->scene.frame_step;
    if (s->given) s->first_frame = 0, s->frame_step = 1, s->nframes = s->ngiven, s->sequence = s->ngiven > 1;
    for (int i = 0; i < s->nentries; i++)
        if (s->entries[i].imported && s->nframes > 1)
            return fs_fail(FS_ERR_INPUT, "%s needs a single-frame scene", fs_word("import"));
    return FS_OK;
}

int fs_study_load_first(fs_study *s, float radius, char *note, int size)
{
    int rc = s->given ? fs_particles_validate(&s->given[0], "particles")
                      : fs_scene_load_frame(&s->scene, s->first_frame, &s->frame0);
    if (!rc && s->given) {
        s->frame0 = s->given[0];
        fs_particles_bounds(&s->frame0);
    }
    if (!rc) fs_scene_adopt_frame(&s->scene, &s->frame0, radius, note, size);
    return rc;
}

int fs_study_alloc(fs_study *s)
{
    for (int k = 0; k < s->nrefs; k++)
        if (!(s->refs[k].made = calloc(s->nframes, sizeof *s->refs[k].made)))
            return fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < s->nentries; i++) {
        fs_study_entry *e = &s->entries[i];
        e->metrics = calloc((size_t)s->nrefs * s->nframes, sizeof *e->metrics);
        e->frame_ms = calloc(s->nframes, sizeof *e->frame_ms);
        e->runs = calloc(s->repeat, sizeof *e->runs);
        e->counts = s->counters ? calloc(s->nframes, sizeof *e->counts) : NULL;
        if (!e->metrics || !e->frame_ms || !e->runs || (s->counters && !e->counts))
            return fs_fail(FS_ERR_RUNTIME, "out of memory");
    }
    return FS_OK;
}

void fs_study_free(fs_study *s)
{
    for (int i = 0; i < s->nentries; i++) {
        fs_study_entry *e = &s->entries[i];
        fs_run_image_free(&e->first);
        free(e->metrics);
        free(e->frame_ms);
        free(e->runs);
        free(e->counts);
        e->metrics = NULL, e->frame_ms = NULL, e->runs = NULL, e->counts = NULL;
    }
    for (int k = 0; k < s->nrefs; k++) {
        fs_run_image_free(&s->refs[k].first);
        free(s->refs[k].made);
        s->refs[k].made = NULL;
    }
    if (!s->given) fs_particles_free(&s->frame0);
}
