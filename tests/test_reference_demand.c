/* The reference's interior proofs on demand (interior=demand, methods/reference/
 * README.md step 9) against the same proofs made up front (interior=on), on the
 * bundled dam break at 128x128 (thickness on): the G-buffers are identical bit
 * for bit, on 2 threads and on 1 (a proof is a function of its cell alone, so it
 * does not matter which ray made it, or when); demand makes at most the proofs
 * that on makes, and more than none; the same number on 1 and 2 threads (a cell
 * is claimed once: two threads never both prove it); and a second render of the
 * same upload makes none (a cell is proven once, whatever renders follow). The
 * coarse sub-cell bounds, also made on demand (by the first ray that walks a
 * cell) where interior=on makes them up front, are checked the same way. With
 * a proof left unmade where a ray enters a cell inside, or made wrongly, the
 * march skips other sub-cells and the images differ. With thickness=off the coarse
 * bounds are always made on demand (a ray walks only the cells before its first hit):
 * its depth, normals and coverage are interior=on's bit for bit, with fewer cells'
 * bounds made. */
#include "counters.h"
#include "fs_error.h"
#include "fs_test.h"
#include "builtin_methods.h"
#include "run.h"
#include "scene.h"
#include "test_render.h"
#include <omp.h>
#include <stdint.h>
#include <string.h>

/* What a render made: interior proofs (stage "interior": field_evals / 512) and
 * cells' coarse bounds (stage "bounds": field_evals, one per sub-cell). */
typedef struct made {
    uint64_t proofs, bounds;
} made;

/* Renders the scene with the reference's parameter `set` (e.g. interior=on), twice on
 * one upload while counting; the first render's G-buffer into g, what each made into m. */
static int render_twice(fs_scene *s, const fs_particles *p, const char *set, fs_gbuffer *g, made m[2])
{
    char full[64];
    snprintf(full, sizeof full, "reference.%s", set);
    s->nsets = 0;
    int rc = fs_scene_add_set(s, full);
    fs_run *run = NULL;
    if (!rc) rc = fs_run_open(&run, fs_method_find("reference"), s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, p, NULL, NULL);
    fs_counting_set(1);
    for (int k = 0; !rc && k < 2; k++) {
        fs_stages st = {0};
        fs_run_image im = {0};
        rc = fs_run_render(run, &s->camera, &im, &st);
        m[k] = (made){0, 0};
        for (int i = 0; i < st.n; i++) {
            if (!strcmp(st.name[i], "interior")) m[k].proofs = st.count[i][FS_CNT_FIELD_EVALS] / (8 * 8 * 8);
            if (!strcmp(st.name[i], "bounds")) m[k].bounds = st.count[i][FS_CNT_FIELD_EVALS];
        }
        if (!rc && k == 0) *g = im.g;
        else fs_run_image_free(&im);
    }
    fs_counting_set(0);
    fs_run_close(run);
    return rc;
}

/* Whether two G-buffers are the same bit for bit (depth, normal, thickness, coverage). */
static int same_bits(const fs_gbuffer *a, const fs_gbuffer *b)
{
    size_t n = (size_t)a->w * a->h;
    return a->w == b->w && a->h == b->h && !memcmp(a->depth, b->depth, n * sizeof *a->depth) &&
        !memcmp(a->normal, b->normal, 3 * n * sizeof *a->normal) &&
        !memcmp(a->thickness, b->thickness, n * sizeof *a->thickness) &&
        !memcmp(a->coverage, b->coverage, n * sizeof *a->coverage);
}

/* demand made what on made or less, more than none, the same on 2 threads (dem[0])
 * and on 1 (dem1[0]), and nothing again in a second render (index 1). */
static void check_made(const char *what, uint64_t on[2], uint64_t dem[2], uint64_t dem1[2])
{
    printf("%s: on %llu up front, demand %llu (2 threads) and %llu (1 thread), then %llu and %llu in a second render\n",
           what, (unsigned long long)on[0], (unsigned long long)dem[0], (unsigned long long)dem1[0],
           (unsigned long long)dem[1], (unsigned long long)dem1[1]);
    CHECK(dem[0] > 0 && dem[0] <= on[0], "%s: demand makes %llu, on %llu", what, (unsigned long long)dem[0],
          (unsigned long long)on[0]);
    CHECK(dem[0] == dem1[0], "%s: the same on 2 threads and on 1 (%llu, %llu)", what, (unsigned long long)dem[0],
          (unsigned long long)dem1[0]);
    CHECK(dem[1] == 0 && dem1[1] == 0 && on[1] == 0, "%s: a second render makes none again", what);
}

/* Whether b has a's first hits bit for bit (depth, normal, coverage) and no thickness. */
static int same_first_hits(const fs_gbuffer *a, const fs_gbuffer *b)
{
    size_t n = (size_t)a->w * a->h;
    int zero = 1;
    for (size_t i = 0; i < n; i++) zero &= b->thickness[i] == 0.0f;
    return zero && a->w == b->w && a->h == b->h && !memcmp(a->depth, b->depth, n * sizeof *a->depth) &&
        !memcmp(a->normal, b->normal, 3 * n * sizeof *a->normal) &&
        !memcmp(a->coverage, b->coverage, n * sizeof *a->coverage);
}

/* thickness=off: the coarse bounds are made on demand (a ray walks only the cells in
 * front of its first hit), on 2 threads and on 1; the first hits are interior=on's bit
 * for bit, and fewer cells' bounds are made than on makes up front. */
static void check_first_hit(fs_scene *s, const fs_particles *p, const fs_gbuffer *on, const made m_on[2])
{
    fs_gbuffer off = {0}, off1 = {0};
    made m2[2], m1[2];
    omp_set_num_threads(2);
    int rc = render_twice(s, p, "thickness=off", &off, m2);
    omp_set_num_threads(1);
    if (!rc) rc = render_twice(s, p, "thickness=off", &off1, m1);
    CHECK(!rc, "thickness=off renders: %s", fs_error_message());
    if (!rc) {
        CHECK(same_first_hits(on, &off), "thickness=off's first hits (2 threads) are interior=on's bit for bit");
        CHECK(same_first_hits(on, &off1), "thickness=off's first hits (1 thread) are interior=on's bit for bit");
        uint64_t on_b[2] = {m_on[0].bounds, m_on[1].bounds}, b2[2] = {m2[0].bounds, m2[1].bounds},
                 b1[2] = {m1[0].bounds, m1[1].bounds};
        check_made("cell bounds, thickness off (sub-cells)", on_b, b2, b1);
        CHECK(b2[0] < on_b[0], "thickness=off makes fewer cells' bounds than interior=on (%llu, %llu)",
              (unsigned long long)b2[0], (unsigned long long)on_b[0]);
    }
    fs_gbuffer_free(&off);
    fs_gbuffer_free(&off1);
}

int main(void)
{
    fs_methods_register_builtin();
    fs_note_quiet(1); /* the small-radius note */
    fs_particles p;
    static fs_scene s;
    fs_field f;
    int rc = fs_test_load_dam(&p, &s, &f);
    CHECK(!rc, "load: %s", fs_error_message());
    if (rc) TEST_DONE();
    fs_gbuffer on = {0}, demand = {0}, demand1 = {0};
    made m_on[2], m_dem[2], m_dem1[2];
    omp_set_num_threads(2);
    rc = render_twice(&s, &p, "interior=on", &on, m_on);
    if (!rc) rc = render_twice(&s, &p, "interior=demand", &demand, m_dem);
    omp_set_num_threads(1);
    if (!rc) rc = render_twice(&s, &p, "interior=demand", &demand1, m_dem1);
    CHECK(!rc, "renders: %s", fs_error_message());
    if (!rc) {
        size_t covered = 0;
        for (size_t i = 0; i < (size_t)on.w * on.h; i++) covered += on.coverage[i] > 0;
        CHECK(covered > 1000, "the fluid covers the image (%zu pixels)", covered);
        CHECK(same_bits(&on, &demand), "interior=demand's G-buffer (2 threads) is interior=on's bit for bit");
        CHECK(same_bits(&on, &demand1), "interior=demand's G-buffer (1 thread) is interior=on's bit for bit");
        uint64_t on_p[2] = {m_on[0].proofs, m_on[1].proofs}, dem_p[2] = {m_dem[0].proofs, m_dem[1].proofs},
                 dem1_p[2] = {m_dem1[0].proofs, m_dem1[1].proofs};
        check_made("interior proofs", on_p, dem_p, dem1_p);
        uint64_t on_b[2] = {m_on[0].bounds, m_on[1].bounds}, dem_b[2] = {m_dem[0].bounds, m_dem[1].bounds},
                 dem1_b[2] = {m_dem1[0].bounds, m_dem1[1].bounds};
        check_made("cell bounds (sub-cells)", on_b, dem_b, dem1_b);
        check_first_hit(&s, &p, &on, m_on);
    }
    fs_gbuffer_free(&on);
    fs_gbuffer_free(&demand);
    fs_gbuffer_free(&demand1);
    fs_particles_free(&p);
    TEST_DONE();
}
