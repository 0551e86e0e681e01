/* The heatmaps of every entry against the first reference: diff_LABEL.png with
 * colour bars, heat_normal_LABEL.png and heat_depth_LABEL.png alone (report.html's layers). */
#include "study_dir_state.h"
#include "outputs_list.h"
#include "diff_panel.h"
#include "fs_error.h"
#include <stdio.h>
#include <string.h>

/* The normal-error heatmap of entry e against the first reference. */
int fs_study_dir_normal_heatmap(const fs_study_dir *r, const fs_study_entry *e, fs_rgba_image *out)
{
    return fs_normal_heatmap(&e->first.g, &r->s->refs[0].first.g, r->normal_scale_deg, out);
}

/* heat_normal_LABEL.png and heat_depth_LABEL.png: the first frame's heatmaps
 * alone, the image's size, for report.html's layers (diff_LABEL.png holds them
 * with their colour bars). */
static int write_heat_data(const fs_study_dir *r, const char *name, const fs_rgba_image *hm, double vmax,
                           const char *title, const char *units)
{
    int ow, oh, dx, dy, w = r->s->entries[0].first.g.w, h = r->s->entries[0].first.g.h;
    int rc = fs_heatmap_layout(w, h, vmax, title, units, &ow, &oh, &dx, &dy);
    if (!rc && (ow != hm->w || oh != hm->h || dx + w > ow || dy + h > oh))
        rc = fs_fail(FS_ERR_RUNTIME, "%s: heatmap layout %dx%d differs from the image's %dx%d", name, ow, oh, hm->w,
                     hm->h);
    fs_rgba_image data = {0};
    if (!rc) rc = fs_rgba_alloc(&data, w, h, NULL);
    for (int y = 0; !rc && y < h; y++)
        memcpy(data.pix + (size_t)4 * w * y, hm->pix + 4 * ((size_t)ow * (dy + y) + dx),
               (size_t)4 * w * sizeof *data.pix);
    if (!rc) rc = fs_study_dir_write_rgba(r, name, &data);
    fs_rgba_free(&data);
    return rc;
}

static int write_heatmaps(const fs_study_dir *r, const fs_study_entry *e)
{
    fs_rgba_image hm = {0};
    char name[300];
    int rc = fs_study_dir_normal_heatmap(r, e, &hm);
    snprintf(name, sizeof name, "heat_normal_%s.png", e->label);
    if (!rc) rc = write_heat_data(r, name, &hm, r->normal_scale_deg, "normal error", "deg");
    fs_rgba_free(&hm);
    if (!rc)
        rc = fs_depth_heatmap(&e->first.g, &r->s->refs[0].first.g, r->s->scene.radius, e->metrics[0].depth_bias_r,
                              r->depth_scale_r, &hm);
    snprintf(name, sizeof name, "heat_depth_%s.png", e->label);
    if (!rc) rc = write_heat_data(r, name, &hm, r->depth_scale_r, "|depth error - bias|", "r");
    fs_rgba_free(&hm);
    return rc;
}

int fs_study_dir_write_diffs(const fs_study_dir *r)
{
    for (int i = 0; i < r->s->nentries; i++) {
        const fs_study_entry *e = &r->s->entries[i];
        char title[400], name[300], path[1400];
        snprintf(title, sizeof title, "%s against %s", e->label, r->s->refs[0].spec);
        snprintf(name, sizeof name, "diff_%s.png", e->label);
        fs_study_dir_path(r, name, path, sizeof path);
        int rc = fs_outputs_record(path);
        if (!rc)
            rc = fs_write_diff_panel(path, &e->first.g, &r->s->refs[0].first.g, r->s->scene.radius,
                                     e->metrics[0].depth_bias_r, r->normal_scale_deg, r->depth_scale_r, title);
        if (!rc) rc = write_heatmaps(r, e);
        if (rc) return rc;
    }
    return FS_OK;
}
