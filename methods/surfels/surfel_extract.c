/* Surfel extraction: edge crossings of the iso value, normals from the density
 * gradient, extra surfels where a cell's crossings are spread wide. Planes are
 * extracted in parallel into per-plane sets and concatenated in order. */
#include "surfel_extract.h"
#include "fs_error.h"
#include "vec3.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static float at(const fs_density_grid *g, int i, int j, int k) { return g->data[fs_density_grid_index(g, i, j, k)]; }

/* d phi / d axis at a grid point: central differences, one-sided on the border. */
static float grad_axis(const fs_density_grid *g, const int c[3], int a)
{
    int lo[3] = {c[0], c[1], c[2]}, hi[3] = {c[0], c[1], c[2]};
    if (c[a] > 0) lo[a]--;
    if (c[a] < g->dim[a] - 1) hi[a]++;
    if (hi[a] == lo[a]) return 0.0f;
    return (at(g, hi[0], hi[1], hi[2]) - at(g, lo[0], lo[1], lo[2])) / ((hi[a] - lo[a]) * g->spacing);
}

static void grad_point(const fs_density_grid *g, const int c[3], float out[3])
{
    for (int a = 0; a < 3; a++) out[a] = grad_axis(g, c, a);
}

/* Trilinear gradient at a world position: the grid-point gradients interpolated. */
static void grad_at(const fs_density_grid *g, const float x[3], float out[3])
{
    float u[3];
    int c0[3];
    for (int a = 0; a < 3; a++) {
        float t = (x[a] - g->origin[a]) / g->spacing;
        int i = (int)floorf(t);
        i = i < 0 ? 0 : (i > g->dim[a] - 2 ? g->dim[a] - 2 : i);
        c0[a] = i;
        u[a] = fminf(fmaxf(t - i, 0.0f), 1.0f);
    }
    out[0] = out[1] = out[2] = 0;
    for (int corner = 0; corner < 8; corner++) {
        int c[3] = {c0[0] + (corner & 1), c0[1] + ((corner >> 1) & 1), c0[2] + ((corner >> 2) & 1)};
        float w = ((corner & 1) ? u[0] : 1 - u[0]) * (((corner >> 1) & 1) ? u[1] : 1 - u[1]) *
            (((corner >> 2) & 1) ? u[2] : 1 - u[2]);
        float gp[3];
        grad_point(g, c, gp);
        for (int a = 0; a < 3; a++) out[a] += w * gp[a];
    }
}

/* Unit outward normal (-grad phi); 0 when the gradient vanishes. */
static void outward(const float grad[3], float n[3])
{
    float l = fs_v3_len(grad);
    for (int a = 0; a < 3; a++) n[a] = l > 0 ? -grad[a] / l : 0.0f;
}

/* Crossing on the edge from grid point c along axis a, if the values straddle iso. */
static int edge_crossing(const fs_density_grid *g, const int c[3], int a, float iso, float pos[3], float n[3])
{
    int d[3] = {c[0], c[1], c[2]};
    d[a]++;
    float v0 = at(g, c[0], c[1], c[2]), v1 = at(g, d[0], d[1], d[2]);
    if ((v0 >= iso) == (v1 >= iso)) return 0;
    float t = (iso - v0) / (v1 - v0), g0[3], g1[3], gr[3];
    grad_point(g, c, g0);
    grad_point(g, d, g1);
    for (int k = 0; k < 3; k++) {
        pos[k] = g->origin[k] + g->spacing * (c[k] + (k == a ? t : 0.0f));
        gr[k] = g0[k] + t * (g1[k] - g0[k]);
    }
    outward(gr, n);
    return 1;
}

/* The 12 edges of a cell: start corner offset and axis. */
static const int CELL_EDGES[12][4] = {
    {0, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 1, 1, 0}, {0, 0, 0, 1}, {1, 0, 0, 1},
    {0, 0, 1, 1}, {1, 0, 1, 1}, {0, 0, 0, 2}, {1, 0, 0, 2}, {0, 1, 0, 2}, {1, 1, 0, 2},
};

/* Gap filling for cell c: the crossings' centroid, pulled onto the surface. */
static int fill_gap(const fs_density_grid *g, const int c[3], const fs_surfel_extract_opts *o, float radius,
                    fs_surfel_set *out, size_t *added)
{
    int above = 0;
    for (int corner = 0; corner < 8; corner++)
        above += at(g, c[0] + (corner & 1), c[1] + ((corner >> 1) & 1), c[2] + ((corner >> 2) & 1)) >= o->iso;
    if (above == 0 || above == 8) return FS_OK; /* no crossing: most cells */
    float pts[12][3], nrm[3], ctr[3] = {0, 0, 0};
    int m = 0;
    for (int e = 0; e < 12; e++) {
        int s[3] = {c[0] + CELL_EDGES[e][0], c[1] + CELL_EDGES[e][1], c[2] + CELL_EDGES[e][2]};
        if (edge_crossing(g, s, CELL_EDGES[e][3], o->iso, pts[m], nrm)) {
            for (int k = 0; k < 3; k++) ctr[k] += pts[m][k];
            m++;
        }
    }
    if (m == 0) return FS_OK;
    for (int k = 0; k < 3; k++) ctr[k] /= m;
    float spread = 0;
    for (int q = 0; q < m; q++) {
        float dx = pts[q][0] - ctr[0], dy = pts[q][1] - ctr[1], dz = pts[q][2] - ctr[2];
        spread = fmaxf(spread, sqrtf(dx * dx + dy * dy + dz * dz));
    }
    if (spread <= o->gap * g->spacing) return FS_OK;
    /* Newton steps along the gradient: phi(x + s grad) = iso to first order. */
    float gr[3];
    for (int it = 0; it < 3; it++) {
        grad_at(g, ctr, gr);
        float gg = gr[0] * gr[0] + gr[1] * gr[1] + gr[2] * gr[2];
        if (!(gg > 0)) return FS_OK;
        float s = (o->iso - fs_density_grid_sample(g, ctr)) / gg;
        float step = fminf(fmaxf(s * sqrtf(gg), -g->spacing), g->spacing); /* stay within the cell's reach */
        float l = sqrtf(gg);
        for (int k = 0; k < 3; k++) ctr[k] += step * gr[k] / l;
    }
    grad_at(g, ctr, gr);
    outward(gr, nrm);
    if (nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0) return FS_OK;
    (*added)++;
    return fs_surfel_push(out, ctr, nrm, radius);
}

int fs_surfels_extract(const fs_density_grid *g, const fs_surfel_extract_opts *o, fs_surfel_set *out, size_t *gap_added)
{
    out->n = 0;
    if (gap_added) *gap_added = 0;
    int nk = g->dim[2];
    fs_surfel_set *planes = calloc((size_t)nk, sizeof *planes);
    size_t *added = calloc((size_t)nk, sizeof *added);
    if (!planes || !added) {
        free(planes);
        free(added);
        return fs_fail(FS_ERR_RUNTIME, "out of memory extracting surfels");
    }
    float radius = o->radius_scale * g->spacing;
    int failed = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(| : failed)
    for (int k = 0; k < nk; k++) {
        for (int j = 0; j < g->dim[1] && !failed; j++)
            for (int i = 0; i < g->dim[0]; i++) {
                int c[3] = {i, j, k};
                float pos[3], n[3];
                for (int a = 0; a < 3; a++)
                    if (c[a] + 1 < g->dim[a] && edge_crossing(g, c, a, o->iso, pos, n) &&
                        fs_surfel_push(&planes[k], pos, n, radius))
                        failed = 1;
                if (o->gap > 0 && i + 1 < g->dim[0] && j + 1 < g->dim[1] && k + 1 < nk &&
                    fill_gap(g, c, o, radius, &planes[k], &added[k]))
                    failed = 1;
            }
    }
    int rc = failed ? FS_ERR_RUNTIME : FS_OK;
    for (int k = 0; k < nk && !rc; k++) {
        for (size_t q = 0; q < planes[k].n && !rc; q++)
            rc = fs_surfel_push(out, planes[k].s[q].pos, planes[k].s[q].normal, planes[k].s[q].radius);
        if (gap_added) *gap_added += added[k];
    }
    for (int k = 0; k < nk; k++) fs_surfel_set_free(&planes[k]);
    free(planes);
    free(added);
    return rc;
}
