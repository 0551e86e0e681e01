/* SPH static obstacles (sph.h, obstacles.h) in JSON scenes: an obstacle adds
 * the boundary particles of its two-layer shell (counted here on the lattice
 * independently) and takes the fluid sites it covers; at the file's own size
 * the simulated obstacles are the file's coordinates exactly; a dam break run
 * 0.5 s against a box and a sphere reaches them and does not enter them;
 * malformed obstacles are refused with the file named. */
#include "fs_error.h"
#include "fs_test.h"
#include "obstacles.h"
#include "particles.h"
#include "sph.h"
#include "timing.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define DIR FS_TEST_OUT "/sph_obstacles"

/* The tank and the dam of every scene here, in metres (multiples of 2r = 0.05). */
static const float BOX[3] = {1.2f, 0.8f, 0.5f}, FLUID_LO[3] = {0, 0, 0}, FLUID_HI[3] = {0.5f, 0.6f, 0.5f};

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL, "cannot write %s", path);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* One obstacle as JSON, with every float written so that it parses back to itself. */
static int obstacle_json(char *out, size_t n, const fs_obstacle *o)
{
    if (o->kind == FS_OBSTACLE_SPHERE)
        return snprintf(out, n, "{\"centre\": [%.9g, %.9g, %.9g], \"radius\": %.9g}", o->c[0], o->c[1], o->c[2],
                        o->radius);
    return snprintf(out, n, "{\"min\": [%.9g, %.9g, %.9g], \"max\": [%.9g, %.9g, %.9g]}", o->lo[0], o->lo[1], o->lo[2],
                    o->hi[0], o->hi[1], o->hi[2]);
}

/* The dam-break scene file with the obstacles ob (none: no "obstacles" key). */
static void write_scene(const char *path, const fs_obstacles *ob)
{
    char text[4096], *e = text;
    e += sprintf(e, "{\"box\": [%g, %g, %g], \"fluid\": [{\"min\": [%g, %g, %g], \"max\": [%g, %g, %g]}]", BOX[0],
                 BOX[1], BOX[2], FLUID_LO[0], FLUID_LO[1], FLUID_LO[2], FLUID_HI[0], FLUID_HI[1], FLUID_HI[2]);
    if (ob->n) e += sprintf(e, ", \"obstacles\": [");
    for (int i = 0; i < ob->n; i++) {
        e += obstacle_json(e, sizeof text - (size_t)(e - text) - 8, &ob->o[i]);
        e += sprintf(e, i + 1 < ob->n ? ", " : "]");
    }
    sprintf(e, "}\n");
    write_file(path, text);
}

static fs_sph *make(const char *scene, size_t n)
{
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *s = NULL;
    CHECK(fs_sph_create(&s, scene, n, &p, 0) == FS_OK, "create %s: %s", scene, fs_error_message());
    return s;
}

/* Signed distance to the nearest obstacle (negative inside one). */
static float distance(const fs_obstacles *ob, const float p[3])
{
    float d = INFINITY;
    for (int i = 0; i < ob->n; i++) d = fminf(d, fs_obstacle_distance(&ob->o[i], p));
    return d;
}

/* The lattice counted here: sites r + i 2r inside the box; inside an obstacle
 * boundary down to 2 spacings deep, empty deeper; fluid in the dam elsewhere. */
typedef struct sites {
    size_t shell, fluid;
} sites;
static sites count_lattice(const fs_obstacles *ob, float r)
{
    const float dx = 2 * r;
    int nc[3];
    for (int a = 0; a < 3; a++) nc[a] = (int)lroundf(BOX[a] / dx);
    sites n = {0, 0};
    for (int k = 0; k < nc[2]; k++)
        for (int j = 0; j < nc[1]; j++)
            for (int i = 0; i < nc[0]; i++) {
                float p[3] = {r + i * dx, r + j * dx, r + k * dx}, d = distance(ob, p);
                if (d < 0) {
                    n.shell += d >= -2 * dx;
                    continue;
                }
                int in = 1;
                for (int a = 0; a < 3; a++) in &= p[a] >= FLUID_LO[a] && p[a] < FLUID_HI[a];
                n.fluid += in;
            }
    return n;
}

/* Fluid particles of s deeper than depth inside an obstacle, within `near` of
 * one's surface, and the deepest one's distance. */
typedef struct contact {
    size_t inside, near;
    float deepest;
} contact;
static contact contacts(fs_sph *s, const fs_obstacles *ob, float depth, float near)
{
    contact c = {0, 0, INFINITY};
    fs_particles q;
    CHECK(fs_sph_get(s, &q) == FS_OK, "get: %s", fs_error_message());
    for (size_t i = 0; i < q.n; i++) {
        float p[3] = {q.x[i], q.y[i], q.z[i]}, d = distance(ob, p);
        if (!(d >= -depth)) c.inside++; /* NaN counts as inside */
        if (d < near) c.near++;
        if (d < c.deepest) c.deepest = d;
    }
    fs_particles_free(&q);
    return c;
}

/* The obstacle scene's counts against the same scene without obstacles, its
 * obstacles exactly the file's at particles 0, and no fluid inside one. */
static void check_build(const char *path, const char *plain, const fs_obstacles *ob, const char *what)
{
    fs_sph *s = make(path, 0), *s0 = make(plain, 0);
    if (!s || !s0) {
        fs_sph_destroy(s);
        fs_sph_destroy(s0);
        return;
    }
    float r = fs_sph_get_params(s)->r;
    sites e = count_lattice(ob, r), e0 = count_lattice(&(fs_obstacles){0}, r);
    size_t nb = fs_sph_boundary_count(s), nb0 = fs_sph_boundary_count(s0);
    printf("%s: boundary %zu = %zu + %zu (expected shell %zu), fluid %zu (expected %zu; %zu without)\n", what, nb, nb0,
           nb - nb0, e.shell, fs_sph_count(s), e.fluid, fs_sph_count(s0));
    CHECK(nb == nb0 + e.shell && e.shell > 0, "%s: boundary %zu, expected %zu + %zu", what, nb, nb0, e.shell);
    CHECK(fs_sph_count(s) == e.fluid && fs_sph_count(s0) == e0.fluid, "%s: fluid %zu / %zu, expected %zu / %zu", what,
          fs_sph_count(s), fs_sph_count(s0), e.fluid, e0.fluid);
    const fs_obstacles *got = fs_sph_obstacles(s);
    CHECK(got->n == ob->n, "%s: %d obstacles", what, got->n);
    for (int i = 0; i < ob->n && i < got->n; i++) {
        const fs_obstacle *a = &got->o[i], *b = &ob->o[i];
        int same = a->kind == b->kind && a->radius == b->radius;
        for (int k = 0; k < 3; k++) same &= a->lo[k] == b->lo[k] && a->hi[k] == b->hi[k] && a->c[k] == b->c[k];
        CHECK(same, "%s: obstacle %d is not the file's exactly (scale 1 at particles 0)", what, i);
    }
    CHECK(fs_sph_obstacles(s0)->n == 0, "no obstacles without the key");
    contact c = contacts(s, ob, 0, 0);
    CHECK(c.inside == 0, "%s: %zu fluid particles start inside an obstacle", what, c.inside);
    fs_sph_destroy(s);
    fs_sph_destroy(s0);
}

/* 0.5 s of the dam break: no fluid centre deeper than r inside an obstacle,
 * and the fluid reached it (within 3r of its surface; not so at the start
 * when the obstacle stands downstream). */
static void check_flow(const char *path, const fs_obstacles *ob, int downstream, const char *what)
{
    fs_sph *s = make(path, 0);
    if (!s) return;
    float r = fs_sph_get_params(s)->r;
    contact c0 = contacts(s, ob, r, 3 * r), c = c0;
    if (downstream) CHECK(c0.near == 0, "%s: fluid near the obstacle at the start (%zu)", what, c0.near);
    double t0 = fs_now_ms();
    int rc = FS_OK;
    for (int f = 0; f < 30 && !rc; f++) {
        rc = fs_sph_advance(s, 1.0 / 60);
        contact cf = contacts(s, ob, r, 3 * r);
        c.inside += cf.inside;
        c.near = cf.near > c.near ? cf.near : c.near;
        c.deepest = fminf(c.deepest, cf.deepest);
    }
    CHECK(rc == FS_OK, "%s: advance: %s", what, fs_error_message());
    const fs_sph_stats *st = fs_sph_get_stats(s);
    printf("%s: %zu fluid + %zu boundary, t = %.2f s in %.1f s (%ld steps): deepest fluid centre %.4f m (r = %.3f; "
           "< 0 inside), %zu deeper than r over 30 frames, up to %zu within 3r, %ld clamps\n",
           what, fs_sph_count(s), fs_sph_boundary_count(s), st->t, (fs_now_ms() - t0) / 1000, st->steps, c.deepest, r,
           c.inside, c.near, st->clamps);
    CHECK(c.inside == 0, "%s: %zu fluid centres deeper than r inside (deepest %g m)", what, c.inside, c.deepest);
    CHECK(c.near >= 20, "%s: the fluid did not reach the obstacle (%zu within 3r)", what, c.near);
    CHECK(fabs(st->t - 0.5) < 1e-4, "%s: time %g", what, st->t);
    fs_sph_destroy(s);
}

/* Scaled by --particles, the obstacles scale with the tank. */
static void check_scaled(const char *path, const fs_obstacles *ob)
{
    fs_sph *s = make(path, 9600); /* 8x the dam's 1200 sites: scale 2 */
    if (!s) return;
    float lo[3], hi[3];
    fs_sph_box(s, lo, hi);
    const fs_obstacle *o = &fs_sph_obstacles(s)->o[0];
    printf("scaled x%.4f: box x %.3f, obstacle min x %.4f (file %.4f)\n", hi[0] / BOX[0], hi[0], o->lo[0],
           ob->o[0].lo[0]);
    for (int a = 0; a < 3; a++)
        CHECK(fabsf(o->lo[a] - 2 * ob->o[0].lo[a]) < 1e-3f && fabsf(o->hi[a] - 2 * ob->o[0].hi[a]) < 1e-3f,
              "scaled obstacle axis %d: %g..%g", a, o->lo[a], o->hi[a]);
    fs_sph_destroy(s);
}

/* A scene file refused: FS_ERR_INPUT, the file and `what` named, nothing made. */
static void refused(const char *name, const char *obstacles, const char *what)
{
    char path[512], text[1024];
    snprintf(path, sizeof path, DIR "/%s.json", name);
    snprintf(text, sizeof text,
             "{\"box\": [1.2, 0.8, 0.5], \"fluid\": [{\"min\": [0, 0, 0], \"max\": [0.5, 0.6, 0.5]}], "
             "%s}\n",
             obstacles);
    write_file(path, text);
    fs_sph_params p;
    fs_sph_params_default(&p);
    fs_sph *s = NULL;
    int rc = fs_sph_create(&s, path, 0, &p, 0);
    const char *msg = fs_error_message();
    printf("%s: %s\n", name, msg);
    CHECK(rc == FS_ERR_INPUT && strstr(msg, path) && strstr(msg, what), "%s: rc %d, %s", name, rc, msg);
    CHECK(s == NULL, "%s: made a simulator", name);
    fs_sph_destroy(s);
}

static void bad_obstacles(void)
{
    refused("min_above_max", "\"obstacles\": [{\"min\": [0.9, 0, 0.1], \"max\": [0.7, 0.3, 0.4]}]", "obstacles[0]");
    refused("negative_radius",
            "\"obstacles\": [{\"min\": [0.7, 0, 0.1], \"max\": [1, 0.3, 0.4]}, "
            "{\"centre\": [0.5, 0.2, 0.25], \"radius\": -0.1}]",
            "obstacles[1]");
    refused("unknown_key", "\"obstacles\": [{\"min\": [0.7, 0, 0.1], \"max\": [1, 0.3, 0.4], \"colour\": [1, 0, 0]}]",
            "obstacles[0]");
    refused("not_array", "\"obstacles\": {\"min\": [0.7, 0, 0.1], \"max\": [1, 0.3, 0.4]}", "obstacles");
    refused("misspelt", "\"obstacle\": []", "(box, fluid, obstacles)");
}

/* An OBJ cube of the box's corners, as quads (the reader fans them into triangles). */
static void write_cube(const char *path, const float lo[3], const float hi[3])
{
    char text[1024], *e = text;
    for (int v = 0; v < 8; v++)
        e += sprintf(e, "v %.9g %.9g %.9g\n", v & 1 ? hi[0] : lo[0], v & 2 ? hi[1] : lo[1], v & 4 ? hi[2] : lo[2]);
    sprintf(e, "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
    write_file(path, text);
}

/* A mesh obstacle that is the box exactly gives the box's boundary and fluid. */
static void check_mesh(const char *pbox, const fs_obstacles *box)
{
    const char *obj = DIR "/cube.obj", *pmesh = DIR "/mesh.json";
    write_cube(obj, box->o[0].lo, box->o[0].hi);
    char text[512];
    snprintf(text, sizeof text,
             "{\"box\": [%g, %g, %g], \"fluid\": [{\"min\": [%g, %g, %g], \"max\": [%g, %g, %g]}], "
             "\"obstacles\": [{\"mesh\": \"cube.obj\"}]}\n",
             BOX[0], BOX[1], BOX[2], FLUID_LO[0], FLUID_LO[1], FLUID_LO[2], FLUID_HI[0], FLUID_HI[1], FLUID_HI[2]);
    write_file(pmesh, text);
    fs_sph *a = make(pbox, 0), *b = make(pmesh, 0);
    if (a && b)
        CHECK(fs_sph_boundary_count(a) == fs_sph_boundary_count(b) && fs_sph_count(a) == fs_sph_count(b),
              "mesh cube: boundary %zu, fluid %zu; the box: %zu, %zu", fs_sph_boundary_count(b), fs_sph_count(b),
              fs_sph_boundary_count(a), fs_sph_count(a));
    fs_sph_destroy(a);
    fs_sph_destroy(b);
}

int main(void)
{
    mkdir(FS_TEST_OUT, 0755);
    mkdir(DIR, 0755);
    /* A block downstream of the dam, on the floor, 6^3 sites: a 2-layer shell
     * of 6^3 - 2^3 = 208 and 8 empty sites within. */
    fs_obstacles box = {1, {{.kind = FS_OBSTACLE_BOX, .lo = {0.7f, 0, 0.1f}, .hi = {1.0f, 0.3f, 0.4f}, .scale = 1}}};
    /* A ball on the floor cutting into the dam's front (its bounds as the parser sets them). */
    fs_obstacles ball = {1,
                         {{.kind = FS_OBSTACLE_SPHERE,
                           .lo = {0.55f - 0.15f, 0.15f - 0.15f, 0.25f - 0.15f},
                           .hi = {0.55f + 0.15f, 0.15f + 0.15f, 0.25f + 0.15f},
                           .c = {0.55f, 0.15f, 0.25f},
                           .radius = 0.15f,
                           .scale = 1}}};
    const char *plain = DIR "/plain.json", *pbox = DIR "/box.json", *pball = DIR "/ball.json";
    write_scene(plain, &(fs_obstacles){0});
    write_scene(pbox, &box);
    write_scene(pball, &ball);
    CHECK(count_lattice(&box, 0.025f).shell == 208, "box shell %zu, expected 6^3 - 2^3",
          count_lattice(&box, 0.025f).shell);
    bad_obstacles();
    fs_sph *dam = make("dam_break", 0);
    CHECK(dam && fs_sph_obstacles(dam)->n == 0, "built-in scenes have no obstacles");
    fs_sph_destroy(dam);
    check_build(pbox, plain, &box, "box obstacle");
    check_build(pball, plain, &ball, "sphere obstacle");
    check_scaled(pbox, &box);
    check_mesh(pbox, &box);
    check_flow(pbox, &box, 1, "dam break past a box");
    check_flow(pball, &ball, 0, "dam break into a sphere");
    TEST_DONE();
}
