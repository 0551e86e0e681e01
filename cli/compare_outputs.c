/* The files `compare` writes: CSVs, heatmaps, the panel and the report. Each is
 * written to a temporary file and renamed (output_file.h), and recorded in the
 * folder's list of fluidsurf's files before it is written (compare_outdir.h). */
#include "compare.h"
#include "compare_outdir.h"
#include "counters_csv.h"
#include "diff_panel.h"
#include "figure.h"
#include "method_params.h"
#include "fs_error.h"
#include "output_file.h"
#include "stats.h"
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cmp_path(const cmp_run *r, const char *name, char *buf, int size) { snprintf(buf, size, "%s/%s", r->outdir, name); }

void cmp_view_path(const cmp_run *r, const char *dir, const char *label, int frame, const char *suffix,
                   const char *ext, char *path, int size)
{
    if (r->sequence) snprintf(path, size, "%s/%s%s_f%04d.%s", dir ? dir : r->outdir, label, suffix, frame, ext);
    else snprintf(path, size, "%s/%s%s.%s", dir ? dir : r->outdir, label, suffix, ext);
}

int cmp_open(const cmp_run *r, const char *name, cmp_file *cf)
{
    cmp_path(r, name, cf->final, sizeof cf->final);
    int rc = cmp_outdir_record(cf->final);
    if (!rc) rc = fs_output_begin(cf->final, cf->tmp, sizeof cf->tmp);
    if (rc) return rc;
    if (!(cf->f = fopen(cf->tmp, "w"))) {
        fs_output_end(cf->final, cf->tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: cannot write", cf->final);
    }
    return FS_OK;
}

int cmp_close(cmp_file *cf)
{
    int ok = !ferror(cf->f);
    ok &= fclose(cf->f) == 0;
    if (!ok) { fs_output_end(cf->final, cf->tmp, 0); return fs_fail(FS_ERR_RUNTIME, "%s: write failed", cf->final); }
    return fs_output_end(cf->final, cf->tmp, 1);
}

static void num(FILE *f, double v, const char *fmt)
{
    if (isnan(v)) fputs("", f);
    else if (isinf(v)) fputs(v > 0 ? "inf" : "-inf", f);
    else fprintf(f, fmt, v);
}

static void csv_text(FILE *f, const char *s)
{
    if (!strpbrk(s, ",\"\n")) { fputs(s, f); return; }
    fputc('"', f);
    for (; *s; s++) { if (*s == '"') fputc('"', f); fputc(*s, f); }
    fputc('"', f);
}

static void provenance_header(const cmp_run *r, FILE *f)
{
    char line[8192];
    fs_provenance_line(&r->prov, line, sizeof line);
    fprintf(f, "%s\n", line);
}

/* Entry e's value of each parameter column, "" where its method has no such parameter. */
static void param_cells(const cmp_run *r, const cmp_entry *e, FILE *f)
{
    for (int c = 0; c < r->npcols; c++) {
        const fs_method *m = e->imported ? NULL : e->v.m;
        for (int j = 0; m && j < m->nparams; j++)
            if (!strcmp(m->params[j].name, r->pcols[c])) {
                char v[64];
                fs_param_format(&m->params[j], e->v.params[j], v, sizeof v);
                csv_text(f, v);
            }
        fputc(',', f);
    }
}

int cmp_write_metrics(const cmp_run *r)
{
    cmp_file cf;
    int rc = cmp_open(r, "metrics.csv", &cf);
    if (rc) return rc;
    FILE *f = cf.f;
    provenance_header(r, f);
    fputs("method,variant,", f);
    for (int c = 0; c < r->npcols; c++) fprintf(f, "%s,", r->pcols[c]); /* one per swept parameter */
    fputs("reference,frame,mask_iou,depth_bias_r,depth_rmse_r,depth_p95_r,normal_mean_deg,normal_p95_deg,"
          "interior_normal_mean_deg,psnr_db,ssim,frame_ms,n_both,n_interior,"
          /* appended, so the columns before keep their positions (scripts read them by index) */
          "depth_median_r,depth_abs_p50_r,depth_abs_p95_r,depth_abs_p99_r,depth_over_1r_frac\n", f);
    for (int i = 0; i < r->nentries; i++) {
        const cmp_entry *e = &r->entries[i];
        int nf = e->imported ? 1 : r->nframes;
        for (int k = 0; k < r->nrefs; k++)
            for (int fr = 0; fr < nf; fr++) {
                const fs_metrics *m = &e->metrics[k * r->nframes + fr];
                csv_text(f, e->name); fputc(',', f);
                csv_text(f, e->variant); fputc(',', f);
                param_cells(r, e, f);
                csv_text(f, r->refs[k].spec); fputc(',', f);
                if (r->sequence) fprintf(f, "%d", r->first_frame + fr);
                const double v[] = {m->mask_iou, m->depth_bias_r, m->depth_rmse_r, m->depth_p95_r, m->normal_mean_deg,
                                    m->normal_p95_deg, m->interior_normal_mean_deg, m->psnr_db, m->ssim, e->frame_ms[fr]};
                for (int j = 0; j < 10; j++) { fputc(',', f); num(f, v[j], j == 9 ? "%.3f" : "%.6g"); }
                fprintf(f, ",%zu,%zu", m->n_both, m->n_interior);
                const double d[] = {m->depth_median_r, m->depth_abs_p50_r, m->depth_abs_p95_r, m->depth_abs_p99_r,
                                    m->depth_over_1r_frac};
                for (int j = 0; j < 5; j++) { fputc(',', f); num(f, d[j], "%.6g"); }
                fputc('\n', f);
            }
    }
    return cmp_close(&cf);
}

/* A reference's rows: its first frame, one run (stage "cache" when it came
 * from the cache), named by its spec with the variant "ground truth". */
static void ref_timings(const cmp_ref *ref, FILE *f)
{
    const fs_stages *st = &ref->stages;
    for (int s = 0; s <= st->n; s++) {
        double v = s < st->n ? st->ms[s] : fs_stages_total(st);
        csv_text(f, ref->spec);
        fprintf(f, ",ground truth,%s,%.3f,%.3f,%.3f,1,,CPU\n", s < st->n ? st->name[s] : "total", v, v, v);
    }
}

/* The runs' wall times of stage name ("total": their sums) into v; the median
 * GL time of the runs that have one into *gpu (NaN: none). Returns the median
 * wall time, v sorted. */
static double stage_runs(const cmp_entry *e, const char *name, int total, double *v, double *gpu)
{
    double g[CMP_MAX_RUNS];
    int ng = 0;
    for (int k = 0; k < e->nruns; k++) {
        const fs_stages *st = &e->runs[k];
        v[k] = total ? fs_stages_total(st) : 0;
        for (int j = 0; !total && j < st->n; j++)
            if (!strcmp(st->name[j], name)) {
                v[k] = st->ms[j];
                if (!isnan(st->gpu_ms[j])) g[ng++] = st->gpu_ms[j];
            }
    }
    *gpu = ng ? fs_median(g, ng) : NAN;
    return fs_median(v, e->nruns);
}

int cmp_write_timings(const cmp_run *r)
{
    cmp_file cf;
    int rc = cmp_open(r, "timings.csv", &cf);
    if (rc) return rc;
    FILE *f = cf.f;
    provenance_header(r, f);
    /* gpu_ms_median: the GL clock (gl_stage.h), empty for CPU stages and totals */
    fputs("method,variant,stage,ms_median,ms_min,ms_max,runs,gpu_ms_median,renderer\n", f);
    for (int k = 0; k < r->nrefs; k++) ref_timings(&r->refs[k], f);
    for (int i = 0; i < r->nentries; i++) {
        const cmp_entry *e = &r->entries[i];
        if (e->imported || !e->nruns) continue;
        /* every stage any run reported, then the total */
        for (int s = 0; s <= e->runs[0].n; s++) {
            double v[CMP_MAX_RUNS], gpu;
            const char *name = s < e->runs[0].n ? e->runs[0].name[s] : "total";
            double med = stage_runs(e, name, s == e->runs[0].n, v, &gpu);
            csv_text(f, e->name); fputc(',', f);
            csv_text(f, e->variant);
            fprintf(f, ",%s,%.3f,%.3f,%.3f,%d,", name, med, v[0], v[e->nruns - 1], e->nruns);
            if (!isnan(gpu)) fprintf(f, "%.3f", gpu);
            fputc(',', f);
            csv_text(f, e->renderer);
            fputc('\n', f);
        }
    }
    return cmp_close(&cf);
}

int cmp_write_temporal(const cmp_run *r)
{
    cmp_file cf;
    int rc = cmp_open(r, "temporal.csv", &cf);
    if (rc) return rc;
    FILE *f = cf.f;
    provenance_header(r, f);
    fputs("method,variant,frames,normal_change_deg,reference_normal_change_deg,normal_temporal_error_deg,"
          "depth_temporal_error_r\n", f);
    for (int i = 0; i < r->nentries; i++) {
        const cmp_entry *e = &r->entries[i];
        if (e->imported) continue;
        csv_text(f, e->name); fputc(',', f);
        csv_text(f, e->variant);
        fprintf(f, ",%d,", r->nframes);
        num(f, e->temporal_deg, "%.4f");
        fputc(',', f);
        num(f, r->ref_temporal_deg, "%.4f");
        fputc(',', f);
        num(f, e->temporal_err_deg, "%.4f");
        fputc(',', f);
        num(f, e->temporal_err_depth_r, "%.5f");
        fputc('\n', f);
    }
    return cmp_close(&cf);
}

static int write_rgba_png(const cmp_run *r, const char *name, const fs_rgba_image *im)
{
    char path[1400];
    cmp_path(r, name, path, sizeof path);
    const char *names[4] = {"R", "G", "B", "A"};
    fs_image img = {im->w, im->h, 4, names, im->pix};
    int rc = cmp_outdir_record(path);
    return rc ? rc : fs_write_png(path, &img);
}

/* The normal-error heatmap of entry e against the first reference. */
static int normal_heatmap(const cmp_run *r, const cmp_entry *e, fs_rgba_image *out)
{
    return fs_normal_heatmap(&e->first.g, &r->refs[0].frames[0].g, r->normal_scale_deg, out);
}

int cmp_write_diffs(const cmp_run *r)
{
    for (int i = 0; i < r->nentries; i++) {
        const cmp_entry *e = &r->entries[i];
        char title[400], name[300], path[1400];
        snprintf(title, sizeof title, "%s against %s", e->label, r->refs[0].spec);
        snprintf(name, sizeof name, "diff_%s.png", e->label);
        cmp_path(r, name, path, sizeof path);
        int rc = cmp_outdir_record(path);
        if (!rc) rc = fs_write_diff_panel(path, &e->first.g, &r->refs[0].frames[0].g, r->scene.radius,
                                     e->metrics[0].depth_bias_r, r->normal_scale_deg, r->depth_scale_r, title);
        if (rc) return rc;
    }
    return FS_OK;
}

static void wrap_view(const cmp_view *v, fs_rgba_image *im) { im->w = v->g.w; im->h = v->g.h; im->pix = v->rgba; }

static void caption(const cmp_run *r, const cmp_entry *e, char *buf, int size)
{
    const fs_metrics *m = &e->metrics[0];
    int n = snprintf(buf, size, "%s", e->imported ? e->name : e->label);
    if (isfinite(e->frame_ms[0])) n += snprintf(buf + n, size - n, "  %.1f ms", e->frame_ms[0]);
    if (isfinite(m->normal_mean_deg)) snprintf(buf + n, size - n, "  %.1f deg", m->normal_mean_deg);
    (void)r;
}

/* A grid: exactly one method swept over two parameters, rows = first, columns = second. */
static int is_grid(const cmp_run *r)
{
    int methods = 0;
    for (int i = 0; i < r->nentries; i++) methods += !r->entries[i].imported;
    return methods > 1 && r->entries[0].v.nswept == 2 && methods == r->nentries && r->entries[0].v.m &&
           r->entries[methods - 1].v.m == r->entries[0].v.m;
}

static int write_grid_panel(const cmp_run *r)
{
    const cmp_entry *e0 = &r->entries[0];
    int rows = 1 + e0->v.value_index[0], cols = 1 + e0->v.value_index[1];
    for (int i = 0; i < r->nentries; i++) {
        if (r->entries[i].v.value_index[0] + 1 > rows) rows = r->entries[i].v.value_index[0] + 1;
        if (r->entries[i].v.value_index[1] + 1 > cols) cols = r->entries[i].v.value_index[1] + 1;
    }
    fs_rgba_image *img = calloc((size_t)rows * cols, sizeof *img), *hm = calloc((size_t)rows * cols, sizeof *hm);
    const fs_rgba_image **ti = calloc((size_t)rows * cols, sizeof *ti), **th = calloc((size_t)rows * cols, sizeof *th);
    char (*cap)[256] = calloc((size_t)rows * cols, sizeof *cap), (*rh)[200] = calloc(rows, sizeof *rh), (*ch)[200] = calloc(cols, sizeof *ch);
    const char **capp = calloc((size_t)rows * cols, sizeof *capp), **rhp = calloc(rows, sizeof *rhp), **chp = calloc(cols, sizeof *chp);
    int rc = img && hm && ti && th && cap && rh && ch && capp && rhp && chp ? FS_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
    for (int i = 0; i < r->nentries && !rc; i++) {
        const cmp_entry *e = &r->entries[i];
        int k = e->v.value_index[0] * cols + e->v.value_index[1];
        const fs_sweep *s0 = NULL;
        (void)s0;
        wrap_view(&e->first, &img[k]);
        ti[k] = &img[k];
        rc = normal_heatmap(r, e, &hm[k]);
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
    snprintf(title, sizeof title, "%s (normal error against %s on the right)", e0->name, r->refs[0].spec);
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
    for (int x = 0; x < cols && !rc; x++) { bch[x] = chp[x]; bch[cols + x] = chp[x]; }
    fs_panel_spec spec = {rows, 2 * cols, both, bcap, bch, rhp, title};
    if (!rc) rc = fs_panel_compose(&spec, &out);
    if (!rc) rc = write_rgba_png(r, "panel.png", &out);
    fs_rgba_free(&out);
    for (int i = 0; hm && i < rows * cols; i++) fs_rgba_free(&hm[i]);
    free(img); free(hm); free(ti); free(th); free(cap); free(rh); free(ch); free(capp); free(rhp); free(chp);
    free(both); free(bcap); free(bch);
    return rc;
}

/* The entry that is the first reference itself (same method and parameters), or -1. */
static int entry_of_ref0(const cmp_run *r)
{
    const cmp_ref *ref = &r->refs[0];
    for (int i = 0; i < r->nentries && !ref->analytic; i++)
        if (r->entries[i].v.m == ref->v.m &&
            !memcmp(r->entries[i].v.params, ref->v.params, ref->v.m->nparams * sizeof ref->v.params[0]))
            return i;
    return -1;
}

int cmp_write_panel(const cmp_run *r)
{
    if (is_grid(r)) return write_grid_panel(r);
    /* columns: the first reference (unless it is among the entries), then every
     * entry; row 2: normal-error heatmaps against it */
    int self = entry_of_ref0(r), gt = self < 0, cols = gt + r->nentries;
    fs_rgba_image *img = calloc(cols, sizeof *img), *hm = calloc(cols, sizeof *hm);
    const fs_rgba_image **tiles = calloc(2 * cols, sizeof *tiles);
    char (*cap)[256] = calloc(2 * cols, sizeof *cap);
    const char **capp = calloc(2 * cols, sizeof *capp);
    int rc = img && hm && tiles && cap && capp ? FS_OK : fs_fail(FS_ERR_RUNTIME, "out of memory");
    if (!rc && gt) {
        wrap_view(&r->refs[0].frames[0], &img[0]);
        tiles[0] = &img[0];
        if (r->refs[0].made[0].hit) snprintf(cap[0], sizeof cap[0], "%s (ground truth, from the cache)", r->refs[0].spec);
        else snprintf(cap[0], sizeof cap[0], "%s (ground truth)  %.1f ms", r->refs[0].spec,
                      fs_stages_total(&r->refs[0].stages)); /* the timed stages only, never the counting render */
        capp[0] = cap[0];
    }
    for (int i = 0; i < r->nentries && !rc; i++) {
        const cmp_entry *e = &r->entries[i];
        /* the ground truth always takes the first column */
        int c = gt ? 1 + i : i == self ? 0 : i < self ? i + 1 : i;
        wrap_view(&e->first, &img[c]);
        tiles[c] = &img[c];
        if (i == self) snprintf(cap[c], sizeof cap[0], "%s (ground truth)  %.1f ms", e->label, e->frame_ms[0]);
        else caption(r, e, cap[c], sizeof cap[0]);
        capp[c] = cap[c];
        if (i == self) continue; /* its error is zero by construction: leave the cell empty */
        rc = normal_heatmap(r, e, &hm[c]);
        tiles[cols + c] = &hm[c];
        snprintf(cap[cols + c], sizeof cap[0], "IoU %.3f, depth bias %+.2f r", e->metrics[0].mask_iou, e->metrics[0].depth_bias_r);
        capp[cols + c] = cap[cols + c];
    }
    fs_rgba_image out = {0};
    char title[1400];
    const char *src = r->scene.synth.shape ? "synthetic scene" : r->scene.source;
    const char *slash = strrchr(src, '/');
    snprintf(title, sizeof title, "%s, %dx%d, r = %g; normal error against %s", slash ? slash + 1 : src,
             r->scene.camera.width, r->scene.camera.height, r->scene.radius, r->refs[0].spec);
    fs_panel_spec spec = {2, cols, tiles, capp, NULL, NULL, title};
    if (!rc) rc = fs_panel_compose(&spec, &out);
    if (!rc) rc = write_rgba_png(r, "panel.png", &out);
    fs_rgba_free(&out);
    for (int i = 0; hm && i < cols; i++) fs_rgba_free(&hm[i]);
    free(img); free(hm); free(tiles); free(cap); free(capp);
    return rc;
}

int cmp_write_counters(const cmp_run *r)
{
    cmp_file cf;
    int rc = cmp_open(r, "counters.csv", &cf);
    if (rc) return rc;
    FILE *f = cf.f;
    provenance_header(r, f);
    fputs(CLI_COUNTERS_HEADER, f);
    for (int k = 0; k < r->nrefs; k++) {
        const cmp_ref *ref = &r->refs[k];
        for (int fr = 0; fr < r->nframes && !ref->analytic; fr++)
            cli_counters_rows(f, ref->spec, "ground truth", r->first_frame + fr, &ref->made[fr].counts, ref->v.m->counters);
    }
    for (int i = 0; i < r->nentries; i++) {
        const cmp_entry *e = &r->entries[i];
        for (int fr = 0; fr < r->nframes && !e->imported; fr++)
            cli_counters_rows(f, e->name, e->variant, r->first_frame + fr, &e->counts[fr], e->v.m->counters);
    }
    return cmp_close(&cf);
}

/* One row of the report's counter table: the first frame's totals. */
static void md_counts(FILE *f, const char *name, const char *variant, const fs_stages *st, unsigned declared)
{
    fprintf(f, "| %s | %s", name, variant[0] ? variant : "—");
    for (int c = 0; c < FS_NCOUNTERS; c++)
        if (declared & FS_CNT_BIT(c)) fprintf(f, " | %" PRIu64, cli_counters_total(st, c));
        else fputs(" | —", f);
    fputs(" |\n", f);
}

static void write_counter_table(const cmp_run *r, FILE *f)
{
    fprintf(f, "## Work counters%s\n\n| method | variant", r->nframes > 1 ? " (first frame)" : "");
    for (int c = 0; c < FS_NCOUNTERS; c++) fprintf(f, " | %s", fs_counter_name(c));
    fputs(" |\n|---|---", f);
    for (int c = 0; c < FS_NCOUNTERS; c++) fputs("|---", f);
    fputs("|\n", f);
    for (int k = 0; k < r->nrefs; k++)
        if (!r->refs[k].analytic) md_counts(f, r->refs[k].spec, "ground truth", &r->refs[k].made[0].counts, r->refs[k].v.m->counters);
    for (int i = 0; i < r->nentries; i++)
        if (!r->entries[i].imported)
            md_counts(f, r->entries[i].name, r->entries[i].variant, &r->entries[i].counts[0], r->entries[i].v.m->counters);
    fputs("\nTotals over the stages of one counting render, made after the timed ones on the same inputs; "
          "per stage and frame in `counters.csv`. The counts do not depend on the machine: docs/DESIGN.md "
          "(\"Work counters\") defines each unit. — marks a counter the method does not report.\n\n", f);
}

static void md_num(FILE *f, double v, const char *fmt)
{
    fputs(" | ", f);
    if (isnan(v)) fputs("—", f);
    else if (isinf(v)) fputs("∞", f);
    else fprintf(f, fmt, v);
}

/* Where each reference came from: rendered, or which cache entry. */
static void write_ref_sources(const cmp_run *r, FILE *f)
{
    fputs("## References\n\n", f);
    for (int k = 0; k < r->nrefs; k++) {
        const cmp_ref *ref = &r->refs[k];
        if (ref->analytic) { fprintf(f, "- `%s`: the ideal shape of the synthetic scene\n", ref->spec); continue; }
        int stored = 0;
        for (int fr = 0; fr < r->nframes; fr++) stored += ref->made[fr].entry[0] != 0;
        if (!stored) fprintf(f, "- `%s`: rendered; no cache (%s)\n", ref->spec, r->cache.why);
        else fprintf(f, "- `%s`: %d of %d frame(s) from the cache\n", ref->spec, ref->hits, r->nframes);
        for (int fr = 0; fr < r->nframes; fr++) {
            const cli_cache_view *m = &ref->made[fr];
            if (!m->entry[0]) continue;
            fprintf(f, "  - ");
            if (r->sequence) fprintf(f, "frame %d: ", r->first_frame + fr);
            fprintf(f, "%s `%s`\n", m->hit ? "from the cache:" : "rendered, stored as", m->entry);
        }
    }
    fputs("\nA reference from the cache is a stored G-buffer whose key (a hash of the particles, field, camera, "
          "image size, the reference's parameters and fluidsurf's commit) and contents checked out; its time in "
          "`timings.csv` is the stage `cache` (loading the entry) in place of rendering.\n\n", f);
}

/* The labels that name the files, each with its method and parameters. */
static void write_labels(const cmp_run *r, FILE *f)
{
    fputs("## Files\n\nEach view is written as `LABEL.png` (shaded), `LABEL.exr` (the G-buffer with its provenance)", f);
    fputs(r->sequence ? ", per frame as `LABEL_fNNNN.png` and `.exr`," : "", f);
    fputs(" and, for a method, `diff_LABEL.png` (heatmaps against the first reference). A label holds only letters, "
          "digits, `_` and `-`: the method, then `_PARAM-VALUE` for each swept parameter, with `.` in a value written "
          "`p` and a minus sign `m` (`0.8` is `0p8`); the settings are the swept values (a reference's, those of its spec).\n\n"
          "| label | method | settings | every parameter |\n|---|---|---|---|\n", f);
    char params[1024];
    for (int k = 0; k < r->nrefs; k++) {
        const cmp_ref *ref = &r->refs[k];
        if (ref->analytic) { fprintf(f, "| `%s` | %s (ground truth) | — | the ideal shape of the synthetic scene |\n", ref->label, ref->spec); continue; }
        fs_method_params_string(ref->v.m, ref->v.params, params, sizeof params);
        const char *colon = strchr(ref->spec, ':');
        fprintf(f, "| `%s` | %s (ground truth) | %s | %s |\n", ref->label, ref->v.m->name, colon ? colon + 1 : "—", params);
    }
    for (int i = 0; i < r->nentries; i++) {
        const cmp_entry *e = &r->entries[i];
        if (e->imported) { fprintf(f, "| `%s` | imported | — | %s |\n", e->label, e->file); continue; }
        fs_method_params_string(e->v.m, e->v.params, params, sizeof params);
        fprintf(f, "| `%s` | %s | %s | %s |\n", e->label, e->name, e->variant[0] ? e->variant : "—", params);
    }
    fputc('\n', f);
}

int cmp_write_report(const cmp_run *r)
{
    cmp_file cf;
    int rc = cmp_open(r, "report.md", &cf);
    if (rc) return rc;
    FILE *f = cf.f;
    fprintf(f, "# fluidsurf compare\n\nReproduce with:\n\n    %s\n\n", r->command);
    fprintf(f, "![panel](panel.png)\n\n");
    for (int k = 0; k < r->nrefs; k++) {
        fprintf(f, "## Against `%s`%s\n\n", r->refs[k].spec, r->nframes > 1 ? " (mean over frames)" : "");
        fputs("| method | variant | IoU | depth bias (r) | depth RMSE (r) | depth p95 (r) | normal mean (deg) | normal p95 (deg) "
              "| interior normal (deg) | PSNR (dB) | SSIM | frame (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n", f);
        for (int i = 0; i < r->nentries; i++) {
            const cmp_entry *e = &r->entries[i];
            int nf = e->imported ? 1 : r->nframes;
            double acc[10] = {0};
            for (int fr = 0; fr < nf; fr++) {
                const fs_metrics *m = &e->metrics[k * r->nframes + fr];
                const double v[] = {m->mask_iou, m->depth_bias_r, m->depth_rmse_r, m->depth_p95_r, m->normal_mean_deg,
                                    m->normal_p95_deg, m->interior_normal_mean_deg, m->psnr_db, m->ssim, e->frame_ms[fr]};
                for (int j = 0; j < 10; j++) acc[j] += v[j] / nf;
            }
            fprintf(f, "| %s | %s", e->name, e->variant[0] ? e->variant : "—");
            const char *fmt[] = {"%.4f", "%+.3f", "%.3f", "%.3f", "%.2f", "%.2f", "%.2f", "%.2f", "%.4f", "%.1f"};
            for (int j = 0; j < 10; j++) md_num(f, acc[j], fmt[j]);
            fputs(" |\n", f);
        }
        fputc('\n', f);
    }
    fprintf(f, "Depth errors are in multiples of r = %g: the bias is the mean signed difference (method - reference) over "
               "pixels both cover, RMSE and p95 measure the error around that bias (so a few far outliers, which pull the "
               "bias, inflate them); metrics.csv also holds the median signed error, percentiles of |error| and the "
               "share of pixels with |error| > 1 r, which such outliers barely move. Normal angles are over pixels both "
               "cover; \"interior\" keeps pixels at least 3 px from either silhouette. PSNR and SSIM (Wang et al. 2004) "
               "are on sRGB luminance over the union of the coverage masks. Frame times are medians of %d runs after a "
               "warm-up; per-stage times are in `timings.csv`. Heatmap scales: normal %g deg, depth %g r.\n\n",
            r->scene.radius, r->repeat, r->normal_scale_deg, r->depth_scale_r);
    write_labels(r, f);
    write_ref_sources(r, f);
    if (r->counters) write_counter_table(r, f);
    fputs("## Renderers\n\n", f);
    for (int i = 0; i < r->nentries; i++) fprintf(f, "- %s: %s\n", r->entries[i].label, r->entries[i].renderer);
    fputs("\nOn OSMesa (llvmpipe) the OpenGL stages run on the same CPU cores as the C code: these timings say nothing "
          "about GPU speed.\n\n## Provenance\n\n", f);
    for (int i = 0; i < r->prov.n; i++) fprintf(f, "- `%s`: %s\n", r->prov.name[i], r->prov.value[i]);
    return cmp_close(&cf);
}
