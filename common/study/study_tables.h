/* The study's results tables as CSV text (docs/DESIGN.md, "The study layer"):
 * a provenance line ("# fluidsurf:..."), a header, one row per item.
 *   metrics   method, variant, one column per swept parameter, reference, frame,
 *             the metrics (metrics.h), frame_ms, ...
 *   timings   per stage: median, min and max over the timed runs, renderer
 *   temporal  per variant of a sequence: normal change and temporal errors
 *   counters  per stage and counter of each counting render
 * compare writes each as DIR/NAME.csv; the library and Python return the text. */
#ifndef FS_STUDY_TABLES_H
#define FS_STUDY_TABLES_H
#include "study.h"
#include <stdio.h>

/* The numbers of a metrics row after its labels, in the columns' order: the metrics of
 * metrics.h, then frame_ms (written once for the table and compare's report). */
#define FS_STUDY_ROW_VALUES 10
void fs_study_row_values(const fs_metrics *m, double frame_ms, double v[FS_STUDY_ROW_VALUES]);

/* Table name of s into f; FS_ERR_INPUT for an unknown name. */
int fs_study_write_table(const fs_study *s, const char *name, FILE *f);

#endif
