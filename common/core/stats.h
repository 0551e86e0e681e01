/* Small statistics helpers shared by the harness. */
#ifndef FS_STATS_H
#define FS_STATS_H
#ifdef __cplusplus
extern "C" {
#endif

/* Median of n values (the array is sorted in place); NAN when n == 0. */
double fs_median(double *v, int n);
/* A "nice" upper bound for a colour scale: the smallest 1, 2 or 5 x 10^k >= x (x > 0). */
double fs_nice_ceil(double x);

#ifdef __cplusplus
}
#endif
#endif
