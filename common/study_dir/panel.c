/* panel.png: the views side by side with their normal-error heatmaps under
 * them, or the grid of a method swept over two parameters. */
#include "study_dir_state.h"
#include "fs_error.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void wrap_view(const fs_run_image *v, fs_rgba_image *im)
{
    im->w = v->g.w;
    im->h = v->g.h;
    im->pix = v->rgba;
}

static void caption(const fs_study_dir *r, const fs_study_entry *e, char *buf, int size)
{
    const fs_metrics *m = &e->metrics[0];
    int n = snprintf(buf, size, "%s", e->imported ? e->name : e->label);
    if (isfinite(e->frame_ms[0])) n += snprintf(buf + n, size - n, "  %.1f ms", e->frame_ms[0]);
    if (isfinite(m->normal_mean_deg)) snprintf(buf + n, size - n, "  %.1f deg", m->normal_mean_deg);
    (void)r;
}

/* A grid: exactly one method swept over two parameters, rows = first, columns = second. */
static int is_grid(const fs_study_dir *r)
{
    int methods = 0;
    for (int i = 0; i < r->s->nentries; i++) methods += !r->s->entries[i].imported;
    return methods > 1 && r->s->entries[0].v.nswept == 2 && methods == r->s->nentries && r->s->entries[0].v.m &&
        r->s->entries[methods - 1].v.m == r->s->entries[0].v.m;
}

static int write_grid_panel(const fs_study_dir *r)
{
    const fs_study_entry *e0 = &r->s->entries[0];
    int rows = 1 + e0->v.value_index[0], cols = 1 + e0->v.value_index[1];
    for (int i = 0; i < r->s->nentries; i++) {
        if (r->s->entries[i].v.value_index[0] + 1 > rows) rows = r->s->entries[i].v.value_index[0] + 1;
        if (r->s->entries[i].v.value_index[1] + 1 > cols) cols = r->s->entries[i].v.value_index[1] + 1;
    }
    fs_rgba_image *img = calloc((size_t)rows * cols, sizeof *img), *hm = calloc((size_t)rows * cols, sizeof *hm);
    const fs_rgba_image **ti = calloc((size_t)rows * cols, sizeof *ti), **th = calloc((size_t)rows * cols, sizeof *th);
    char(*cap)[256] = calloc((size_t)rows * cols, sizeof *cap), (*rh)[200] = calloc(rows, sizeof *rh),
    (*ch)[200] = calloc(cols, sizeof *ch);
    const char **capp = calloc((size_t)rows * cols, sizeof *capp), **rhp = calloc(rows, sizeof *rhp),
               **chp = calloc(cols, sizeof *chp);
    int rc = img && hm && ti && th && cap && rh && ch && capp && rhp && chp ? FS_OK
                                                                            : fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < r->s->nentries && !rc; i++) {
        const fs_study_entry *e = &r->s->entries[i];
        int k = e->v.value_index[0] * cols + e->v.value_index[1];
        const fs_sweep *s0 = NULL;
        (void)s0;
        wrap_view(&e->first, &img[k]);
        ti[k] = &img[k];
        rc = fs_study_dir_normal_heatmap(r, e, &hm[k]);
        th[k] = &hm[k];
        const fs_metrics *m = &e->metrics[0];
        snprintf(cap[k], sizeof cap[k], "%.1f ms  %.1f deg", e->frame_ms[0], m->normal_mean_deg);
        capp[k] = cap[k];
        /* headers from the variant string "p=v;q=w" */
        char var[200];
        snprintf(var, sizeof var, "%s", e->variant);
        char *semi = strchr(var, ';');
        if (semi) *semi = 0;
        snprintf(rh[e->v.value_index[0]], sizeof rh[0], "%s", var);
        snprintf(ch[e->v.value_index[1]], sizeof ch[0], "%s", semi ? semi + 1 : "");
    }
    for (int i = 0; i < rows; i++) rhp[i] = rh[i];
    for (int i = 0; i < cols; i++) chp[i] = ch[i];
    fs_rgba_image out = {0};
    char title[300];
    snprintf(title, sizeof title, "%s (normal error against %s on the right)", e0->name, r->s->refs[0].spec);
    /* images and heatmaps side by side: 2*cols columns */
    const fs_rgba_image **both = calloc((size_t)rows * cols * 2, sizeof *both);
    const char **bcap = calloc((size_t)rows * cols * 2, sizeof *bcap), **bch = calloc((size_t)cols * 2, sizeof *bch);
    if (!rc && (!both || !bcap || !bch)) rc = fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int y = 0; y < rows && !rc; y++)
        for (int x = 0; x < cols; x++) {
            both[y * 2 * cols + x] = ti[y * cols + x];
            both[y * 2 * cols + cols + x] = th[y * cols + x];
            bcap[y * 2 * cols + x] = capp[y * cols + x];
            bcap[y * 2 * cols + cols + x] = capp[y * cols + x];
        }
    for (int x = 0; x < cols && !rc; x++) {
        bch[x] = chp[x];
        bch[cols + x] = chp[x];
    }
    fs_panel_spec spec = {rows, 2 * cols, both, bcap, bch, rhp, title};
    if (!rc) rc = fs_panel_compose(&spec, &out);
    if (!rc) rc = fs_study_dir_write_rgba(r, "panel.png", &out);
    fs_rgba_free(&out);
    for (int i = 0; hm && i < rows * cols; i++) fs_rgba_free(&hm[i]);
    free(img);
    free(hm);
    free(ti);
    free(th);
    free(cap);
    free(rh);
    free(ch);
    free(capp);
    free(rhp);
    free(chp);
    free(both);
    free(bcap);
    free(bch);
    return rc;
}

/* The entry that is the first reference itself (same method and parameters), or -1. */
static int entry_of_ref0(const fs_study_dir *r)
{
    const fs_study_ref *ref = &r->s->refs[0];
    for (int i = 0; i < r->s->nentries && !ref->analytic; i++)
        if (r->s->entries[i].v.m == ref->v.m &&
            !memcmp(r->s->entries[i].v.params, ref->v.params, ref->v.m->nparams * sizeof ref->v.params[0]))
            return i;
    return -1;
}

int fs_study_dir_write_panel(const fs_study_dir *r)
{
    if (is_grid(r)) return write_grid_panel(r);
    /* columns: the first reference (unless it is among the entries), then every
     * entry; row 2: normal-error heatmaps against it */
    int self = entry_of_ref0(r), gt = self < 0, cols = gt + r->s->nentries;
    fs_rgba_image *img = calloc(cols, sizeof *img), *hm = calloc(cols, sizeof *hm);
    const fs_rgba_image **tiles = calloc(2 * cols, sizeof *tiles);
    char(*cap)[256] = calloc(2 * cols, sizeof *cap);
    const char **capp = calloc(2 * cols, sizeof *capp);
    int rc = img && hm && tiles && cap && capp ? FS_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc && gt) {
        wrap_view(&r->s->refs[0].first, &img[0]);
        tiles[0] = &img[0];
        if (r->s->refs[0].made[0].hit)
            snprintf(cap[0], sizeof cap[0], "%s (ground truth, from the cache)", r->s->refs[0].spec);
        else
            snprintf(cap[0], sizeof cap[0], "%s (ground truth)  %.1f ms", r->s->refs[0].spec,
                     fs_stages_total(&r->s->refs[0].stages)); /* the timed stages only, never the counting render */
        capp[0] = cap[0];
    }
    for (int i = 0; i < r->s->nentries && !rc; i++) {
        const fs_study_entry *e = &r->s->entries[i];
        /* the ground truth always takes the first column */
        int c = gt ? 1 + i : i == self ? 0 : i < self ? i + 1 : i;
        wrap_view(&e->first, &img[c]);
        tiles[c] = &img[c];
        if (i == self) snprintf(cap[c], sizeof cap[0], "%s (ground truth)  %.1f ms", e->label, e->frame_ms[0]);
        else caption(r, e, cap[c], sizeof cap[0]);
        capp[c] = cap[c];
        if (i == self) continue; /* its error is zero by construction: leave the cell empty */
        rc = fs_study_dir_normal_heatmap(r, e, &hm[c]);
        tiles[cols + c] = &hm[c];
        snprintf(cap[cols + c], sizeof cap[0], "IoU %.3f, depth bias %+.2f r", e->metrics[0].mask_iou,
                 e->metrics[0].depth_bias_r);
        capp[cols + c] = cap[cols + c];
    }
    fs_rgba_image out = {0};
    char title[1400];
    const char *src = r->s->scene.synth.shape ? "synthetic scene" : r->s->scene.source;
    const char *slash = strrchr(src, '/');
    snprintf(title, sizeof title, "%s, %dx%d, r = %g; normal error against %s", slash ? slash + 1 : src,
             r->s->scene.camera.width, r->s->scene.camera.height, r->s->scene.radius, r->s->refs[0].spec);
    fs_panel_spec spec = {2, cols, tiles, capp, NULL, NULL, title};
    if (!rc) rc = fs_panel_compose(&spec, &out);
    if (!rc) rc = fs_study_dir_write_rgba(r, "panel.png", &out);
    fs_rgba_free(&out);
    for (int i = 0; hm && i < cols; i++) fs_rgba_free(&hm[i]);
    free(img);
    free(hm);
    free(tiles);
    free(cap);
    free(capp);
    return rc;
}
