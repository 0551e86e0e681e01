#include "counters_csv.h"
#include "text_out.h"
#include <inttypes.h>
#include <string.h>

static void row(FILE *f, const char *method, const char *variant, int frame, const char *stage, int c, uint64_t v)
{
    fs_csv_text(f, method);
    fputc(',', f);
    fs_csv_text(f, variant);
    fprintf(f, ",%d,%s,%s,%" PRIu64 "\n", frame, stage, fs_counter_name(c), v);
}

uint64_t fs_counters_total(const fs_stages *st, int c)
{
    uint64_t t;
    fs_stages_count_total(st, c, &t); /* cannot wrap: fs_run_count and fs_stage_counts_parse reject such counts */
    return t;
}

void fs_counters_rows(FILE *f, const char *method, const char *variant, int frame, const fs_stages *st,
                      unsigned declared)
{
    for (int i = 0; i < st->n; i++)
        for (int c = 0; c < FS_NCOUNTERS; c++)
            if (st->count[i][c]) row(f, method, variant, frame, st->name[i], c, st->count[i][c]);
    for (int c = 0; c < FS_NCOUNTERS; c++)
        if (declared & FS_CNT_BIT(c)) row(f, method, variant, frame, "total", c, fs_counters_total(st, c));
}
