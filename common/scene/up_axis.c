#include "up_axis.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), k = strlen(tail);
    return n >= k && !strcasecmp(s + n - k, tail);
}

/* Skewness of each coordinate: positive where the mass sits at the low end
 * and a tail (a jet, spray) reaches up. */
static void skewness(const fs_particles *p, double skew[3])
{
    const float *c[3] = {p->x, p->y, p->z};
    for (int a = 0; a < 3; a++) {
        double mean = 0, m2 = 0, m3 = 0;
        for (size_t i = 0; i < p->n; i++) mean += c[a][i];
        mean /= (double)p->n;
        for (size_t i = 0; i < p->n; i++) {
            double d = c[a][i] - mean;
            m2 += d * d;
            m3 += d * d * d;
        }
        m2 /= (double)p->n;
        m3 /= (double)p->n;
        skew[a] = m2 > 0 ? m3 / pow(m2, 1.5) : 0;
    }
}

/* Among the axes about as thin as the thinnest, the one the fluid piles up along. */
static int pick_among_thin(const float ext[3], int thinnest, const fs_particles *p, char *why, int size)
{
    int cand[3], n = 0;
    for (int a = 0; a < 3; a++)
        if (ext[a] <= FS_UP_EXTENT_TIE * ext[thinnest]) cand[n++] = a;
    if (n == 1) {
        snprintf(why, (size_t)size, "the particles' extent is smallest along it");
        return thinnest;
    }
    double skew[3];
    skewness(p, skew);
    int best = cand[0], second = -1;
    for (int k = 1; k < n; k++)
        if (skew[cand[k]] > skew[best]) best = cand[k];
    for (int k = 0; k < n; k++)
        if (cand[k] != best && (second < 0 || skew[cand[k]] > skew[second])) second = cand[k];
    if (skew[best] - skew[second] >= FS_UP_SKEW_LEAD) {
        snprintf(why, (size_t)size, "the particles pile up at its low end, skewness %.2f against %.2f", skew[best],
                 skew[second]);
        return best;
    }
    for (int k = 0; k < n; k++)
        if (cand[k] == 1) {
            snprintf(why, (size_t)size, "no axis stands out; y, the usual convention");
            return 1;
        }
    snprintf(why, (size_t)size, "the particles' extent is smallest along it");
    return thinnest;
}

int fs_up_axis_guess(const fs_particles *p, const char *path, char *why, int size)
{
    if (path && (ends_with(path, ".bgeo") || ends_with(path, ".bgeo.sc") || ends_with(path, ".geo"))) {
        snprintf(why, (size_t)size, "Houdini's convention for its files");
        return 1;
    }
    float lo[3], hi[3], ext[3];
    fs_particles_core_bounds_in(p, 0.01f, p->bmin, p->bmax, lo, hi);
    int thinnest = 0;
    for (int a = 0; a < 3; a++) {
        ext[a] = hi[a] - lo[a];
        if (ext[a] < ext[thinnest]) thinnest = a;
    }
    if (p->n < 2 || !(ext[thinnest] > 0)) {
        snprintf(why, (size_t)size, "too few particles to tell; y, the usual convention");
        return 1;
    }
    return pick_among_thin(ext, thinnest, p, why, size);
}
