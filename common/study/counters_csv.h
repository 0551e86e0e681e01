/* counters.csv rows (docs/DESIGN.md, "Work counters"), shared by `render
 * --counters` (stdout) and `compare --counters` (DIR/counters.csv). */
#ifndef FS_COUNTERS_CSV_H
#define FS_COUNTERS_CSV_H
#include "timing.h"
#include <stdio.h>

#define FS_COUNTERS_HEADER "method,variant,frame,stage,counter,value\n"

/* One row per stage and counter it counted (zero counts are left out), then a
 * "total" row for every counter in declared (FS_CNT_BIT mask), zero or not. */
void fs_counters_rows(FILE *f, const char *method, const char *variant, int frame, const fs_stages *st,
                      unsigned declared);
/* The sum of counter c over st's stages. */
uint64_t fs_counters_total(const fs_stages *st, int c);

#endif
