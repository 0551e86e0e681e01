#include "counters.h"
#include "fs_error.h"
#include "timing.h"
#include <stdio.h>
#include <string.h>

static const char *const names[FS_NCOUNTERS] = {
    "field_evals",   "neighbours_visited",   "march_samples",       "fragments_shaded",
    "filter_taps",   "texels_written",       "crossings",           "cells_walked",
    "cells_marched", "cells_marched_inside", "cells_proven_inside", "cells_proven_outside",
    "refine_evals",  "inside_evals",         "splat_pixels",        "splat_atomics"};

const char *fs_counter_name(int c) { return c >= 0 && c < FS_NCOUNTERS ? names[c] : NULL; }

int fs_counter_index(const char *name)
{
    for (int c = 0; c < FS_NCOUNTERS; c++)
        if (!strcmp(names[c], name)) return c;
    return -1;
}

int fs_counting;
static uint64_t pending[FS_NCOUNTERS];
static unsigned pending_over; /* bits: counters whose pending sum wrapped */
static char over_msg[200];    /* the first error: an overflow with its stage, or a full stage table */
static void (*collector)(void);

void fs_counting_set(int on) { fs_counting = on; }
void fs_counters_set_collector(void (*collect)(void)) { collector = collect; }

void fs_count_add_(fs_counter c, uint64_t n)
{
    uint64_t old = __atomic_fetch_add(&pending[c], n, __ATOMIC_RELAXED);
    if (old + n < old) __atomic_fetch_or(&pending_over, FS_CNT_BIT(c), __ATOMIC_RELAXED);
}

void fs_counters_overflowed(fs_counter c) { __atomic_fetch_or(&pending_over, FS_CNT_BIT(c), __ATOMIC_RELAXED); }

static void note_overflow(int c, const char *stage)
{
    if (!over_msg[0])
        snprintf(over_msg, sizeof over_msg, "work counter %s overflowed 2^64 in stage %s", names[c], stage);
}

void fs_counters_no_stage(const char *stage)
{
    if (!over_msg[0])
        snprintf(over_msg, sizeof over_msg, "work counts of stage %s have no row: a run has at most %d stages", stage,
                 FS_MAX_STAGES);
}

unsigned fs_counters_unattributed(void)
{
    unsigned bits = __atomic_load_n(&pending_over, __ATOMIC_RELAXED);
    for (int c = 0; c < FS_NCOUNTERS; c++)
        if (__atomic_load_n(&pending[c], __ATOMIC_RELAXED)) bits |= FS_CNT_BIT(c);
    return bits;
}

void fs_counters_attribute(uint64_t *row, const char *stage)
{
    if (collector) collector();
    for (int c = 0; c < FS_NCOUNTERS; c++) {
        uint64_t n = __atomic_exchange_n(&pending[c], 0, __ATOMIC_RELAXED);
        if (pending_over & FS_CNT_BIT(c) || row[c] + n < row[c]) note_overflow(c, stage);
        row[c] += n;
    }
    pending_over = 0;
}

void fs_counters_reset(void)
{
    for (int c = 0; c < FS_NCOUNTERS; c++) pending[c] = 0;
    pending_over = 0;
    over_msg[0] = 0;
}

int fs_counters_check(void)
{
    if (!over_msg[0]) return FS_OK;
    return fs_fail(FS_ERR_RUNTIME, "%s", over_msg);
}
