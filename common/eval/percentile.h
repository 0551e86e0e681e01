/* Nearest-rank percentiles of the metrics (docs/DESIGN.md, "Metrics"). */
#ifndef FS_PERCENTILE_H
#define FS_PERCENTILE_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* The nearest-rank pct-th percentile of v[0..n): the ceil(pct n / 100)-th smallest
 * value (1-based; pct 50 of an even n is the lower middle value), pct in 1..100.
 * Reorders v (quickselect, O(n) expected), so several percentiles of one array
 * may be taken in turn. NAN when n == 0 or any value is NaN. */
double fs_percentile(double *v, size_t n, int pct);

#ifdef __cplusplus
}
#endif
#endif
