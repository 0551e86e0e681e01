#include "timing.h"
#include <math.h>
#include <string.h>
#include <time.h>

double fs_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

void fs_stages_add_gpu(fs_stages *s, const char *name, double ms, double gpu_ms)
{
    int i = 0;
    while (i < s->n && strcmp(s->name[i], name)) i++;
    if (i == FS_MAX_STAGES) { /* no row: while counting, an error, never dropped counts */
        if (fs_counting) fs_counters_no_stage(name);
        return;
    }
    if (i == s->n) {
        s->name[i] = name;
        s->ms[i] = 0;
        s->gpu_ms[i] = NAN;
        memset(s->count[i], 0, sizeof s->count[i]);
        s->n++;
    }
    s->ms[i] += ms;
    if (!isnan(gpu_ms)) s->gpu_ms[i] = isnan(s->gpu_ms[i]) ? gpu_ms : s->gpu_ms[i] + gpu_ms;
    if (fs_counting) fs_counters_attribute(s->count[i], name);
}

void fs_stages_add(fs_stages *s, const char *name, double ms) { fs_stages_add_gpu(s, name, ms, NAN); }

double fs_stages_total(const fs_stages *s)
{
    double t = 0;
    for (int i = 0; i < s->n; i++) t += s->ms[i];
    return t;
}

int fs_stages_count_total(const fs_stages *s, int c, uint64_t *total)
{
    uint64_t t = 0;
    for (int i = 0; i < s->n; i++) {
        if (t + s->count[i][c] < t) {
            *total = UINT64_MAX;
            return 1;
        }
        t += s->count[i][c];
    }
    *total = t;
    return 0;
}
