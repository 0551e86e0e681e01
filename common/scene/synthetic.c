/* Synthetic scenes with a known ideal surface (synthetic.h, docs/DESIGN.md
 * "References"): a lattice of spacing 2r with a seeded jitter. The exact ray
 * caster of the ideal solid is eval/analytic.c. */
#include "synthetic.h"
#include "fs_error.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

static const char *scene_name(const fs_scene *s) { return s->path[0] ? s->path : "synthetic scene"; }

static int sphere_keeps(const fs_synthetic_layout *L, int i, int j, int k)
{
    double dx = L->base[0] + 2 * L->r * i - L->centre[0];
    double dy = L->base[1] + 2 * L->r * j - L->centre[1];
    double dz = L->base[2] + 2 * L->r * k - L->centre[2];
    return dx * dx + dy * dy + dz * dz < L->rc * L->rc;
}

/* Axis a `moving` scene translates along: x, or y when x is up. */
static int move_axis(const fs_scene *s) { return s->up_axis == 0 ? 1 : 0; }

int fs_synthetic_layout_of(const fs_scene *s, int frame, fs_synthetic_layout *L)
{
    const fs_synthetic *y = &s->synth;
    memset(L, 0, sizeof *L);
    if (y->shape != FS_SYNTH_SLAB && y->shape != FS_SYNTH_BOX && y->shape != FS_SYNTH_SPHERE)
        return fs_fail(FS_ERR_INPUT, "%s: no synthetic shape (slab, box or sphere)", scene_name(s));
    if (!(s->radius > 0) || !isfinite(s->radius))
        return fs_fail(FS_ERR_INPUT, "%s: particle radius %g must be positive", scene_name(s), s->radius);
    if (!(y->jitter >= 0) || y->jitter > 1)
        return fs_fail(FS_ERR_INPUT, "%s: jitter %g must lie in [0, 1] (multiples of r)", scene_name(s), y->jitter);
    if (s->up_axis < 0 || s->up_axis > 2)
        return fs_fail(FS_ERR_INPUT, "%s: up axis %d is not 0, 1 or 2", scene_name(s), s->up_axis);
    int up = s->up_axis;
    L->r = s->radius;
    L->sphere = y->shape == FS_SYNTH_SPHERE;
    /* Sizes are particles per world axis; 0 picks the defaults (the slab is
     * thin along the up axis). */
    for (int a = 0; a < 3; a++) {
        int v = L->sphere ? y->size[0] : y->size[a];
        if (v < 0 || v > 2000)
            return fs_fail(FS_ERR_INPUT, "%s: synthetic size %d must lie in [1, 2000]", scene_name(s), v);
        if (v == 0) v = y->shape == FS_SYNTH_SLAB ? (a == up ? 6 : 48) : (y->shape == FS_SYNTH_BOX ? 16 : 20);
        L->n[a] = v;
    }
    double d = 2 * L->r, shift = s->synth.moving ? d * frame : 0;
    for (int a = 0; a < 3; a++) L->base[a] = -0.5 * d * (L->n[a] - 1) + (a == move_axis(s) ? shift : 0);
    if (L->sphere) {
        /* Keep the centres inside the ball of diameter n * 2r; the ideal radius
         * gives the same volume as the kept cubes. */
        for (int a = 0; a < 3; a++) L->centre[a] = a == move_axis(s) ? shift : 0;
        L->rc = L->r * L->n[0];
        for (int k = 0; k < L->n[2]; k++)
            for (int j = 0; j < L->n[1]; j++)
                for (int i = 0; i < L->n[0]; i++) L->count += (size_t)sphere_keeps(L, i, j, k);
        L->R = d * cbrt(3.0 * L->count / (4.0 * FS_PI));
        /* Rest on the floor: lift lattice and centre so the ball's bottom is at 0. */
        L->base[up] += L->R;
        L->centre[up] = L->R;
    } else {
        L->base[up] = L->r;
        L->count = (size_t)L->n[0] * L->n[1] * L->n[2];
        for (int a = 0; a < 3; a++) {
            L->lo[a] = L->base[a] - L->r;
            L->hi[a] = L->base[a] + d * (L->n[a] - 1) + L->r;
        }
    }
    if (L->count == 0) return fs_fail(FS_ERR_INPUT, "%s: the synthetic shape holds no particles", scene_name(s));
    if (L->count > ((size_t)1 << 30))
        return fs_fail(FS_ERR_INPUT, "%s: %zu synthetic particles: too many", scene_name(s), L->count);
    return FS_OK;
}

/* splitmix64: small, seedable, good enough for a jitter. */
static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/* Uniform in [-1, 1). */
static double uniform_pm1(uint64_t *state) { return (double)(splitmix64(state) >> 11) * 0x1.0p-52 - 1.0; }

int fs_synthetic_generate(const fs_scene *s, int frame, fs_particles *p)
{
    fs_synthetic_layout L;
    memset(p, 0, sizeof *p);
    int rc = fs_synthetic_layout_of(s, frame, &L);
    if (rc) return rc;
    rc = fs_particles_alloc(p, L.count, 0);
    if (rc) return rc;
    /* Seed and frame both enter the state, so each frame re-jitters deterministically. */
    uint64_t state =
        (uint64_t)s->synth.seed * 0xD1B54A32D192ED03ull ^ ((uint64_t)(uint32_t)frame + 1) * 0x8CB92BA72F3D8DD7ull;
    splitmix64(&state);
    double amp = s->synth.jitter * L.r, d = 2 * L.r;
    size_t m = 0;
    for (int k = 0; k < L.n[2]; k++)
        for (int j = 0; j < L.n[1]; j++)
            for (int i = 0; i < L.n[0]; i++) {
                if (L.sphere && !sphere_keeps(&L, i, j, k)) continue;
                p->x[m] = (float)(L.base[0] + d * i + amp * uniform_pm1(&state));
                p->y[m] = (float)(L.base[1] + d * j + amp * uniform_pm1(&state));
                p->z[m] = (float)(L.base[2] + d * k + amp * uniform_pm1(&state));
                m++;
            }
    p->radius = s->radius;
    fs_particles_bounds(p);
    return FS_OK;
}
