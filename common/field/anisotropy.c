/* Yu & Turk 2013 anisotropy (anisotropy.h). Sums run relative to the point in
 * double precision; the GLSL version does the same algebra in float. */
#include "anisotropy.h"
#include "counters.h"
#include "eigen3.h"
#include "fs_error.h"
#include <math.h>
#include <string.h>

double fs_aniso_sigma_ref(fs_kernel k, float radius, float spacing)
{
    int m = (int)ceil(radius / spacing);
    double sw = 0, sxx = 0;
    for (int i = -m; i <= m; i++)
        for (int j = -m; j <= m; j++)
            for (int l = -m; l <= m; l++) {
                double x = i * (double)spacing, y = j * (double)spacing, z = l * (double)spacing;
                double w = fs_kernel_w(k, (float)sqrt(x * x + y * y + z * z), radius);
                sw += w;
                sxx += w * x * x;
            }
    return sw > 0 ? sxx / sw : 0;
}

void fs_aniso_defaults(fs_aniso_params *ap, fs_kernel k, float r)
{
    ap->kernel = k;
    ap->radius = (float)FS_ANISO_RADIUS_R * r;
    ap->kappa = (float)FS_ANISO_KAPPA;
    ap->n_eps = FS_ANISO_N_EPS;
    ap->scale = (float)FS_ANISO_SCALE;
    ap->lambda = (float)FS_ANISO_LAMBDA;
    ap->per_particle = FS_ANISO_PER_PARTICLE;
    ap->sigma_ref = (float)fs_aniso_sigma_ref(k, ap->radius, 2 * r);
}

typedef struct acc {
    const fs_grid *g;
    const fs_aniso_params *ap;
    double x[3], sw, se[3], see[6];
    int n;
} acc;

static void visit(void *user, uint32_t slot, float dist2)
{
    acc *a = user;
    const float *q = a->g->pos4 + 4 * (size_t)slot;
    float d = sqrtf(dist2);
    if (d >= a->ap->radius) return;
    double w = fs_kernel_w(a->ap->kernel, d, a->ap->radius);
    double e[3] = {q[0] - a->x[0], q[1] - a->x[1], q[2] - a->x[2]};
    if (dist2 > 0) a->n++;
    a->sw += w;
    for (int k = 0; k < 3; k++) a->se[k] += w * e[k];
    a->see[0] += w * e[0] * e[0];
    a->see[1] += w * e[0] * e[1];
    a->see[2] += w * e[0] * e[2];
    a->see[3] += w * e[1] * e[1];
    a->see[4] += w * e[1] * e[2];
    a->see[5] += w * e[2] * e[2];
}

/* fs_aniso_point; *tested gets the particles whose distance the query computed. */
static int aniso_point(const fs_grid *g, const float x[3], const fs_aniso_params *ap, float centre[3], float A[9],
                       size_t *tested)
{
    acc a = {g, ap, {x[0], x[1], x[2]}, 0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}, 0};
    *tested = fs_grid_query(g, x, ap->radius, visit, &a);
    memset(A, 0, 9 * sizeof *A);
    A[0] = A[4] = A[8] = 1;
    for (int k = 0; k < 3; k++) centre[k] = x[k];
    if (!(a.sw > 0)) return a.n;
    /* eq. 5: w_ij = W_ij / sum W; weighted mean relative to x; eq. 6 covariance. */
    double m[3] = {a.se[0] / a.sw, a.se[1] / a.sw, a.se[2] / a.sw};
    for (int k = 0; k < 3; k++) centre[k] = (float)(x[k] + ap->lambda * m[k]); /* Yu & Turk eq. 6 */
    if (a.n <= ap->n_eps) return a.n;
    double C[9];
    C[0] = a.see[0] / a.sw - m[0] * m[0];
    C[1] = C[3] = a.see[1] / a.sw - m[0] * m[1];
    C[2] = C[6] = a.see[2] / a.sw - m[0] * m[2];
    C[4] = a.see[3] / a.sw - m[1] * m[1];
    C[5] = C[7] = a.see[4] / a.sw - m[1] * m[2];
    C[8] = a.see[5] / a.sw - m[2] * m[2];
    double ev[3], V[9];
    fs_eigen3_sym(C, ev, V); /* ascending: ev[2] is sigma_1 */
    double s[3];
    for (int k = 0; k < 3; k++)
        s[k] = ev[k] > ev[2] / ap->kappa ? ev[k] : ev[2] / ap->kappa; /* max(sigma_k, sigma_1/kappa) */
    double norm = ap->per_particle ? cbrt(s[0] * s[1] * s[2]) : ap->sigma_ref;
    for (int k = 0; k < 3; k++) s[k] *= ap->scale / norm;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double v = 0;
            for (int k = 0; k < 3; k++) v += s[k] * V[3 * k + i] * V[3 * k + j];
            A[3 * i + j] = (float)v;
        }
    return a.n;
}

int fs_aniso_point(const fs_grid *g, const float x[3], const fs_aniso_params *ap, float centre[3], float A[9])
{
    size_t tested;
    return aniso_point(g, x, ap, centre, A, &tested);
}

int fs_aniso_compute(const fs_particles *p, const fs_grid *g, const fs_aniso_params *ap, float *centre, float *A,
                     float *max_axis)
{
    if (!(ap->radius > 0) || !(ap->kappa >= 1) || !(ap->scale > 0) || !(ap->sigma_ref > 0))
        return fs_fail(FS_ERR_INPUT, "anisotropy: radius %g, kappa %g, scale %g must be positive (kappa >= 1)",
                       ap->radius, ap->kappa, ap->scale);
    if (g->n != p->n) return fs_fail(FS_ERR_RUNTIME, "anisotropy: grid holds %zu particles, the set %zu", g->n, p->n);
    float mx = 1;
    long n = (long)p->n;
    uint64_t visits = 0; /* work counters: the neighbours looked at */
#pragma omp parallel for schedule(dynamic, 256) reduction(max : mx) reduction(+ : visits)
    for (long i = 0; i < n; i++) {
        float x[3] = {p->x[i], p->y[i], p->z[i]}, *Ai = A + 9 * i;
        size_t tested;
        aniso_point(g, x, ap, centre + 3 * i, Ai, &tested);
        visits += tested;
        /* Largest axis: the largest eigenvalue, bounded by the Frobenius norm. */
        float f = 0;
        for (int k = 0; k < 9; k++) f += Ai[k] * Ai[k];
        f = sqrtf(f);
        if (f > mx) mx = f;
    }
    if (max_axis) *max_axis = mx;
    fs_count_add(FS_CNT_NEIGHBOURS, visits);
    return FS_OK;
}
