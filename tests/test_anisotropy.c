/* common/field/anisotropy.c on a synthetic slab: a particle on the flat top is
 * flattened along the normal (y), one in the middle of a thick block is nearly
 * isotropic, one with few neighbours is exactly isotropic; per-particle
 * normalisation keeps det A = scale^3; the bulk lattice maps to stretch 1. */
#include "anisotropy.h"
#include "eigen3.h"
#include "fs_error.h"
#include "fs_test.h"
#include "scene.h"
#include "synthetic.h"
#include <stdlib.h>

static void eig(const float A[9], double ev[3], double V[9])
{
    double a[9];
    for (int k = 0; k < 9; k++) a[k] = A[k];
    fs_eigen3_sym(a, ev, V);
}

/* Index of the particle nearest to x. */
static size_t nearest(const fs_particles *p, float x, float y, float z)
{
    size_t best = 0;
    float bd = INFINITY;
    for (size_t i = 0; i < p->n; i++) {
        float d = (p->x[i] - x) * (p->x[i] - x) + (p->y[i] - y) * (p->y[i] - y) + (p->z[i] - z) * (p->z[i] - z);
        if (d < bd) {
            bd = d;
            best = i;
        }
    }
    return best;
}

int main(void)
{
    const float r = 0.025f;
    fs_scene s;
    fs_scene_defaults(&s);
    s.radius = r;
    s.synth.shape = FS_SYNTH_BOX;
    s.synth.size[0] = s.synth.size[1] = s.synth.size[2] = 14;
    s.synth.jitter = 0.1f;
    s.synth.seed = 3;
    fs_particles p;
    CHECK(fs_synthetic_generate(&s, 0, &p) == FS_OK, "box: %s", fs_error_message());
    fs_particles_bounds(&p);
    fs_grid g;
    CHECK(fs_grid_build(&g, &p, 4 * r) == FS_OK, "grid: %s", fs_error_message());
    fs_aniso_params ap;
    fs_aniso_defaults(&ap, FS_KERNEL_CUBIC, r);
    CHECK(ap.sigma_ref > 0 && ap.sigma_ref < ap.radius * ap.radius, "sigma_ref %g", ap.sigma_ref);
    float *c = malloc(p.n * 3 * sizeof *c), *A = malloc(p.n * 9 * sizeof *A), amax = 0;
    CHECK(fs_aniso_compute(&p, &g, &ap, c, A, &amax) == FS_OK, "compute: %s", fs_error_message());
    float cx = 0.5f * (p.bmin[0] + p.bmax[0]), cy = 0.5f * (p.bmin[1] + p.bmax[1]), cz = 0.5f * (p.bmin[2] + p.bmax[2]);
    double ev[3], V[9];
    /* Middle of the top face: smallest axis along y, at most half the largest. */
    size_t top = nearest(&p, cx, p.bmax[1], cz);
    eig(A + 9 * top, ev, V);
    printf("top: axes %.3f %.3f %.3f, smallest along (%.3f %.3f %.3f)\n", ev[0], ev[1], ev[2], V[0], V[1], V[2]);
    CHECK(fabs(V[1]) > 0.95, "top particle's thin axis is not along y (%g %g %g)", V[0], V[1], V[2]);
    CHECK(ev[0] < 0.6 * ev[2], "top particle not flattened (%g vs %g)", ev[0], ev[2]);
    CHECK_NEAR(ev[0] * ev[1] * ev[2], 1.0, 1e-3, "det A of the top particle (volume kept)");
    /* Centre of the block: neighbours all round, nearly isotropic. */
    size_t mid = nearest(&p, cx, cy, cz);
    eig(A + 9 * mid, ev, V);
    printf("bulk: axes %.3f %.3f %.3f; largest axis of all %.3f\n", ev[0], ev[1], ev[2], amax);
    CHECK(ev[0] > 0.85 * ev[2], "bulk particle anisotropic (%g vs %g)", ev[0], ev[2]);
    CHECK(amax >= ev[2], "max axis %g below a particle's %g", amax, ev[2]);
    /* The global normalisation maps the unjittered bulk lattice to stretch 1. */
    fs_aniso_params gl = ap;
    gl.per_particle = 0;
    s.synth.jitter = 0;
    fs_particles q;
    fs_grid gq;
    CHECK(fs_synthetic_generate(&s, 0, &q) == FS_OK && fs_grid_build(&gq, &q, 4 * r) == FS_OK, "lattice");
    float cen[3], B[9], x[3];
    size_t m2 = nearest(&q, cx, cy, cz);
    x[0] = q.x[m2];
    x[1] = q.y[m2];
    x[2] = q.z[m2];
    int nn = fs_aniso_point(&gq, x, &gl, cen, B);
    printf("lattice bulk: %d neighbours, diag %.4f %.4f %.4f\n", nn, B[0], B[4], B[8]);
    for (int k = 0; k < 3; k++) CHECK_NEAR(B[4 * k], 1.0, 1e-3, "bulk lattice stretch");
    CHECK_NEAR(B[1], 0.0, 1e-3, "bulk lattice off-diagonal");
    /* A small cluster (7 particles): at or below n_eps, so A = I and the centre stays. */
    fs_particles few;
    fs_particles_alloc(&few, 7, 0);
    for (int i = 0; i < 7; i++) {
        few.x[i] = (i % 3) * 2 * r;
        few.y[i] = (i / 3) * 2 * r;
        few.z[i] = 0;
    }
    fs_particles_bounds(&few);
    fs_grid gf;
    CHECK(fs_grid_build(&gf, &few, 4 * r) == FS_OK, "few grid");
    float xf[3] = {few.x[0], few.y[0], few.z[0]};
    ap.lambda = 0.5f; /* the centre still moves by lambda times the weighted mean offset */
    nn = fs_aniso_point(&gf, xf, &ap, cen, B);
    CHECK(nn == 6, "%d neighbours of 7", nn);
    for (int k = 0; k < 9; k++) CHECK_NEAR(B[k], k % 4 == 0 ? 1.0 : 0.0, 0, "isotropic with few neighbours");
    CHECK(cen[0] > xf[0] && cen[1] > xf[1], "lambda does not move the centre towards the neighbours");
    fs_grid_free(&gf);
    fs_particles_free(&few);
    fs_grid_free(&gq);
    fs_particles_free(&q);
    free(c);
    free(A);
    fs_grid_free(&g);
    fs_particles_free(&p);
    TEST_DONE();
}
