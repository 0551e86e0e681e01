/* Per-stage wall-clock timings. GL stages are bracketed with glFinish() by the
 * caller (llvmpipe timer queries are not trustworthy, docs/DESIGN.md). */
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
    /* work counts per stage, filled only while counting (counters.h) */
    uint64_t count[FS_MAX_STAGES][FS_NCOUNTERS];
} fs_stages;

double fs_now_ms(void); /* CLOCK_MONOTONIC in milliseconds */
/* Adds ms to the stage called name (created on first use; names are static
 * strings); while counting, also the pending work counts. */
void fs_stages_add(fs_stages *s, const char *name, double ms);
double fs_stages_total(const fs_stages *s);

#ifdef __cplusplus
}
#endif
#endif
