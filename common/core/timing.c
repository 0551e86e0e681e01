#include "timing.h"
#include <string.h>
#include <time.h>

double fs_now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

void fs_stages_add(fs_stages *s, const char *name, double ms)
{
    int i = 0;
    while (i < s->n && strcmp(s->name[i], name)) i++;
    if (i == FS_MAX_STAGES) return;
    if (i == s->n) { s->name[s->n++] = name; s->ms[i] = 0; memset(s->count[i], 0, sizeof s->count[i]); }
    s->ms[i] += ms;
    if (fs_counting) fs_counters_attribute(s->count[i], name);
}

double fs_stages_total(const fs_stages *s)
{
    double t = 0;
    for (int i = 0; i < s->n; i++) t += s->ms[i];
    return t;
}
