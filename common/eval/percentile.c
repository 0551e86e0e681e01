/* Nearest-rank percentiles by quickselect (percentile.h). */
#include "percentile.h"
#include <math.h>

/* Median of three, the pivot of one partition step. */
static double median3(double p0, double p1, double p2)
{
    return p0 < p1 ? (p1 < p2 ? p1 : (p0 < p2 ? p2 : p0)) : (p0 < p2 ? p0 : (p1 < p2 ? p2 : p1));
}

double fs_percentile(double *v, size_t n, int pct)
{
    if (n == 0 || pct < 1 || pct > 100) return NAN;
    for (size_t i = 0; i < n; i++)
        if (isnan(v[i])) return NAN;
    ptrdiff_t k = (ptrdiff_t)(((size_t)pct * n + 99) / 100) - 1;
    ptrdiff_t lo = 0, hi = (ptrdiff_t)n - 1;
    while (lo < hi) { /* Hoare partition around a median of three */
        double pivot = median3(v[lo], v[lo + (hi - lo) / 2], v[hi]);
        ptrdiff_t i = lo, j = hi;
        while (i <= j) {
            while (v[i] < pivot) i++;
            while (v[j] > pivot) j--;
            if (i <= j) {
                double t = v[i];
                v[i++] = v[j];
                v[j--] = t;
            }
        }
        /* now v[lo..j] <= pivot, v[i..hi] >= pivot, v[j+1..i-1] == pivot */
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return v[k];
    }
    return v[k];
}
