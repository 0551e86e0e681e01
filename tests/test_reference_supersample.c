/* reference.supersample and the note of a small radius (issue 32, part 8):
 * supersample=1 is the default's output bit for bit; on a jittered sphere whose r
 * is about a pixel, 2 x 2 rays bring the normals closer to an 8 x 8 render than
 * one ray does, and leave fractional coverage at the silhouette; the note of r
 * under 2 px comes once per run at a small image, not at a large one, and not
 * where the rays a pixel make up for it (r N >= 2 px). */
#include "fs_error.h"
#include "fs_test.h"
#include "method.h"
#include "builtin_methods.h"
#include "run.h"
#include "synthetic.h"
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>

/* A jittered synthetic sphere of 20 particles across, framed at size x size. */
static void sphere(fs_scene *s, fs_particles *p, fs_camera *cam, int size)
{
    fs_scene_defaults(s);
    s->synth.shape = FS_SYNTH_SPHERE;
    s->synth.jitter = 0.3f;
    s->synth.seed = 7;
    fs_synthetic_generate(s, 0, p);
    *cam = s->camera;
    cam->width = cam->height = size;
    fs_camera_frame_box(cam, p->bmin, p->bmax, s->up_axis);
    fs_camera_fit_clip(cam, p->bmin, p->bmax);
}

/* The reference with "reference.P=V" settings (NULL-terminated) into out; renders
 * it `times` times in one run (the note is once per run). */
static int render(const fs_scene *s0, const fs_particles *p, const fs_camera *cam, const char *const *sets, int times,
                  fs_gbuffer *out)
{
    static fs_scene s; /* the run keeps a pointer until closed */
    s = *s0;
    const fs_method *m = fs_method_find("reference");
    fs_run *run = NULL;
    int rc = m ? FS_OK : fs_fail(FS_ERR_RUNTIME, "reference not registered");
    for (int i = 0; sets && sets[i] && !rc; i++) rc = fs_scene_add_set(&s, sets[i]);
    if (!rc) rc = fs_run_open(&run, m, &s, NULL, NULL);
    if (!rc) rc = fs_run_upload(run, p, NULL, NULL);
    for (int i = 0; i < times && !rc; i++) {
        fs_run_image im = {0};
        rc = fs_run_render(run, cam, &im, NULL);
        if (!rc) {
            fs_gbuffer_free(out);
            *out = im.g;
        } else fs_run_image_free(&im);
    }
    fs_run_close(run);
    CHECK(rc == FS_OK, "render: %s", fs_error_message());
    return rc;
}

static int same_layer(const float *a, const float *b, size_t n) { return !memcmp(a, b, n * sizeof *a); }

/* Mean angle (degrees) between the normals of a and b where both cover >= 0.5. */
static double normal_error(const fs_gbuffer *a, const fs_gbuffer *b, size_t *count)
{
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)a->w * a->h; i++) {
        if (a->coverage[i] < 0.5f || b->coverage[i] < 0.5f) continue;
        const float *u = a->normal + 3 * i, *v = b->normal + 3 * i;
        double c = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        sum += acos(c > 1 ? 1 : c < -1 ? -1 : c) * 180 / M_PI;
        n++;
    }
    *count = n;
    return n ? sum / n : NAN;
}

static void default_unchanged(void)
{
    fs_scene s;
    fs_particles p;
    fs_camera cam;
    fs_gbuffer a = {0}, b = {0};
    sphere(&s, &p, &cam, 64);
    const char *one[] = {"reference.supersample=1", NULL};
    if (!render(&s, &p, &cam, NULL, 1, &a) && !render(&s, &p, &cam, one, 1, &b)) {
        size_t n = (size_t)a.w * a.h;
        CHECK(same_layer(a.depth, b.depth, n) && same_layer(a.normal, b.normal, 3 * n) &&
                  same_layer(a.thickness, b.thickness, n) && same_layer(a.coverage, b.coverage, n),
              "supersample=1 is the default's G-buffer bit for bit");
        size_t hit = 0;
        for (size_t i = 0; i < n; i++) hit += a.coverage[i] == 1.0f;
        CHECK(hit > 500, "the sphere covers pixels: %zu", hit);
    }
    fs_gbuffer_free(&a);
    fs_gbuffer_free(&b);
    fs_particles_free(&p);
}

/* r about a pixel: the sphere (40 r across) in 48 pixels. */
static void small_radius(void)
{
    fs_scene s;
    fs_particles p;
    fs_camera cam;
    fs_gbuffer g1 = {0}, g2 = {0}, g8 = {0};
    sphere(&s, &p, &cam, 48);
    const char *two[] = {"reference.supersample=2", NULL}, *eight[] = {"reference.supersample=8", NULL};
    if (render(&s, &p, &cam, NULL, 1, &g1) || render(&s, &p, &cam, two, 1, &g2) || render(&s, &p, &cam, eight, 1, &g8))
        goto done;
    size_t n1, n2, frac1 = 0, frac2 = 0, n = (size_t)g1.w * g1.h;
    double e1 = normal_error(&g1, &g8, &n1), e2 = normal_error(&g2, &g8, &n2);
    printf("r ~ 1 px: normal error against 8 x 8 rays: %.2f deg at 1 ray (%zu px), %.2f deg at 2 x 2 (%zu px)\n", e1,
           n1, e2, n2);
    CHECK(n1 > 300 && n2 > 300, "pixels compared: %zu, %zu", n1, n2);
    CHECK(e1 > 1, "one ray a pixel is off the 8 x 8 rays' normals by over a degree (the moire): %.2f deg", e1);
    CHECK(e2 < 0.75 * e1, "2 x 2 rays are closer to 8 x 8 than 1 ray: %.2f against %.2f deg", e2, e1);
    size_t unit = 0;
    for (size_t i = 0; i < n; i++) {
        frac1 += g1.coverage[i] > 0 && g1.coverage[i] < 1;
        frac2 += g2.coverage[i] > 0 && g2.coverage[i] < 1;
        if (g2.coverage[i] > 0) {
            const float *v = g2.normal + 3 * i;
            unit += fabs(sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) - 1) < 1e-5 && v[2] > 0;
            CHECK(isfinite(g2.depth[i]), "pixel %zu: covered in part, with a depth", i);
        }
    }
    size_t covered2 = 0;
    for (size_t i = 0; i < n; i++) covered2 += g2.coverage[i] > 0;
    CHECK(frac1 == 0 && frac2 > 20, "fractional coverage at the silhouette: %zu px at 2 x 2, %zu at 1 ray", frac2,
          frac1);
    CHECK(unit == covered2, "renormalised normals, facing the camera: %zu of %zu", unit, covered2);
done:
    fs_gbuffer_free(&g1);
    fs_gbuffer_free(&g2);
    fs_gbuffer_free(&g8);
    fs_particles_free(&p);
}

/* The notes of `times` renders in one run at size x size with settings sets
 * (NULL-terminated, or NULL), read from stderr. */
static void notes_of(int size, int times, const char *const *sets, char *text, size_t cap)
{
    fs_scene s;
    fs_particles p;
    fs_camera cam;
    fs_gbuffer g = {0};
    char path[512];
    snprintf(path, sizeof path, "%s/reference_supersample_notes.txt", FS_TEST_OUT);
    sphere(&s, &p, &cam, size);
    fflush(stderr);
    int saved = dup(2), fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 2);
    render(&s, &p, &cam, sets, times, &g);
    fflush(stderr);
    dup2(saved, 2);
    close(fd);
    close(saved);
    FILE *f = fopen(path, "r");
    size_t got = f ? fread(text, 1, cap - 1, f) : 0;
    text[got] = 0;
    if (f) fclose(f);
    fs_gbuffer_free(&g);
    fs_particles_free(&p);
}

static void note(void)
{
    char text[4096];
    notes_of(48, 2, NULL, text, sizeof text);
    const char *prefix = "fluidsurf: note: reference: r is ", *at = strstr(text, prefix);
    CHECK(at && strstr(at, " px at the particles' centre (under 2 px") && strstr(at, "reference.supersample=3 ") &&
              !strstr(at + strlen(prefix), "r is"),
          "r ~ 1 px: one note over two renders, naming the setting: %s", text);
    double px = at ? atof(at + strlen(prefix)) : 0;
    CHECK(px > 0.5 && px < 2, "r ~ 1 px: %g px", px);
    notes_of(256, 1, NULL, text, sizeof text);
    CHECK(!strstr(text, "reference: r is"), "r ~ 5 px: no note: %s", text);
    const char *three[] = {"reference.supersample=3", NULL};
    notes_of(48, 1, three, text, sizeof text);
    CHECK(!strstr(text, "reference: r is"), "r ~ 0.7 px at 3 x 3 rays a pixel (r ~ 2 sub-rays): no note: %s", text);
}

int main(void)
{
    fs_methods_register_builtin();
    default_unchanged();
    small_radius();
    note();
    TEST_DONE();
}
