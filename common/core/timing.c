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
    for (int i = 0; i < s->n; i++)
        if (!strcmp(s->name[i], name)) { s->ms[i] += ms; return; }
    if (s->n == FS_MAX_STAGES) return;
    s->name[s->n] = name;
    s->ms[s->n++] = ms;
}

double fs_stages_total(const fs_stages *s)
{
    double t = 0;
    for (int i = 0; i < s->n; i++) t += s->ms[i];
    return t;
}
