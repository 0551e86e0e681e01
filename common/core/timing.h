/* Per-stage wall-clock timings, and for GL stages the GL's own clock beside them
 * (gl_stage.h). Wall times are bracketed with glFinish(): llvmpipe's timer
 * queries are not trustworthy (docs/DESIGN.md), a real GPU's are. */
#ifndef FS_TIMING_H
#define FS_TIMING_H
#include "counters.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_MAX_STAGES 16

typedef struct fs_stages {
    int n;
    const char *name[FS_MAX_STAGES];
    double ms[FS_MAX_STAGES];
    double gpu_ms[FS_MAX_STAGES]; /* GL timestamp difference; NaN for a stage without one */
    /* work counts per stage, filled only while counting (counters.h) */
    uint64_t count[FS_MAX_STAGES][FS_NCOUNTERS];
} fs_stages;

double fs_now_ms(void); /* CLOCK_MONOTONIC in milliseconds */
/* Adds ms to the stage called name (created on first use; names are static
 * strings); while counting, also the pending work counts. */
void fs_stages_add(fs_stages *s, const char *name, double ms);
/* The same, with the GL clock's time of the stage (NaN: none; kept NaN until one comes). */
void fs_stages_add_gpu(fs_stages *s, const char *name, double ms, double gpu_ms);
double fs_stages_total(const fs_stages *s);
/* The sum of work counter c over the stages into *total: 0, or 1 when it wraps
 * 2^64 (*total is then UINT64_MAX). Every total of counts is made here. */
int fs_stages_count_total(const fs_stages *s, int c, uint64_t *total);

#ifdef __cplusplus
}
#endif
#endif
