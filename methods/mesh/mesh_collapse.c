/* Collapsing degenerate faces (mesh_collapse.h). */
#include "mesh_collapse.h"
#include "fs_error.h"
#include "vec3.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct work {
    uint32_t *parent; /* union-find over the vertices */
    double *acc;      /* per root: summed position and member count */
    uint32_t *index;  /* per vertex: joined in this round (0/1), then its new index or UINT32_MAX when unused */
    size_t *touched;  /* faces with a merged corner */
} work;

typedef struct face_key {
    uint32_t k[3]; /* the corners, sorted */
    int odd;       /* 1 when the winding is the reverse of the sorted order */
    size_t t;
} face_key;

static uint32_t find(uint32_t *parent, uint32_t v)
{
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

/* Joins a and b when neither was joined in this round (taken: 0 or 1 per
 * vertex), so a round merges pairs and moves a vertex at most half an edge. */
static void join(uint32_t *parent, uint32_t *taken, uint32_t a, uint32_t b)
{
    if (taken[a] || taken[b] || a == b) return;
    parent[a > b ? a : b] = a < b ? a : b;
    taken[a] = taken[b] = 1;
}

/* Joins the ends of face t's shortest edge when its smallest height (twice its
 * area over its longest edge) is below eps (unless one of them was joined
 * already in this round); 1 when the face is degenerate. */
static int join_if_degenerate(const fs_trimesh *m, size_t t, double eps, work *w)
{
    const uint32_t *c = m->tri + 3 * t;
    double e[3][3], len[3];
    for (int i = 0; i < 3; i++) {
        const float *a = m->pos + 3 * (size_t)c[i], *b = m->pos + 3 * (size_t)c[(i + 1) % 3];
        for (int k = 0; k < 3; k++) e[i][k] = (double)b[k] - a[k];
        len[i] = fs_v3d_len(e[i]);
    }
    double x[3];
    fs_v3d_cross(e[0], e[1], x);
    double area2 = fs_v3d_len(x);
    double longest = fmax(len[0], fmax(len[1], len[2]));
    if (longest > 0 && area2 / longest >= eps) return 0;
    int s = len[0] <= len[1] && len[0] <= len[2] ? 0 : len[1] <= len[2] ? 1 : 2; /* edge s joins corners s, s+1 */
    join(w->parent, w->index, c[s], c[(s + 1) % 3]);
    return 1;
}

/* Moves each root to its pair's mean; acc keeps each root's member count. */
static void merge_positions(fs_trimesh *m, work *w)
{
    memset(w->acc, 0, m->nv * 4 * sizeof *w->acc);
    for (size_t v = 0; v < m->nv; v++) {
        double *a = w->acc + 4 * (size_t)find(w->parent, (uint32_t)v);
        for (int k = 0; k < 3; k++) a[k] += m->pos[3 * v + k];
        a[3] += 1;
    }
    for (size_t v = 0; v < m->nv; v++)
        if (w->parent[v] == v && w->acc[4 * v + 3] > 1)
            for (int k = 0; k < 3; k++) m->pos[3 * v + k] = (float)(w->acc[4 * v + k] / w->acc[4 * v + 3]);
}

/* Corners renamed to their roots; faces with two equal corners dropped; the
 * faces left that have a merged corner listed in w->touched. Returns their count. */
static size_t remap_faces(fs_trimesh *m, work *w, size_t *removed)
{
    size_t n = 0, nt = 0;
    for (size_t t = 0; t < m->nt; t++) {
        uint32_t c[3];
        int merged = 0;
        for (int i = 0; i < 3; i++) {
            c[i] = find(w->parent, m->tri[3 * t + i]);
            merged |= w->acc[4 * (size_t)c[i] + 3] > 1;
        }
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) {
            (*removed)++;
            continue;
        }
        memcpy(m->tri + 3 * nt, c, sizeof c);
        if (merged) w->touched[n++] = nt;
        nt++;
    }
    m->nt = nt;
    return n;
}

static int cmp_key(const void *pa, const void *pb)
{
    const face_key *a = pa, *b = pb;
    for (int i = 0; i < 3; i++)
        if (a->k[i] != b->k[i]) return a->k[i] < b->k[i] ? -1 : 1;
    return a->odd - b->odd;
}

/* The sorted corners of face t and the parity of its winding against them. */
static face_key key_of(const fs_trimesh *m, size_t t)
{
    const uint32_t *c = m->tri + 3 * t;
    int lo = c[0] < c[1] ? (c[0] < c[2] ? 0 : 2) : (c[1] < c[2] ? 1 : 2);
    uint32_t a = c[lo], b = c[(lo + 1) % 3], d = c[(lo + 2) % 3]; /* same winding, smallest first */
    face_key k = {{a, b < d ? b : d, b < d ? d : b}, b > d, t};
    return k;
}

/* Among the touched faces, a face and its reverse on the same corners cancel;
 * of faces repeated with one winding one is kept. Dropped faces get corner
 * UINT32_MAX in their first slot. Returns how many were dropped. */
static size_t drop_repeats(fs_trimesh *m, const work *w, size_t n, face_key *keys)
{
    for (size_t i = 0; i < n; i++) keys[i] = key_of(m, w->touched[i]);
    qsort(keys, n, sizeof *keys, cmp_key);
    size_t dropped = 0;
    for (size_t i = 0, j; i < n; i = j) {
        long bal = 0; /* faces of even minus odd winding on these corners */
        for (j = i; j < n && !memcmp(keys[j].k, keys[i].k, sizeof keys[i].k); j++) bal += keys[j].odd ? -1 : 1;
        size_t keep = bal > 0 ? i : j - 1; /* one of the surplus winding (sorted: even first) */
        for (size_t s = i; s < j; s++)
            if (bal == 0 || s != keep) m->tri[3 * keys[s].t] = UINT32_MAX, dropped++;
    }
    return dropped;
}

/* Drops the faces marked by drop_repeats and the vertices no face uses. */
static void compact(fs_trimesh *m, work *w)
{
    size_t nt = 0, nv = 0;
    for (size_t t = 0; t < m->nt; t++)
        if (m->tri[3 * t] != UINT32_MAX) memmove(m->tri + 3 * nt++, m->tri + 3 * t, 3 * sizeof *m->tri);
    m->nt = nt;
    memset(w->index, 0xff, m->nv * sizeof *w->index);
    for (size_t i = 0; i < 3 * nt; i++) w->index[m->tri[i]] = 0;
    for (size_t v = 0; v < m->nv; v++)
        if (!w->index[v]) {
            memmove(m->pos + 3 * nv, m->pos + 3 * v, 3 * sizeof *m->pos);
            w->index[v] = (uint32_t)nv++;
        }
    for (size_t i = 0; i < 3 * nt; i++) m->tri[i] = w->index[m->tri[i]];
    m->nv = nv;
}

/* One round; 0 when no face was degenerate (m untouched). Each round that
 * finds one merges a pair or drops a face with two equal corners. */
static int round_once(fs_trimesh *m, double eps, work *w, face_key *keys, size_t *removed)
{
    for (size_t v = 0; v < m->nv; v++) w->parent[v] = (uint32_t)v;
    memset(w->index, 0, m->nv * sizeof *w->index); /* here: taken in this round */
    int any = 0;
    for (size_t t = 0; t < m->nt; t++) any |= join_if_degenerate(m, t, eps, w);
    if (!any) return 0;
    merge_positions(m, w);
    size_t n = remap_faces(m, w, removed);
    *removed += drop_repeats(m, w, n, keys);
    compact(m, w);
    return 1;
}

int fs_mesh_collapse_degenerate(fs_trimesh *m, double eps, size_t *removed)
{
    size_t gone = 0, nv = m->nv ? m->nv : 1, nt = m->nt ? m->nt : 1;
    work w = {malloc(nv * sizeof *w.parent), malloc(nv * 4 * sizeof *w.acc), malloc(nv * sizeof *w.index),
              malloc(nt * sizeof *w.touched)};
    face_key *keys = malloc(nt * sizeof *keys);
    int rc = w.parent && w.acc && w.index && w.touched && keys
        ? FS_OK
        : fs_fail(FS_ERR_RUNTIME, "mesh: out of memory collapsing degenerate faces");
    while (!rc && round_once(m, eps, &w, keys, &gone)) {}
    free(w.parent), free(w.acc), free(w.index), free(w.touched), free(keys);
    if (removed) *removed = gone;
    return rc;
}
