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

/* The share of p within band of each axis's low end, and how many. */
static void low_end_shares(const fs_particles *p, const float low[3], float band, double share[3], size_t count[3])
{
    const float *c[3] = {p->x, p->y, p->z};
    for (int a = 0; a < 3; a++) {
        size_t k = 0;
        for (size_t i = 0; i < p->n; i++) k += c[a][i] <= low[a] + band;
        count[a] = k;
        share[a] = p->n ? (double)k / (double)p->n : 0;
    }
}

void fs_up_low_end_shares(const fs_particles *p, float r, double share[3])
{
    float low[3], high[3];
    size_t count[3];
    fs_particles_core_bounds_in(p, 0.001f, p->bmin, p->bmax, low, high);
    low_end_shares(p, low, FS_UP_FLOOR_BAND * r, share, count);
}

/* The axis along which clearly more particles sit at the low end than along
 * any other (a fluid spread on its floor), or -1. */
static int floor_by_share(const fs_particles *p, const float low[3], float r, char *why, int size)
{
    double share[3];
    size_t count[3];
    low_end_shares(p, low, FS_UP_FLOOR_BAND * r, share, count);
    int best = 0;
    for (int a = 1; a < 3; a++)
        if (share[a] > share[best]) best = a;
    int next = best == 0 ? 1 : 0;
    for (int a = 0; a < 3; a++)
        if (a != best && share[a] > share[next]) next = a;
    if (count[best] < FS_UP_FLOOR_MIN || share[best] < FS_UP_FLOOR_LEAD * share[next]) return -1;
    snprintf(why, (size_t)size,
             "a floor: %.1f%% of the particles lie within r of its low end, %.2f times the %.1f%% along %c",
             100 * share[best], share[best] / share[next], 100 * share[next], 'x' + next);
    return best;
}

/* Whether the 1%..99% box is centred on 0 along the axis. */
static int centred(float lo, float hi) { return fabsf(lo + hi) <= 2 * FS_UP_CENTRED * (hi - lo); }

/* The one axis whose low end lies at 0 while the other two are centred on 0
 * (an object stood on a ground plane), or -1. */
static int floor_at_zero(const float low[3], const float lo[3], const float hi[3], float r, char *why, int size)
{
    int found = -1;
    for (int a = 0; a < 3; a++) {
        int b = (a + 1) % 3, c = (a + 2) % 3;
        if (fabsf(low[a]) <= FS_UP_ZERO_BAND * r && !centred(lo[a], hi[a]) && centred(lo[b], hi[b]) &&
            centred(lo[c], hi[c]))
            found = a;
    }
    if (found >= 0)
        snprintf(why, (size_t)size, "a floor at 0: its low end lies %.2g r from 0, and the other axes are centred on 0",
                 fabsf(low[found]) / r);
    return found;
}

/* The floor, by its share or at 0; -1 when there is no sign of one. */
static int floor_axis(const fs_particles *p, const float lo[3], const float hi[3], float r, char *why, int size)
{
    if (!(r > 0)) return -1;
    float low[3], high[3];
    fs_particles_core_bounds_in(p, 0.001f, p->bmin, p->bmax, low, high);
    int a = floor_by_share(p, low, r, why, size);
    return a >= 0 ? a : floor_at_zero(low, lo, hi, r, why, size);
}

static int is_houdini(const char *path)
{
    return path && (ends_with(path, ".bgeo") || ends_with(path, ".bgeo.sc") || ends_with(path, ".geo"));
}

int fs_up_axis_guess(const fs_particles *p, const char *path, float r, char *why, int size)
{
    float lo[3], hi[3], ext[3];
    fs_particles_core_bounds_in(p, 0.01f, p->bmin, p->bmax, lo, hi);
    int thinnest = 0;
    for (int a = 0; a < 3; a++) {
        ext[a] = hi[a] - lo[a];
        if (ext[a] < ext[thinnest]) thinnest = a;
    }
    int floor = p->n < 2 ? -1 : floor_axis(p, lo, hi, r, why, size);
    if (floor >= 0) return floor;
    if (is_houdini(path)) {
        snprintf(why, (size_t)size, "Houdini's convention for its files");
        return 1;
    }
    if (p->n < 2 || !(ext[thinnest] > 0)) {
        snprintf(why, (size_t)size, "too few particles to tell; y, the usual convention");
        return 1;
    }
    return pick_among_thin(ext, thinnest, p, why, size);
}
