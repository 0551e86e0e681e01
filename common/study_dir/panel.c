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

/* The grid panel's cells: a row per value of the first swept parameter, and per
 * value of the second a column of images, then a column of their heatmaps. */
typedef struct grid_cells {
    int rows, cols;          /* the variants' grid; the panel has 2 * cols columns */
    fs_rgba_image *img, *hm; /* rows * cols */
    char (*cap)[256], (*rh)[200], (*ch)[200];
    const fs_rgba_image **tiles; /* rows * 2 cols */
    const char **caps, **rhp, **chp;
} grid_cells;

static void grid_free(grid_cells *g)
{
    for (int i = 0; g->hm && i < g->rows * g->cols; i++) fs_rgba_free(&g->hm[i]);
    free(g->img), free(g->hm), free(g->cap), free(g->rh), free(g->ch);
    free(g->tiles), free(g->caps), free(g->rhp), free(g->chp);
}

static int grid_alloc(grid_cells *g, const fs_study *s)
{
    memset(g, 0, sizeof *g);
    g->rows = 1 + s->entries[0].v.value_index[0], g->cols = 1 + s->entries[0].v.value_index[1];
    for (int i = 0; i < s->nentries; i++) {
        if (s->entries[i].v.value_index[0] + 1 > g->rows) g->rows = s->entries[i].v.value_index[0] + 1;
        if (s->entries[i].v.value_index[1] + 1 > g->cols) g->cols = s->entries[i].v.value_index[1] + 1;
    }
    size_t n = (size_t)g->rows * g->cols;
    g->img = calloc(n, sizeof *g->img), g->hm = calloc(n, sizeof *g->hm), g->cap = calloc(n, sizeof *g->cap);
    g->rh = calloc(g->rows, sizeof *g->rh), g->ch = calloc(g->cols, sizeof *g->ch);
    g->tiles = calloc(2 * n, sizeof *g->tiles), g->caps = calloc(2 * n, sizeof *g->caps);
    g->rhp = calloc(g->rows, sizeof *g->rhp), g->chp = calloc(2 * (size_t)g->cols, sizeof *g->chp);
    int ok = g->img && g->hm && g->cap && g->rh && g->ch && g->tiles && g->caps && g->rhp && g->chp;
    return ok ? FS_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
}

/* Entry e's cell: its image, its heatmap beside it, one caption under both, and
 * the headers from its variant string "p=v;q=w". */
static int grid_cell(grid_cells *g, const fs_study_dir *r, const fs_study_entry *e)
{
    int y = e->v.value_index[0], x = e->v.value_index[1], k = y * g->cols + x, t = y * 2 * g->cols + x;
    wrap_view(&e->first, &g->img[k]);
    int rc = fs_study_dir_normal_heatmap(r, e, &g->hm[k]);
    snprintf(g->cap[k], sizeof g->cap[k], "%.1f ms  %.1f deg", e->frame_ms[0], e->metrics[0].normal_mean_deg);
    g->tiles[t] = &g->img[k], g->tiles[t + g->cols] = &g->hm[k];
    g->caps[t] = g->caps[t + g->cols] = g->cap[k];
    char var[200];
    snprintf(var, sizeof var, "%s", e->variant);
    char *semi = strchr(var, ';');
    if (semi) *semi = 0;
    snprintf(g->rh[y], sizeof g->rh[0], "%s", var);
    snprintf(g->ch[x], sizeof g->ch[0], "%s", semi ? semi + 1 : "");
    return rc;
}

static int write_grid_panel(const fs_study_dir *r)
{
    grid_cells g;
    int rc = grid_alloc(&g, r->s);
    for (int i = 0; i < r->s->nentries && !rc; i++) rc = grid_cell(&g, r, &r->s->entries[i]);
    for (int i = 0; !rc && i < g.rows; i++) g.rhp[i] = g.rh[i];
    for (int x = 0; !rc && x < g.cols; x++) g.chp[x] = g.chp[g.cols + x] = g.ch[x];
    char title[300];
    snprintf(title, sizeof title, "%s (normal error against %s on the right)", r->s->entries[0].name,
             r->s->refs[0].spec);
    fs_panel_spec spec = {g.rows, 2 * g.cols, g.tiles, g.caps, g.chp, g.rhp, title};
    fs_rgba_image out = {0};
    if (!rc) rc = fs_panel_compose(&spec, &out);
    if (!rc) rc = fs_study_dir_write_rgba(r, "panel.png", &out);
    fs_rgba_free(&out);
    grid_free(&g);
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
