/* compare's report.md: the command, the panel, the metrics per reference, the
 * files' labels, where the references came from, the counters, renderers and
 * provenance. */
#include "study_dir_state.h"
#include "counters_csv.h"
#include "method_params.h"
#include "study_tables.h"
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* One row of the report's counter table: the first frame's totals. */
static void md_counts(FILE *f, const char *name, const char *variant, const fs_stages *st, unsigned declared)
{
    fprintf(f, "| %s | %s", name, variant[0] ? variant : "—");
    for (int c = 0; c < FS_NCOUNTERS; c++)
        if (declared & FS_CNT_BIT(c)) fprintf(f, " | %" PRIu64, fs_counters_total(st, c));
        else fputs(" | —", f);
    fputs(" |\n", f);
}

static void write_counter_table(const fs_study_dir *r, FILE *f)
{
    fprintf(f, "## Work counters%s\n\n| method | variant", r->s->nframes > 1 ? " (first frame)" : "");
    for (int c = 0; c < FS_NCOUNTERS; c++) fprintf(f, " | %s", fs_counter_name(c));
    fputs(" |\n|---|---", f);
    for (int c = 0; c < FS_NCOUNTERS; c++) fputs("|---", f);
    fputs("|\n", f);
    for (int k = 0; k < r->s->nrefs; k++)
        if (!r->s->refs[k].analytic)
            md_counts(f, r->s->refs[k].spec, "ground truth", &r->s->refs[k].made[0].counts,
                      r->s->refs[k].v.m->counters);
    for (int i = 0; i < r->s->nentries; i++)
        if (!r->s->entries[i].imported)
            md_counts(f, r->s->entries[i].name, r->s->entries[i].variant, &r->s->entries[i].counts[0],
                      r->s->entries[i].v.m->counters);
    fputs("\nTotals over the stages of one counting render, made after the timed ones on the same inputs; "
          "per stage and frame in `counters.csv`. The counts do not depend on the machine: docs/DESIGN.md "
          "(\"Work counters\") defines each unit. — marks a counter the method does not report.\n\n",
          f);
}

static void md_num(FILE *f, double v, const char *fmt)
{
    fputs(" | ", f);
    if (isnan(v)) fputs("—", f);
    else if (isinf(v)) fputs("∞", f);
    else fprintf(f, fmt, v);
}

/* Where each reference came from: rendered, or which cache entry. */
static void write_ref_sources(const fs_study_dir *r, FILE *f)
{
    fputs("## References\n\n", f);
    for (int k = 0; k < r->s->nrefs; k++) {
        const fs_study_ref *ref = &r->s->refs[k];
        if (ref->analytic) {
            fprintf(f, "- `%s`: the ideal shape of the synthetic scene\n", ref->spec);
            continue;
        }
        int stored = 0;
        for (int fr = 0; fr < r->s->nframes; fr++) stored += ref->made[fr].entry[0] != 0;
        if (!stored) fprintf(f, "- `%s`: rendered; no cache (%s)\n", ref->spec, r->cache.why);
        else fprintf(f, "- `%s`: %d of %d frame(s) from the cache\n", ref->spec, ref->hits, r->s->nframes);
        for (int fr = 0; fr < r->s->nframes; fr++) {
            const fs_study_made *m = &ref->made[fr];
            if (!m->entry[0]) continue;
            fprintf(f, "  - ");
            if (r->s->sequence) fprintf(f, "frame %d: ", fs_study_frame(r->s, fr));
            fprintf(f, "%s `%s`\n", m->hit ? "from the cache:" : "rendered, stored as", m->entry);
        }
    }
    fputs("\nA reference from the cache is a stored G-buffer whose key (a hash of the particles, field, camera, "
          "image size, the reference's parameters and fluidsurf's commit) and contents checked out; its time in "
          "`timings.csv` is the stage `cache` (loading the entry) in place of rendering.\n\n",
          f);
}

/* The labels that name the files, each with its method and parameters. */
static void write_labels(const fs_study_dir *r, FILE *f)
{
    fputs("## Files\n\nEach view is written as `LABEL.png` (shaded), `LABEL.exr` (the G-buffer with its provenance)",
          f);
    fputs(r->s->sequence ? ", per frame as `LABEL_fNNNN.png` and `.exr`," : "", f);
    fputs(
        " and, for a method, `diff_LABEL.png` (heatmaps against the first reference). A label holds only letters, "
        "digits, `_` and `-`: the method, then `_PARAM-VALUE` for each swept parameter, with `.` in a value written "
        "`p` and a minus sign `m` (`0.8` is `0p8`); the settings are the swept values (a reference's, those of its spec).\n\n"
        "| label | method | settings | every parameter |\n|---|---|---|---|\n",
        f);
    char params[1024];
    for (int k = 0; k < r->s->nrefs; k++) {
        const fs_study_ref *ref = &r->s->refs[k];
        if (ref->analytic) {
            fprintf(f, "| `%s` | %s (ground truth) | — | the ideal shape of the synthetic scene |\n", ref->label,
                    ref->spec);
            continue;
        }
        fs_method_params_string(ref->v.m, ref->v.params, params, sizeof params);
        const char *colon = strchr(ref->spec, ':');
        fprintf(f, "| `%s` | %s (ground truth) | %s | %s |\n", ref->label, ref->v.m->name, colon ? colon + 1 : "—",
                params);
    }
    for (int i = 0; i < r->s->nentries; i++) {
        const fs_study_entry *e = &r->s->entries[i];
        if (e->imported) {
            fprintf(f, "| `%s` | imported | — | %s |\n", e->label, e->file);
            continue;
        }
        fs_method_params_string(e->v.m, e->v.params, params, sizeof params);
        fprintf(f, "| `%s` | %s | %s | %s |\n", e->label, e->name, e->variant[0] ? e->variant : "—", params);
    }
    fputc('\n', f);
}

/* Entry e's row against reference k, its metrics' means over the frames; beside
 * the p95 around the bias, the p95 of |depth error| itself. */
static void write_row(const fs_study_dir *r, const fs_study_entry *e, int k, FILE *f)
{
    int nf = e->imported ? 1 : r->s->nframes;
    double acc[FS_STUDY_ROW_VALUES] = {0}, abs_p95 = 0;
    for (int fr = 0; fr < nf; fr++) {
        double v[FS_STUDY_ROW_VALUES];
        const fs_metrics *m = &e->metrics[k * r->s->nframes + fr];
        fs_study_row_values(m, e->frame_ms[fr], v);
        for (int j = 0; j < FS_STUDY_ROW_VALUES; j++) acc[j] += v[j] / nf;
        abs_p95 += m->depth_abs_p95_r / nf;
    }
    fprintf(f, "| %s | %s", e->name, e->variant[0] ? e->variant : "—");
    const char *fmt[FS_STUDY_ROW_VALUES] = {"%.4f", "%+.3f", "%.3f", "%.3f", "%.2f",
                                            "%.2f", "%.2f",  "%.2f", "%.4f", "%.1f"};
    for (int j = 0; j < FS_STUDY_ROW_VALUES; j++) {
        md_num(f, acc[j], fmt[j]);
        if (j == 3) md_num(f, abs_p95, "%.3f"); /* after depth_p95_r */
    }
    fputs(" |\n", f);
}

int fs_study_dir_write_report(const fs_study_dir *r)
{
    fs_output cf;
    int rc = fs_study_dir_open(r, "report.md", &cf);
    if (rc) return rc;
    FILE *f = cf.f;
    fprintf(f, "# fluidsurf compare\n\nReproduce with:\n\n    %s\n\n", r->o->command);
    fprintf(f, "![panel](panel.png)\n\n");
    for (int k = 0; k < r->s->nrefs; k++) {
        fprintf(f, "## Against `%s`%s\n\n", r->s->refs[k].spec, r->s->nframes > 1 ? " (mean over frames)" : "");
        fputs("| method | variant | IoU | depth bias (r) | depth RMSE (r) | depth p95 around the bias (r) "
              "| abs depth p95 (r) | normal mean (deg) | normal p95 (deg) | interior normal (deg) | PSNR (dB) | SSIM "
              "| frame (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
              f);
        for (int i = 0; i < r->s->nentries; i++) write_row(r, &r->s->entries[i], k, f);
        fputc('\n', f);
    }
    fprintf(
        f,
        "Depth errors are in multiples of r = %g: the bias is the mean signed difference (method - reference) over "
        "pixels both cover, RMSE and \"p95 around the bias\" (metrics.csv's depth_p95_r) measure |error - bias| "
        "(so a few far outliers, which pull the bias, inflate them); \"abs depth p95\" (depth_abs_p95_r) is the "
        "95th percentile of |error| itself, which such outliers barely move; metrics.csv also holds the median "
        "signed error, other percentiles of |error| and the share of pixels with |error| > 1 r. Normal angles are over pixels both "
        "cover; \"interior\" keeps pixels at least 3 px from either silhouette. PSNR and SSIM (Wang et al. 2004) "
        "are on sRGB luminance over the union of the coverage masks. Frame times are medians of %d runs after a "
        "warm-up; per-stage times are in `timings.csv`. Heatmap scales: normal %g deg, depth %g r.\n\n",
        r->s->scene.radius, r->s->repeat, r->normal_scale_deg, r->depth_scale_r);
    write_labels(r, f);
    write_ref_sources(r, f);
    if (r->s->counters) write_counter_table(r, f);
    fputs("## Renderers\n\n", f);
    for (int i = 0; i < r->s->nentries; i++)
        fprintf(f, "- %s: %s\n", r->s->entries[i].label, r->s->entries[i].renderer);
    fputs("\nOn OSMesa (llvmpipe) the OpenGL stages run on the same CPU cores as the C code: these timings say nothing "
          "about GPU speed.\n\n## Provenance\n\n",
          f);
    for (int i = 0; i < r->s->prov.n; i++) fprintf(f, "- `%s`: %s\n", r->s->prov.name[i], r->s->prov.value[i]);
    return fs_study_dir_close(&cf);
}
