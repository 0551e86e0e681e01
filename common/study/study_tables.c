/* The study's tables as CSV (study_tables.h): one writer for compare's files,
 * the library and Python. */
#include "study_tables.h"
#include "counters_csv.h"
#include "fs_error.h"
#include "method_params.h"
#include "stats.h"
#include "text_out.h"
#include <math.h>
#include <string.h>

void fs_study_row_values(const fs_metrics *m, double frame_ms, double v[FS_STUDY_ROW_VALUES])
{
    const double all[FS_STUDY_ROW_VALUES] = {m->mask_iou,
                                             m->depth_bias_r,
                                             m->depth_rmse_r,
                                             m->depth_p95_r,
                                             m->normal_mean_deg,
                                             m->normal_p95_deg,
                                             m->interior_normal_mean_deg,
                                             m->psnr_db,
                                             m->ssim,
                                             frame_ms};
    for (int j = 0; j < FS_STUDY_ROW_VALUES; j++) v[j] = all[j];
}

static void num(FILE *f, double v, const char *fmt)
{
    if (isnan(v)) fputs("", f);
    else if (isinf(v)) fputs(v > 0 ? "inf" : "-inf", f);
    else fprintf(f, fmt, v);
}

static void provenance_header(const fs_study *s, FILE *f)
{
    char line[8192];
    fs_provenance_line(&s->prov, line, sizeof line);
    fprintf(f, "%s\n", line);
}

/* 1 when entry e's method sweeps parameter column c. */
static int sweeps_column(const fs_study *s, const fs_study_entry *e, int c)
{
    int yes = 0;
    for (int k = 0; k < s->nswept; k++) yes |= s->swept_col[k] == c && s->swept[k] == e->v.m && !e->imported;
    return yes;
}

/* Entry e's value of each parameter column, "" where its method does not sweep it
 * (another method's parameter of that name is not the one swept). */
static void param_cells(const fs_study *s, const fs_study_entry *e, FILE *f)
{
    for (int c = 0; c < s->npcols; c++) {
        const fs_method *m = sweeps_column(s, e, c) ? e->v.m : NULL;
        for (int j = 0; m && j < m->nparams; j++)
            if (!strcmp(m->params[j].name, s->pcols[c])) {
                char v[64];
                fs_param_format(&m->params[j], e->v.params[j], v, sizeof v);
                fs_csv_text(f, v);
            }
        fputc(',', f);
    }
}

static int write_metrics(const fs_study *s, FILE *f)
{
    provenance_header(s, f);
    fputs("method,variant,", f);
    for (int c = 0; c < s->npcols; c++) fprintf(f, "%s,", s->pcols[c]); /* one per swept parameter */
    fputs("reference,frame,mask_iou,depth_bias_r,depth_rmse_r,depth_p95_r,normal_mean_deg,normal_p95_deg,"
          "interior_normal_mean_deg,psnr_db,ssim,frame_ms,n_both,n_interior,"
          /* appended, so the columns before keep their positions (scripts read them by index) */
          "depth_median_r,depth_abs_p50_r,depth_abs_p95_r,depth_abs_p99_r,depth_over_1r_frac\n",
          f);
    for (int i = 0; i < s->nentries; i++) {
        const fs_study_entry *e = &s->entries[i];
        int nf = e->imported ? 1 : s->nframes;
        for (int k = 0; k < s->nrefs; k++)
            for (int fr = 0; fr < nf; fr++) {
                const fs_metrics *m = &e->metrics[k * s->nframes + fr];
                fs_csv_text(f, e->name);
                fputc(',', f);
                fs_csv_text(f, e->variant);
                fputc(',', f);
                param_cells(s, e, f);
                fs_csv_text(f, s->refs[k].spec);
                fputc(',', f);
                if (s->sequence) fprintf(f, "%d", fs_study_frame(s, fr));
                double v[FS_STUDY_ROW_VALUES];
                fs_study_row_values(m, e->frame_ms[fr], v);
                for (int j = 0; j < FS_STUDY_ROW_VALUES; j++) {
                    fputc(',', f);
                    num(f, v[j], j == 9 ? "%.3f" : "%.6g");
                }
                fprintf(f, ",%zu,%zu", m->n_both, m->n_interior);
                const double d[] = {m->depth_median_r, m->depth_abs_p50_r, m->depth_abs_p95_r, m->depth_abs_p99_r,
                                    m->depth_over_1r_frac};
                for (int j = 0; j < 5; j++) {
                    fputc(',', f);
                    num(f, d[j], "%.6g");
                }
                fputc('\n', f);
            }
    }
    return FS_OK;
}

/* A reference's rows: its first frame, one run (stage "cache" when it came
 * from the cache), named by its spec with the variant "ground truth". */
static void ref_timings(const fs_study_ref *ref, FILE *f)
{
    const fs_stages *st = &ref->stages;
    for (int s = 0; s <= st->n; s++) {
        double v = s < st->n ? st->ms[s] : fs_stages_total(st);
        fs_csv_text(f, ref->spec);
        fprintf(f, ",ground truth,%s,%.3f,%.3f,%.3f,1,,CPU\n", s < st->n ? st->name[s] : "total", v, v, v);
    }
}

/* The runs' wall times of stage name ("total": their sums) into v; the median
 * GL time of the runs that have one into *gpu (NaN: none). Returns the median
 * wall time, v sorted. */
static double stage_runs(const fs_study_entry *e, const char *name, int total, double *v, double *gpu)
{
    double g[FS_STUDY_MAX_RUNS];
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

static int write_timings(const fs_study *s, FILE *f)
{
    provenance_header(s, f);
    /* gpu_ms_median: the GL clock (gl_stage.h), empty for CPU stages and totals */
    fputs("method,variant,stage,ms_median,ms_min,ms_max,runs,gpu_ms_median,renderer\n", f);
    for (int k = 0; k < s->nrefs; k++) ref_timings(&s->refs[k], f);
    for (int i = 0; i < s->nentries; i++) {
        const fs_study_entry *e = &s->entries[i];
        if (e->imported || !e->nruns) continue;
        /* every stage any run reported, then the total */
        for (int j = 0; j <= e->runs[0].n; j++) {
            double v[FS_STUDY_MAX_RUNS], gpu;
            const char *name = j < e->runs[0].n ? e->runs[0].name[j] : "total";
            double med = stage_runs(e, name, j == e->runs[0].n, v, &gpu);
            fs_csv_text(f, e->name);
            fputc(',', f);
            fs_csv_text(f, e->variant);
            fprintf(f, ",%s,%.3f,%.3f,%.3f,%d,", name, med, v[0], v[e->nruns - 1], e->nruns);
            if (!isnan(gpu)) fprintf(f, "%.3f", gpu);
            fputc(',', f);
            fs_csv_text(f, e->renderer);
            fputc('\n', f);
        }
    }
    return FS_OK;
}

static int write_temporal(const fs_study *s, FILE *f)
{
    provenance_header(s, f);
    fputs("method,variant,frames,normal_change_deg,reference_normal_change_deg,normal_temporal_error_deg,"
          "depth_temporal_error_r\n",
          f);
    for (int i = 0; i < s->nentries; i++) {
        const fs_study_entry *e = &s->entries[i];
        if (e->imported) continue;
        fs_csv_text(f, e->name);
        fputc(',', f);
        fs_csv_text(f, e->variant);
        fprintf(f, ",%d,", s->nframes);
        num(f, e->temporal_deg, "%.4f");
        fputc(',', f);
        num(f, s->ref_temporal_deg, "%.4f");
        fputc(',', f);
        num(f, e->temporal_err_deg, "%.4f");
        fputc(',', f);
        num(f, e->temporal_err_depth_r, "%.5f");
        fputc('\n', f);
    }
    return FS_OK;
}

static int write_counters(const fs_study *s, FILE *f)
{
    provenance_header(s, f);
    fputs(FS_COUNTERS_HEADER, f);
    for (int k = 0; k < s->nrefs; k++) {
        const fs_study_ref *ref = &s->refs[k];
        for (int fr = 0; fr < s->nframes && !ref->analytic; fr++)
            fs_counters_rows(f, ref->spec, "ground truth", fs_study_frame(s, fr), &ref->made[fr].counts,
                             ref->v.m->counters);
    }
    for (int i = 0; i < s->nentries; i++) {
        const fs_study_entry *e = &s->entries[i];
        for (int fr = 0; fr < s->nframes && !e->imported; fr++)
            fs_counters_rows(f, e->name, e->variant, fs_study_frame(s, fr), &e->counts[fr], e->v.m->counters);
    }
    return FS_OK;
}

int fs_study_write_table(const fs_study *s, const char *name, FILE *f)
{
    if (!strcmp(name, "metrics")) return write_metrics(s, f);
    if (!strcmp(name, "timings")) return write_timings(s, f);
    if (!strcmp(name, "temporal")) return write_temporal(s, f);
    if (!strcmp(name, "counters")) return write_counters(s, f);
    return fs_fail(FS_ERR_INPUT, "%s: no such table (metrics, timings, temporal, counters)", name);
}
