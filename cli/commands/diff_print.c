/* The metrics of `diff` as "name value" lines or one JSON object (diff.h). */
#include "diff.h"
#include "text_out.h"
#include <math.h>

/* The metrics in the order diff prints them, named as metrics.csv's columns. */
typedef struct named {
    const char *name;
    double v;
} named;
enum { NMETRICS = 17 };

static void metric_list(const fs_metrics *m, named out[NMETRICS])
{
    const named l[NMETRICS] = {
        {"mask_iou", m->mask_iou},
        {"depth_bias_r", m->depth_bias_r},
        {"depth_rmse_r", m->depth_rmse_r},
        {"depth_p95_r", m->depth_p95_r},
        {"normal_mean_deg", m->normal_mean_deg},
        {"normal_p95_deg", m->normal_p95_deg},
        {"interior_normal_mean_deg", m->interior_normal_mean_deg},
        {"psnr_db", m->psnr_db},
        {"ssim", m->ssim},
        {"n_both", (double)m->n_both},
        {"n_interior", (double)m->n_interior},
        {"depth_median_r", m->depth_median_r},
        {"depth_abs_p50_r", m->depth_abs_p50_r},
        {"depth_abs_p95_r", m->depth_abs_p95_r},
        {"depth_abs_p99_r", m->depth_abs_p99_r},
        {"depth_over_1r_frac", m->depth_over_1r_frac},
        {"n_union", (double)m->n_union},
    };
    for (int i = 0; i < NMETRICS; i++) out[i] = l[i];
}

void diff_print_text(FILE *f, const char *const files[2], float r, long masked, const fs_metrics *m,
                     const diff_fail *fails, int nfails)
{
    named l[NMETRICS];
    metric_list(m, l);
    fprintf(f, "a: %s\nb: %s (reference)\nr: %g\n", files[0], files[1], r);
    if (masked >= 0)
        fprintf(f, "solids_masked_px %ld (hidden by solids, left out as compare leaves them out)\n", masked);
    for (int i = 0; i < NMETRICS; i++) fprintf(f, "%s %.6g\n", l[i].name, l[i].v);
    for (int i = 0; i < nfails; i++) fprintf(f, "FAIL %s\n", fails[i].text);
}

/* fmt: "%.17g" for a double, "%.9g" for a float (the shortest that reads back) */
static void json_number(FILE *f, double v, const char *fmt)
{
    if (isnan(v)) fputs("null", f);
    else if (isinf(v)) fputs(v > 0 ? "1e999" : "-1e999", f);
    else fprintf(f, fmt, v);
}

void diff_print_json(FILE *f, const char *const files[2], float r, long masked, const fs_metrics *m,
                     const diff_fail *fails, int nfails)
{
    named l[NMETRICS];
    metric_list(m, l);
    fputs("{\"a\": ", f);
    fs_json_string(f, files[0]);
    fputs(", \"b\": ", f);
    fs_json_string(f, files[1]);
    fputs(", \"r\": ", f);
    json_number(f, r, "%.9g");
    if (masked >= 0) fprintf(f, ", \"solids_masked_px\": %ld", masked);
    for (int i = 0; i < NMETRICS; i++) {
        fprintf(f, ", \"%s\": ", l[i].name);
        json_number(f, l[i].v, "%.17g");
    }
    fputs(", \"failed\": [", f);
    for (int i = 0; i < nfails; i++) {
        if (i) fputs(", ", f);
        fs_json_string(f, fails[i].text);
    }
    fputs("]}\n", f);
}
