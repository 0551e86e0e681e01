#include "pca_normal.h"
#include "eigen3.h"
#include "kernels.h"
#include "vec3.h"
#include <math.h>

int rpca_basic_normal(const float x[3], const float *pts, int n, float R, float out[3])
{
    out[0] = out[1] = out[2] = 0;
    for (int j = 0; j < n; j++) {
        float e[3] = {x[0] - pts[3 * j], x[1] - pts[3 * j + 1], x[2] - pts[3 * j + 2]};
        float d = fs_v3_len(e);
        if (d >= R || d <= 0) continue;
        float g = fs_spiky_dw(d, R) / d; /* grad_x W = W'(d) e / d, pointing inwards */
        for (int a = 0; a < 3; a++) out[a] -= g * e[a];
    }
    return fs_v3_normalize(out);
}

int rpca_pca_normal(const float x[3], const float *pts, int n, float R, int min_n, float out[3])
{
    double ws = 0, m[3] = {0, 0, 0};
    int cnt = 0;
    for (int j = 0; j < n; j++) {
        const float *p = pts + 3 * j;
        float e[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
        double q = sqrt((double)e[0] * e[0] + (double)e[1] * e[1] + (double)e[2] * e[2]) / R;
        if (q >= 1) continue;
        double w = 1 - q * q * q;
        ws += w;
        cnt++;
        for (int a = 0; a < 3; a++) m[a] += w * p[a];
    }
    out[0] = out[1] = out[2] = 0;
    if (cnt < min_n || cnt < 3 || !(ws > 0)) return 0;
    for (int a = 0; a < 3; a++) m[a] /= ws;
    double c[9] = {0};
    for (int j = 0; j < n; j++) {
        const float *p = pts + 3 * j;
        float e[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
        double q = sqrt((double)e[0] * e[0] + (double)e[1] * e[1] + (double)e[2] * e[2]) / R;
        if (q >= 1) continue;
        double w = 1 - q * q * q, u[3] = {p[0] - m[0], p[1] - m[1], p[2] - m[2]};
        for (int a = 0; a < 3; a++)
            for (int b = a; b < 3; b++) c[3 * a + b] += w * u[a] * u[b];
    }
    for (int i = 0; i < 9; i++) c[i] /= ws;
    double ev[3], vec[9];
    fs_eigen3_sym(c, ev, vec);
    /* Rank < 2: the middle eigenvalue vanishes next to the largest. */
    if (!(ev[2] > 0) || ev[1] <= 1e-4 * ev[2]) return 0;
    for (int a = 0; a < 3; a++) out[a] = (float)vec[a];
    return fs_v3_normalize(out);
}

float rpca_blend_weight(const rpca_normal_opts *o, const float b[3], const float p[3])
{
    if (o->fixed_weight) return o->w_fixed;
    float dot = b[0] * p[0] + b[1] * p[1] + b[2] * p[2];
    float w = expf(o->d * (dot - o->k));
    return w < 1 ? w : 1;
}

int rpca_normal(const float x[3], const float *pts, int n, const rpca_normal_opts *o, float out[3])
{
    float b[3], p[3];
    if (!rpca_basic_normal(x, pts, n, o->R, b)) {
        out[0] = out[1] = out[2] = 0;
        return -1;
    }
    if (o->mode == RPCA_NORMALS_BASIC || !rpca_pca_normal(x, pts, n, o->R, o->min_neighbors, p)) {
        for (int a = 0; a < 3; a++) out[a] = b[a];
        return 0;
    }
    if (b[0] * p[0] + b[1] * p[1] + b[2] * p[2] < 0)
        for (int a = 0; a < 3; a++) p[a] = -p[a]; /* the sign that agrees with the basic normal */
    if (o->mode == RPCA_NORMALS_PCA) {
        for (int a = 0; a < 3; a++) out[a] = p[a];
        return 1;
    }
    float w = rpca_blend_weight(o, b, p);
    for (int a = 0; a < 3; a++) out[a] = (1 - w) * b[a] + w * p[a];
    if (!fs_v3_normalize(out))
        for (int a = 0; a < 3; a++) out[a] = b[a];
    return 1;
}
