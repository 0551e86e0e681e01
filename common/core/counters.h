/* Hardware-independent work counters (docs/DESIGN.md, "Work counters"): counts
 * of a method's algorithmic work that do not depend on the machine. Code keeps
 * its counts in integer locals (per ray, tile or voxel row), mostly incremented
 * always, and adds them with fs_count_add once per thread or pass; that add is
 * a no-op unless a counting render switched counting on (fs_counting_set). So
 * a timed render pays the local increments (docs/DESIGN.md says which code
 * skips them) and one branch per fs_count_add.
 * Counts are added to a process-wide pending table; the next fs_stages_add
 * attributes what is pending to its stage. */
#ifndef FS_COUNTERS_H
#define FS_COUNTERS_H
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

/* The counters; docs/DESIGN.md defines exactly what one unit of each is. The
 * list is extensible: a new counter (a library's voxels or triangles) is one
 * enum entry and one name. Shaders get the same indices as FS_CNT_* defines. */
typedef enum fs_counter {
    FS_CNT_FIELD_EVALS = 0,
    FS_CNT_NEIGHBOURS,
    FS_CNT_MARCH_SAMPLES,
    FS_CNT_FRAGMENTS,
    FS_CNT_FILTER_TAPS,
    FS_CNT_TEXELS,
    /* a ray caster's walk: what its rays cross and how (issue 33; the reference) */
    FS_CNT_CROSSINGS,
    FS_CNT_CELLS_WALKED,
    FS_CNT_CELLS_MARCHED,
    FS_CNT_CELLS_MARCHED_INSIDE,
    FS_CNT_CELLS_PROVEN_INSIDE,
    FS_CNT_CELLS_PROVEN_OUTSIDE,
    FS_CNT_REFINE_EVALS,
    FS_CNT_INSIDE_EVALS,
    /* the compute splatter's work (issue 47; common/gl/gl_splat.h) */
    FS_CNT_SPLAT_PIXELS,
    FS_CNT_SPLAT_ATOMICS,
    FS_NCOUNTERS
} fs_counter;
#define FS_CNT_BIT(c) (1u << (c))

/* "field_evals", ... (the CSV names); NULL out of range. */
const char *fs_counter_name(int c);
/* The index of a CSV name, or -1. */
int fs_counter_index(const char *name);

/* 1 while a counting render runs. Read it directly in hot code: a plain int. */
extern int fs_counting;
void fs_counting_set(int on);

/* Adds n to counter c's pending count (atomic, 64-bit); an overflow is
 * remembered and reported by fs_counters_check. A no-op when not counting. */
void fs_count_add_(fs_counter c, uint64_t n);
static inline void fs_count_add(fs_counter c, uint64_t n)
{
    if (fs_counting && n) fs_count_add_(c, n);
}

/* A source of pending counts outside C (the GL layer's storage buffer), asked
 * before pending counts are attributed to a stage; NULL removes it. */
void fs_counters_set_collector(void (*collect)(void));

/* For fs_stages_add: moves the pending counts into row[FS_NCOUNTERS] (the
 * stage's), noting an overflow with the stage name. */
void fs_counters_attribute(uint64_t *row, const char *stage);
/* For fs_stages_add, when the stage table is full (FS_MAX_STAGES) while
 * counting: notes the error (fs_counters_check reports it); what is pending
 * stays pending, so fs_counters_unattributed sees it too. */
void fs_counters_no_stage(const char *stage);
/* After a counting render's last stage (and the GL collector's last read):
 * the bits (FS_CNT_BIT) of the counters that still hold pending counts or a
 * pending overflow, which no stage took. */
unsigned fs_counters_unattributed(void);
/* Drops pending counts and a noted overflow (before a counting render). */
void fs_counters_reset(void);
/* FS_OK, or FS_ERR_RUNTIME (fs_fail) naming the counter and stage that
 * overflowed, or the stage that found the stage table full. */
int fs_counters_check(void);

/* Marks an overflow of counter c (a GL counter's high word wrapped). */
void fs_counters_overflowed(fs_counter c);

#ifdef __cplusplus
}
#endif
#endif
