/* Where a study's work items come from and go to (study.h, fs_study_io): the
 * shard plan, the reference cache, --resume, merge's shard folders, and the
 * output folder's PNGs and EXRs. */
#include "study_dir_state.h"
#include "merge.h"
#include "outputs_list.h"
#include "resume.h"
#include "fs_error.h"
#include "method_params.h"
#include "progress.h"
#include "render_output.h"
#include <stdio.h>

static fs_item_where io_where(void *user, const fs_study *s, int item)
{
    (void)s;
    const fs_study_dir *r = user;
    if (r->merge) return FS_ITEM_LOAD;
    return fs_study_dir_renders(r, item) ? FS_ITEM_RENDER : FS_ITEM_SKIP;
}

/* A reference view from the cache, or rendered and stored in it. */
static int io_ref_view(void *user, fs_study *s, int k, int f, fs_run *run, const fs_particles *p, const fs_grid *g,
                       fs_run_image *v, fs_stages *st, fs_study_made *made)
{
    fs_study_dir *r = user;
    int frame = fs_study_frame(s, f);
    int rc = fs_ref_cache_render(&r->cache, run, &s->scene, p, g, &s->prov, frame, v, st, made);
    if (!rc && made->hit) fs_note("%s, frame %d: from the cache, %s", s->refs[k].spec, frame, made->entry);
    return rc;
}

/* merge: every item from its shard; --resume: a method's item finished before. */
static int io_load(void *user, fs_study *s, int is_ref, int index, int f, const fs_provenance *prov, fs_run_image *v,
                   int *got)
{
    fs_study_dir *r = user;
    *got = 0;
    if (r->merge) {
        int rc = is_ref ? fs_merge_ref(r, index, f, v) : fs_merge_entry(r, index, f, v);
        *got = !rc;
        return rc;
    }
    if (!r->o->resume || is_ref) return FS_OK;
    char exr[1400];
    fs_study_dir_view_path(r, NULL, s->entries[index].label, fs_study_frame(s, f), "", "exr", exr, sizeof exr);
    *got = fs_resume_load(&s->entries[index], f, s->repeat, prov, exr, v);
    r->resumed += *got;
    return FS_OK;
}

/* The PNGs first and the EXR last: a complete EXR means a finished item (--resume). */
static int write_view(const fs_study_dir *r, const char *label, int frame, const fs_run_image *v,
                      const fs_provenance *prov)
{
    char path[1400];
    fs_study_dir_view_path(r, NULL, label, frame, "", "png", path, sizeof path);
    int rc = fs_outputs_record(path);
    if (!rc) rc = fs_write_render(path, &v->g, v->rgba, prov);
    const float *own = fs_gbuffer_aov(&v->g, FS_AOV_OWN);
    if (!rc && own) { /* the method's own appearance beside the shared shading */
        fs_study_dir_view_path(r, NULL, label, frame, "_own", "png", path, sizeof path);
        if (!(rc = fs_outputs_record(path))) rc = fs_write_render(path, &v->g, own, prov);
    }
    fs_study_dir_view_path(r, NULL, label, frame, "", "exr", path, sizeof path);
    if (!rc) rc = fs_outputs_record(path);
    return rc ? rc : fs_write_render_in_scene(path, &r->s->scene, &r->s->scene.camera, &v->g, v->rgba, prov);
}

/* A reference's provenance names its label and parameters; it ran on the CPU. */
static void ref_provenance(const fs_study_ref *ref, fs_provenance *prov)
{
    char pstr[600];
    if (!ref->analytic) {
        fs_method_params_string(ref->v.m, ref->v.params, pstr, sizeof pstr);
        fs_provenance_set(prov, "params", pstr);
    }
    fs_provenance_set(prov, "method", ref->label);
    fs_provenance_set(prov, "gl_renderer", "CPU");
}

static int io_store(void *user, fs_study *s, int is_ref, int index, int f, const fs_run_image *v, fs_provenance *prov)
{
    fs_study_dir *r = user;
    if (is_ref) ref_provenance(&s->refs[index], prov);
    else fs_resume_stamp(prov, &s->entries[index], f);
    return write_view(r, is_ref ? s->refs[index].label : s->entries[index].label, fs_study_frame(s, f), v, prov);
}

/* A finished work item (one view of one frame), for the progress bar or line. */
static void io_done(void *user, const fs_study *s, const char *label, int f)
{
    (void)user;
    char what[160];
    if (s->nframes > 1) snprintf(what, sizeof what, "%s, frame %d", label, fs_study_frame(s, f));
    else snprintf(what, sizeof what, "%s", label);
    fs_progress_item(what);
}

static void io_note(void *user, const char *text)
{
    (void)user;
    fs_note("%s", text);
}

fs_study_io fs_study_dir_io(fs_study_dir *r)
{
    fs_study_io io = {r, io_where, io_ref_view, io_load, io_store, io_done, io_note};
    return io;
}
