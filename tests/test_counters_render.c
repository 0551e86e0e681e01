/* Every method's counting render (run.h fs_run_count) against its timed render
 * on the 6,859-particle dam break at 128x128: the same G-buffer bit for bit,
 * no counts in the timed stages, and counts that are plausible and can fail
 * (bounded by the sprites' pixels, at least one sample per covered pixel, one
 * texel per pixel where a pass writes every pixel, passes that must agree).
 * Also: the GL counters' exact 64-bit carry and their overflow error naming
 * the counter and stage, and the refusal of a method that declares no counters. */
#include "counters.h"
#include "fs_error.h"
#include "fs_test.h"
#include "gl.h"
#include "gl_context.h"
#include "gl_counters.h"
#include "builtin_methods.h"
#include "run.h"
#include "scene.h"
#include "shader.h"
#include "test_render.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static fs_particles P;
static fs_scene S;
static fs_gl_context CTX;

/* Counter c of stage (NULL: the sum over the stages). */
static uint64_t cnt(const fs_stages *st, const char *stage, int c)
{
    uint64_t t = 0;
    if (!stage) {
        CHECK(!fs_stages_count_total(st, c, &t), "the total of %s wraps", fs_counter_name(c));
        return t;
    }
    for (int i = 0; i < st->n; i++)
        if (!strcmp(st->name[i], stage)) t += st->count[i][c];
    return t;
}

static size_t covered(const fs_gbuffer *g)
{
    size_t n = 0;
    for (size_t i = 0; i < (size_t)g->w * g->h; i++) n += g->coverage[i] >= 0.5f;
    return n;
}

static int same_floats(const float *a, const float *b, size_t n)
{
    return (!a && !b) || (a && b && !memcmp(a, b, n * sizeof *a));
}

static int same_gbuffer(const fs_gbuffer *a, const fs_gbuffer *b)
{
    size_t n = (size_t)a->w * a->h;
    if (a->w != b->w || a->h != b->h || a->naovs != b->naovs) return 0;
    int ok = same_floats(a->depth, b->depth, n) && same_floats(a->normal, b->normal, 3 * n) &&
        same_floats(a->thickness, b->thickness, n) && same_floats(a->coverage, b->coverage, n);
    for (int k = 0; k < a->naovs && ok; k++)
        ok = a->aov[k].ncomp == b->aov[k].ncomp && same_floats(a->aov[k].data, b->aov[k].data, n * a->aov[k].ncomp);
    return ok;
}

/* An upper bound of the pixels of every particle's sprite quad: the sphere's
 * projected radius, grown for the perspective stretch at the image corner. */
static double sprite_pixels_bound(float radius)
{
    const fs_camera *cam = &S.camera;
    float view[16];
    fs_camera_view_matrix(cam, view);
    double t = tan(cam->fovy_deg * M_PI / 360.0), f_px = 0.5 * cam->height / t;
    double ta = t * sqrt(1.0 + (double)cam->width * cam->width / ((double)cam->height * cam->height));
    double stretch = 1.0 + ta * ta; /* 1 / cos^2 of the corner's angle */
    double sum = 0;
    for (size_t i = 0; i < P.n; i++) {
        double z = -(view[2] * P.x[i] + view[6] * P.y[i] + view[10] * P.z[i] + view[14]);
        if (z <= radius) continue;
        double rho = f_px * radius / (z - radius) * stretch;
        sum += (2 * rho + 2) * (2 * rho + 2);
    }
    return sum;
}

static uint64_t spheres_fragments; /* the raster's, for the compute splatter's check */

static void check_spheres(const fs_stages *c, const fs_gbuffer *g)
{
    uint64_t fr = cnt(c, "splat", FS_CNT_FRAGMENTS), tx = cnt(c, "splat", FS_CNT_TEXELS);
    spheres_fragments = fr;
    double bound = sprite_pixels_bound(S.radius);
    CHECK(fr > 0 && fr <= bound, "spheres: %llu fragments, sprites hold at most %.0f pixels", (unsigned long long)fr,
          bound);
    CHECK(tx >= covered(g) && tx <= fr, "spheres: %llu texels written, %zu covered, %llu fragments",
          (unsigned long long)tx, covered(g), (unsigned long long)fr);
    CHECK(cnt(c, "thickness", FS_CNT_FRAGMENTS) == fr && cnt(c, "thickness", FS_CNT_TEXELS) == tx,
          "spheres: the thickness pass draws the same sprites");
}

/* splat=compute: its footprints are the raster's quads (as many pixels as the
 * raster's fragments, once per pass: the depth's two, the thickness's one),
 * with an atomic per hit at most (plus the listing of large sprites and the
 * thickness's carries), a depth texel per covered pixel, and no fragment. */
static void check_spheres_compute(const fs_stages *c, const fs_gbuffer *g)
{
    uint64_t px = cnt(c, "splat_compute", FS_CNT_SPLAT_PIXELS), tpx = cnt(c, "thickness_compute", FS_CNT_SPLAT_PIXELS);
    printf("spheres, splat=compute: %llu footprint pixels (raster: %llu fragments), %llu atomics, %llu + %llu texels\n",
           (unsigned long long)tpx, (unsigned long long)spheres_fragments,
           (unsigned long long)cnt(c, "splat_compute", FS_CNT_SPLAT_ATOMICS),
           (unsigned long long)cnt(c, "splat_compute", FS_CNT_TEXELS),
           (unsigned long long)cnt(c, "thickness_compute", FS_CNT_TEXELS));
    CHECK(tpx == spheres_fragments && px == 2 * tpx, "spheres, splat=compute: %llu and %llu pixels for %llu fragments",
          (unsigned long long)px, (unsigned long long)tpx, (unsigned long long)spheres_fragments);
    uint64_t at = cnt(c, "splat_compute", FS_CNT_SPLAT_ATOMICS),
             tat = cnt(c, "thickness_compute", FS_CNT_SPLAT_ATOMICS);
    CHECK(at >= 2 * covered(g) && at <= px && tat >= covered(g), "spheres, splat=compute: %llu and %llu atomics",
          (unsigned long long)at, (unsigned long long)tat);
    CHECK(cnt(c, "splat_compute", FS_CNT_TEXELS) == covered(g) &&
              cnt(c, "thickness_compute", FS_CNT_TEXELS) >= covered(g),
          "spheres, splat=compute: a depth texel per covered pixel");
    CHECK(!cnt(c, NULL, FS_CNT_FRAGMENTS), "spheres, splat=compute: fragments shaded");
}

/* The reference's walk counts of stage s: each near cell walked is marched, crossed on
 * proven bounds, or passed (no particle within reach), once. */
static void check_reference_cells(const fs_stages *c, const char *s, const char *what)
{
    uint64_t walked = cnt(c, s, FS_CNT_CELLS_WALKED), marched = cnt(c, s, FS_CNT_CELLS_MARCHED);
    uint64_t in = cnt(c, s, FS_CNT_CELLS_PROVEN_INSIDE), out = cnt(c, s, FS_CNT_CELLS_PROVEN_OUTSIDE);
    printf("%s, %s: %llu cells walked, %llu marched (%llu inside all along), %llu proven inside, %llu outside, "
           "%llu crossings, %llu field evaluations\n",
           what, s, (unsigned long long)walked, (unsigned long long)marched,
           (unsigned long long)cnt(c, s, FS_CNT_CELLS_MARCHED_INSIDE), (unsigned long long)in, (unsigned long long)out,
           (unsigned long long)cnt(c, s, FS_CNT_CROSSINGS), (unsigned long long)cnt(c, s, FS_CNT_FIELD_EVALS));
    CHECK(walked >= marched + in + out && cnt(c, s, FS_CNT_CELLS_MARCHED_INSIDE) <= marched,
          "%s, %s: %llu cells walked, fewer than marched and proven", what, s, (unsigned long long)walked);
    uint64_t fe = cnt(c, s, FS_CNT_FIELD_EVALS), inside = cnt(c, s, FS_CNT_INSIDE_EVALS);
    CHECK(inside + cnt(c, s, FS_CNT_REFINE_EVALS) <= fe && !inside == !cnt(c, s, FS_CNT_CELLS_MARCHED_INSIDE),
          "%s, %s: %llu evaluations, %llu inside, %llu refining", what, s, (unsigned long long)fe,
          (unsigned long long)inside, (unsigned long long)cnt(c, s, FS_CNT_REFINE_EVALS));
}

/* thickness on: the first-hit march ("march") finds one crossing per covered pixel, and
 * the thickness march after it ("thickness") at least the exit of each; off: no
 * "thickness" counts. */
static void check_reference_phases(const fs_stages *c, const fs_gbuffer *g, int thickness, const char *what)
{
    uint64_t hits = covered(g), first = cnt(c, "march", FS_CNT_CROSSINGS),
             after = cnt(c, "thickness", FS_CNT_CROSSINGS);
    CHECK(hits > 0 && first == hits, "%s: %llu first-hit crossings for %llu covered pixels", what,
          (unsigned long long)first, (unsigned long long)hits);
    if (thickness)
        CHECK(after >= hits && cnt(c, "thickness", FS_CNT_FIELD_EVALS) > 0,
              "%s: %llu crossings after %llu first hits (at least an exit each)", what, (unsigned long long)after,
              (unsigned long long)hits);
    else
        for (int k = 0; k < FS_NCOUNTERS; k++)
            CHECK(!cnt(c, "thickness", k), "%s: %s counted after the first hit", what, fs_counter_name(k));
    check_reference_cells(c, "march", what);
    if (thickness) check_reference_cells(c, "thickness", what);
}

static void check_reference(const fs_stages *c, const fs_gbuffer *g)
{
    uint64_t ms = cnt(c, "march", FS_CNT_MARCH_SAMPLES), fe = cnt(c, "march", FS_CNT_FIELD_EVALS);
    CHECK(ms >= covered(g) && covered(g) > 0, "reference: %llu samples for %zu covered pixels", (unsigned long long)ms,
          covered(g));
    /* every crossing is located by sampled sums (a step proven on the last sample's
     * second-order bound reads no sum: samples may outnumber sums) */
    uint64_t cr = cnt(c, "march", FS_CNT_CROSSINGS);
    CHECK(fe > cr && ms > cr && cnt(c, "march", FS_CNT_NEIGHBOURS) > fe,
          "reference: evaluations %llu, samples %llu, crossings %llu", (unsigned long long)fe, (unsigned long long)ms,
          (unsigned long long)cr);
    check_reference_phases(c, g, 1, "reference");
    CHECK(cnt(c, "thickness", FS_CNT_CELLS_PROVEN_INSIDE) > 0 && cnt(c, "march", FS_CNT_CELLS_PROVEN_OUTSIDE) > 0,
          "reference: the interior bits prove no cell inside after the first hit, or the bounds none outside before");
}

static void check_reference_thickness_off(const fs_stages *c, const fs_gbuffer *g)
{
    check_reference_phases(c, g, 0, "reference, thickness=off");
}

/* accel=off has no bounds: every near cell is marched or passed, never proven. */
static void check_reference_plain(const fs_stages *c, const fs_gbuffer *g)
{
    check_reference_phases(c, g, 1, "reference, accel=off");
    CHECK(!cnt(c, NULL, FS_CNT_CELLS_PROVEN_INSIDE) && !cnt(c, NULL, FS_CNT_CELLS_PROVEN_OUTSIDE),
          "reference, accel=off: cells proven without bounds");
}

static void check_raycast_pca(const fs_stages *c, const fs_gbuffer *g)
{
    size_t px = (size_t)g->w * g->h;
    CHECK(cnt(c, "march", FS_CNT_TEXELS) == px, "raycast_pca: the march writes every pixel once");
    CHECK(cnt(c, "normals", FS_CNT_FIELD_EVALS) == covered(g), "raycast_pca: one normal sum per hit: %llu vs %zu",
          (unsigned long long)cnt(c, "normals", FS_CNT_FIELD_EVALS), covered(g));
    CHECK(cnt(c, "march", FS_CNT_MARCH_SAMPLES) >= covered(g), "raycast_pca: a sample per hit at least");
    CHECK(cnt(c, "filter", FS_CNT_FILTER_TAPS) >= covered(g), "raycast_pca: the filter reads each hit at least");
}

static void check_aniso_ssf(const fs_stages *c, const fs_gbuffer *g)
{
    CHECK(cnt(c, "anisotropy", FS_CNT_NEIGHBOURS) >= P.n, "aniso_ssf: every particle sees itself at least");
    CHECK(cnt(c, "normals", FS_CNT_TEXELS) == (size_t)g->w * g->h, "aniso_ssf: normals write every pixel once");
    CHECK(cnt(c, "splat", FS_CNT_TEXELS) >= covered(g), "aniso_ssf: a sprite texel per covered pixel");
    CHECK(cnt(c, "filter", FS_CNT_FILTER_TAPS) >= covered(g), "aniso_ssf: the filter reads each covered pixel");
}

static void check_surfels(const fs_stages *c, const fs_gbuffer *g)
{
    CHECK(cnt(c, "normalize", FS_CNT_TEXELS) == (size_t)g->w * g->h, "surfels: normalize writes every pixel once");
    CHECK(cnt(c, "density_grid", FS_CNT_TEXELS) == 4 * cnt(c, "density_grid", FS_CNT_FRAGMENTS) &&
              cnt(c, "density_grid", FS_CNT_FRAGMENTS) > 0,
          "surfels: four voxels per slice-splat fragment");
    CHECK(cnt(c, "blend", FS_CNT_TEXELS) >= covered(g), "surfels: a surfel texel per covered pixel");
}

static void check_volume_raycast(const fs_stages *c, const fs_gbuffer *g)
{
    CHECK(cnt(c, "march", FS_CNT_TEXELS) == (size_t)g->w * g->h, "volume_raycast: the march writes every pixel once");
    CHECK(cnt(c, "march", FS_CNT_MARCH_SAMPLES) >= covered(g), "volume_raycast: a sample per covered pixel");
    CHECK(cnt(c, "volume", FS_CNT_TEXELS) == cnt(c, "volume", FS_CNT_FRAGMENTS),
          "volume_raycast: a voxel per fragment");
}

/* levelset (a build with OpenVDB): the level set's voxels at upload, one intersector
 * query per ray for the first hit and two more per layer for the thickness */
static void check_levelset(const fs_stages *c, const fs_gbuffer *g)
{
    uint64_t ms = cnt(c, "trace", FS_CNT_MARCH_SAMPLES), px = (uint64_t)g->w * g->h;
    CHECK(cnt(c, "upload", FS_CNT_TEXELS) > 0, "levelset: the level set's active voxels at upload");
    CHECK(ms >= px + covered(g), "levelset: %llu queries for %llu rays, %zu hits (one, then an exit each)",
          (unsigned long long)ms, (unsigned long long)px, covered(g));
}

/* The timed render, then the counting render, of method name with its parameter
 * set (NAME=VALUE, a bool as 0 or 1) changed from the default (NULL: none). */
static void test_method_set(const char *name, const char *set, void (*check)(const fs_stages *, const fs_gbuffer *))
{
    const fs_method *m = fs_method_find(name);
    fs_run *run = NULL;
    fs_run_image timed = {0}, counted = {0};
    fs_stages st = {0}, cst;
    double values[64];
    int rc = fs_run_open(&run, m, &S, NULL, m->needs_gl ? &CTX : NULL);
    if (set && !rc) { /* reopened with the one value changed */
        char key[64];
        snprintf(key, sizeof key, "%.*s", (int)strcspn(set, "="), set);
        int k = fs_method_param_index(m, key);
        CHECK(k >= 0 && m->nparams <= 64, "%s: no parameter %s", name, key);
        memcpy(values, fs_run_values(run), (size_t)m->nparams * sizeof *values);
        values[k] = atof(strchr(set, '=') + 1);
        fs_run_close(run);
        run = NULL;
        rc = fs_run_open(&run, m, &S, values, m->needs_gl ? &CTX : NULL);
    }
    if (!rc) rc = fs_run_upload(run, &P, NULL, &st);
    if (!rc) rc = fs_run_render(run, &S.camera, &timed, &st);
    if (!rc) rc = fs_run_count(m, &S, fs_run_values(run), &CTX, &P, NULL, &S.camera, &counted, &cst);
    CHECK(!rc, "%s: %s", name, fs_error_message());
    if (!rc) {
        CHECK(same_gbuffer(&timed.g, &counted.g), "%s: the counting render's G-buffer differs from the timed one",
              name);
        uint64_t any = 0;
        for (int c = 0; c < FS_NCOUNTERS; c++) any |= cnt(&st, NULL, c);
        CHECK(!any, "%s: the timed render counted", name);
        for (int c = 0; c < FS_NCOUNTERS; c++)
            CHECK(!cnt(&cst, NULL, c) || (m->counters & FS_CNT_BIT(c)), "%s counts %s, which it does not declare", name,
                  fs_counter_name(c));
        check(&cst, &counted.g);
    }
    fs_run_close(run);
    fs_run_image_free(&timed);
    fs_run_image_free(&counted);
}

static void test_method(const char *name, void (*check)(const fs_stages *, const fs_gbuffer *))
{
    test_method_set(name, NULL, check);
}

/* The carry into the high word is exact, and a wrap of the high word is an
 * error naming the counter and the stage. */
static void test_gl_carry(void)
{
    const char *st[] = {"tests/counter_add.comp.glsl", NULL};
    fs_counters_reset();
    fs_counting_set(1);
    unsigned prog = fs_program_build(st, NULL);
    CHECK(prog && fs_gl_counters_begin() == FS_OK, "counter program: %s", fs_error_message());
    fs_stages s = {0};
    glUseProgram(prog);
    glUniform1ui(glGetUniformLocation(prog, "u_n"), 0xF0000000u);
    glUniform1ui(glGetUniformLocation(prog, "u_counter"), FS_CNT_FILTER_TAPS);
    glDispatchCompute(4, 1, 1); /* 256 adds */
    glFinish();
    fs_stages_add(&s, "carry", 0);
    CHECK(s.count[0][FS_CNT_FILTER_TAPS] == 256ull * 0xF0000000u, "64-bit sum: %llu",
          (unsigned long long)s.count[0][FS_CNT_FILTER_TAPS]);
    GLint buf = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, FS_GL_COUNTER_BINDING, &buf);
    uint32_t full[2] = {0xFFFFFFFFu, 0xFFFFFFFFu};
    glNamedBufferSubData((GLuint)buf, 2 * FS_CNT_TEXELS * sizeof(uint32_t), sizeof full, full);
    glUniform1ui(glGetUniformLocation(prog, "u_n"), 1);
    glUniform1ui(glGetUniformLocation(prog, "u_counter"), FS_CNT_TEXELS);
    glDispatchCompute(1, 1, 1);
    glFinish();
    fs_stages_add(&s, "wrap", 0);
    fs_gl_counters_end();
    fs_counting_set(0);
    CHECK(fs_counters_check() != FS_OK && strstr(fs_error_message(), "texels_written") &&
              strstr(fs_error_message(), "wrap"),
          "GL overflow: %s", fs_error_message());
    fs_counters_reset();
    glDeleteProgram(prog);
}

/* A method that declares no counters is refused, by name. */
static void *none_create(const fs_method_setup *s)
{
    (void)s;
    static int x;
    return &x;
}
static int none_upload(void *self, const fs_particles *p, const fs_grid *g)
{
    (void)self;
    (void)p;
    (void)g;
    return FS_OK;
}
static int none_render(void *self, const fs_camera *c, fs_gbuffer *o, fs_stages *t)
{
    (void)self;
    (void)c;
    (void)o;
    (void)t;
    return FS_OK;
}
static void none_destroy(void *self) { (void)self; }
static const fs_method uncounted = {.name = "uncounted",
                                    .description = "declares no counters",
                                    .paper = "",
                                    .grid_use = FS_GRID_UNUSED,
                                    .create = none_create,
                                    .upload = none_upload,
                                    .render = none_render,
                                    .destroy = none_destroy};

static void test_uncounted(void)
{
    CHECK(fs_method_register(&uncounted, FS_METHOD_HIDDEN) == FS_OK, "register");
    fs_run_image im = {0};
    fs_stages st;
    int rc = fs_run_count(fs_method_find("uncounted"), &S, NULL, NULL, &P, NULL, &S.camera, &im, &st);
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "'uncounted'"), "refused: %d %s", rc, fs_error_message());
    CHECK(!fs_counting, "counting is off again");
    fs_run_image_free(&im);
}

/* Counts made after the last stage, and a stage past the table's 16: errors
 * naming the method or the stage, never counts dropped silently. */
static int late_render(void *self, const fs_camera *c, fs_gbuffer *o, fs_stages *t)
{
    (void)self;
    (void)c;
    (void)o;
    fs_stages_add(t, "late_stage", 0);
    fs_count_add(FS_CNT_FIELD_EVALS, 3); /* after the method's last stage */
    return FS_OK;
}
static int many_render(void *self, const fs_camera *c, fs_gbuffer *o, fs_stages *t)
{
    static const char *const names[FS_MAX_STAGES] = {"s0", "s1", "s2",  "s3",  "s4",  "s5",  "s6",  "s7",
                                                     "s8", "s9", "s10", "s11", "s12", "s13", "s14", "s15"};
    (void)self;
    (void)c;
    (void)o;
    for (int i = 0; i < FS_MAX_STAGES; i++) {
        fs_count_add(FS_CNT_FIELD_EVALS, 1);
        fs_stages_add(t, names[i], 0); /* with "upload" before them: the last finds the table full */
    }
    return FS_OK;
}
static const fs_method late = {.name = "late",
                               .description = "counts after its last stage",
                               .paper = "",
                               .grid_use = FS_GRID_UNUSED,
                               .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS),
                               .create = none_create,
                               .upload = none_upload,
                               .render = late_render,
                               .destroy = none_destroy};
static const fs_method many = {.name = "many",
                               .description = "has more stages than a table holds",
                               .paper = "",
                               .grid_use = FS_GRID_UNUSED,
                               .counters = FS_CNT_BIT(FS_CNT_FIELD_EVALS),
                               .create = none_create,
                               .upload = none_upload,
                               .render = many_render,
                               .destroy = none_destroy};

static void test_never_dropped(void)
{
    CHECK(fs_method_register(&late, FS_METHOD_HIDDEN) == FS_OK && fs_method_register(&many, FS_METHOD_HIDDEN) == FS_OK,
          "register");
    fs_run_image im = {0};
    fs_stages st;
    int rc = fs_run_count(fs_method_find("late"), &S, NULL, NULL, &P, NULL, &S.camera, &im, &st);
    CHECK(rc == FS_ERR_RUNTIME && strstr(fs_error_message(), "'late'") && strstr(fs_error_message(), "field_evals"),
          "counts after the last stage: %d %s", rc, fs_error_message());
    fs_run_image_free(&im);
    rc = fs_run_count(fs_method_find("many"), &S, NULL, NULL, &P, NULL, &S.camera, &im, &st);
    CHECK(rc == FS_ERR_RUNTIME && strstr(fs_error_message(), "s15") && strstr(fs_error_message(), "at most 16"),
          "a full stage table while counting: %d %s", rc, fs_error_message());
    CHECK(!fs_counting, "counting is off again");
    fs_run_image_free(&im);
}

int main(void)
{
    fs_field f;
    fs_methods_register_builtin();
    if (fs_test_load_dam(&P, &S, &f) || fs_gl_context_create(&CTX, fs_gl_context_default_kind(), 16, 16)) {
        CHECK(0, "setup: %s", fs_error_message());
        TEST_DONE();
    }
    test_method("spheres", check_spheres);
    test_method_set("spheres", "splat=1", check_spheres_compute);
    test_method("reference", check_reference);
    test_method_set("reference", "thickness=0", check_reference_thickness_off);
    test_method_set("reference", "accel=0", check_reference_plain);
    test_method("raycast_pca", check_raycast_pca);
    test_method("aniso_ssf", check_aniso_ssf);
    test_method("surfels", check_surfels);
    test_method("volume_raycast", check_volume_raycast);
    if (FS_WITH_OPENVDB) test_method("levelset", check_levelset);
    test_gl_carry();
    test_uncounted();
    test_never_dropped();
    fs_gl_context_destroy(&CTX);
    fs_particles_free(&P);
    TEST_DONE();
}
