/* surfels caustics (iwasaki2006 5.1-5.2) on synthetic surfel sets, y up, floor
 * at y = 0: (a) a flat slab lit from above gives L_i T(0) exp(-c) in the
 * interior; (b) a Gaussian bump on it focuses light like a lens, as an exact
 * radial ray map predicts (centre within 6%), on two planes; (c) no light
 * where no water lies above; (d) the flux on the floor equals the flux
 * entering the water without extinction; (e) oblique light shifts the lit
 * patch by tan(theta_t) per unit depth and transmits cos(theta_i) T(theta_i).
 * Also surfel_set growth, a hidden lower layer, back-facing surfels, an empty
 * set and bad setups. Writes the bump's floor map as a PNG (test-out/). */
#include "fs_error.h"
#include "fs_test.h"
#include "gl.h"
#include "test_gl_context.h"
#include "image_io.h"
#include "surfels/caustics.h"
#include "surfels/surfel_set.h"
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const float IOR = 1.33f;

static unsigned upload(const fs_surfel_set *set)
{
    unsigned b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, (GLsizeiptr)((set->n ? set->n : 1) * sizeof(fs_surfel)), set->s, 0);
    return b;
}

static void setup_defaults(fs_caustics_setup *s, float half)
{
    memset(s, 0, sizeof *s);
    s->up_axis = 1;
    s->light_dir[1] = 1;
    for (int k = 0; k < 3; k++) s->light_color[k] = 1;
    s->ior = IOR;
    s->rect_min[0] = s->rect_min[1] = -half;
    s->rect_max[0] = s->rect_max[1] = half;
    s->top = 2.0f;
    s->screen_res = 128;
    s->plane_res = 128;
    s->nplanes = 1;
}

/* Flat water at height y over |x|,|z| <= half (lattice spacing h, radius 1.2 h). */
static void flat(fs_surfel_set *set, float y, float half, float h)
{
    int m = (int)lroundf(2 * half / h);
    const float up[3] = {0, 1, 0};
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= m; i++) {
            float p[3] = {-half + i * h, y, -half + j * h};
            fs_surfel_push(set, p, up, 1.2f * h);
        }
}

/* Texel centre of plane texel (u, v): horizontal a = z along u, b = x along v. */
static void texel_pos(const fs_caustics_setup *s, int u, int v, float *z, float *x)
{
    *z = s->rect_min[0] + (u + 0.5f) * (s->rect_max[0] - s->rect_min[0]) / s->plane_res;
    *x = s->rect_min[1] + (v + 0.5f) * (s->rect_max[1] - s->rect_min[1]) / s->plane_res;
}

static const float *map_at(const fs_caustics *c, const fs_caustics_setup *s, int plane, int u, int v)
{
    return fs_caustics_maps(c) + 4 * ((size_t)plane * s->plane_res * s->plane_res + (size_t)v * s->plane_res + u);
}

static void test_surfel_set(void)
{
    fs_surfel_set set = {0};
    for (int i = 0; i < 5000; i++) {
        float p[3] = {(float)i, 0, 0}, n[3] = {0, 1, 0};
        CHECK(fs_surfel_push(&set, p, n, 0.5f) == FS_OK, "push");
    }
    CHECK(set.n == 5000 && set.cap >= 5000, "n %zu cap %zu", set.n, set.cap);
    CHECK(set.s[4321].pos[0] == 4321.0f && set.s[4321].normal[1] == 1.0f && set.s[4321].radius == 0.5f &&
              set.s[4321].pad == 0.0f,
          "stored surfel");
    CHECK(sizeof(fs_surfel) == 32, "layout: two vec4");
    fs_surfel_set_free(&set);
    CHECK(set.n == 0 && set.s == NULL, "freed");
}

/* (a) flat slab with extinction, (c) darkness outside, (d) flux balance. */
static void test_flat(fs_caustics *c)
{
    fs_caustics_setup s;
    setup_defaults(&s, 1.5f);
    const float cext[3] = {0.3f, 0.1f, 0.0f};
    memcpy(s.extinction, cext, sizeof cext);
    s.nplanes = 2;
    s.plane_height[0] = 0.0f;
    s.plane_height[1] = 0.5f;
    fs_surfel_set set = {0};
    flat(&set, 1.0f, 1.0f, 0.04f);
    unsigned buf = upload(&set);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    CHECK(fs_caustics_run(c, &s, buf, set.n) == FS_OK, "run: %s", fs_error_message());
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("flat slab, %zu surfels, screen %d^2, %d planes of %d^2: first run %.1f ms (%s)\n", set.n, s.screen_res,
           s.nplanes, s.plane_res, (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) * 1e-6,
           (const char *)glGetString(GL_RENDERER));
    double T0 = fs_caustics_transmittance(1.0, IOR);
    CHECK_NEAR(T0, 1.0 - pow((IOR - 1) / (IOR + 1), 2), 1e-9, "T(0)");
    double worst[2] = {0, 0};
    int nint = 0, nout = 0, dark_bad = 0;
    for (int v = 0; v < s.plane_res; v++)
        for (int u = 0; u < s.plane_res; u++) {
            float z, x;
            texel_pos(&s, u, v, &z, &x);
            float r = fmaxf(fabsf(z), fabsf(x));
            for (int k = 0; k < 2; k++) {
                const float *m = map_at(c, &s, k, u, v);
                if (r < 0.85f) {
                    for (int ch = 0; ch < 3; ch++) {
                        double want = T0 * exp(-cext[ch] * (1.0 - s.plane_height[k]));
                        worst[k] = fmax(worst[k], fabs(m[ch] / want - 1));
                    }
                    nint += k == 0;
                } else if (r > 1.12f) {
                    dark_bad += m[0] != 0 || m[1] != 0 || m[2] != 0;
                    nout += k == 0;
                }
            }
        }
    const float *mid = map_at(c, &s, 0, s.plane_res / 2, s.plane_res / 2);
    printf("(a) flat slab: floor centre %.5f %.5f %.5f, want %.5f %.5f %.5f; worst interior error floor %.3f%%, "
           "plane y=0.5 %.3f%% (%d texels)\n",
           mid[0], mid[1], mid[2], T0 * exp(-cext[0]), T0 * exp(-cext[1]), T0 * exp(-cext[2]), 100 * worst[0],
           100 * worst[1], nint);
    CHECK(worst[0] < 0.05 && worst[1] < 0.05, "interior irradiance off by %g / %g", worst[0], worst[1]);
    printf("(c) outside the water's shadow: %d of %d texels per plane not exactly 0\n", dark_bad, nout);
    CHECK(dark_bad == 0, "%d texels lit outside the shadow", dark_bad);
    fs_caustics_set_max_jump(c, 4);
    s.extinction[0] = s.extinction[1] = s.extinction[2] = 0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    CHECK(fs_caustics_run(c, &s, buf, set.n) == FS_OK, "run: %s", fs_error_message());
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("    second run (shaders compiled): %.1f ms\n",
           (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) * 1e-6);
    double fin = fs_caustics_flux_in(c), f0 = fs_caustics_flux_plane(c, 0), f1 = fs_caustics_flux_plane(c, 1);
    double side = 2.0 + 2 * 1.2 * 0.04; /* the water's shadow: the lattice plus the disks' rims */
    printf("(d) flat, no extinction: %zu volumes, flux in %.6f, floor %.6f (ratio %.6f), plane y=0.5 %.6f (%.6f); "
           "T(0) x area %.6f\n",
           fs_caustics_triangles(c), fin, f0, f0 / fin, f1, f1 / fin, T0 * side * side);
    CHECK(fabs(f0 / fin - 1) < 0.01 && fabs(f1 / fin - 1) < 0.01, "flux balance %g %g", f0 / fin, f1 / fin);
    CHECK(fabs(fin / (T0 * side * side) - 1) < 0.03, "flux in %g vs the water's area x T(0) %g", fin, T0 * side * side);
    /* screen 64^2, planes 128^2: every triangle edge lies on texel edges (counted once?) */
    s.screen_res = 64;
    CHECK(fs_caustics_run(c, &s, buf, set.n) == FS_OK, "run: %s", fs_error_message());
    double worst2 = 0;
    for (int v = 0; v < s.plane_res; v++)
        for (int u = 0; u < s.plane_res; u++) {
            float z, x;
            texel_pos(&s, u, v, &z, &x);
            if (fmaxf(fabsf(z), fabsf(x)) < 0.85f) worst2 = fmax(worst2, fabs(map_at(c, &s, 0, u, v)[1] / T0 - 1));
        }
    double r2 = fs_caustics_flux_plane(c, 0) / fs_caustics_flux_in(c);
    printf("    screen 64^2 on planes 128^2 (edges on texel edges): worst interior error %.2e, flux ratio %.6f\n",
           worst2, r2);
    CHECK(worst2 < 1e-4 && fabs(r2 - 1) < 1e-4, "edges on texel edges: %g, ratio %g", worst2, r2);
    glDeleteBuffers(1, &buf);
    fs_surfel_set_free(&set);
}

/* Flat water (y = 1, disk of radius 1.3) with a Gaussian bump of height BA and
 * width BW, y = 1 + BA exp(-r^2 / BW^2): near the axis a sphere of radius
 * BW^2 / (2 BA), a converging lens; beyond the inflection (r = BW / sqrt 2) it
 * diverges. No fold above the floor: the map is smooth. Surfels on a lattice of
 * spacing h, radius 1.2 h / n_y (no holes on the slopes). */
#define BA 0.1f
#define BW 0.3f
static void bump_surface(fs_surfel_set *set, float h)
{
    int m = (int)lroundf(2.6f / h);
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= m; i++) {
            float x = -1.3f + i * h, z = -1.3f + j * h, rr = x * x + z * z;
            if (rr > 1.3f * 1.3f) continue;
            float g = BA * expf(-rr / (BW * BW)), dg = -2 * g / (BW * BW); /* dy/dx = dg x */
            float n[3] = {-dg * x, 1, -dg * z}, l = sqrtf(n[0] * n[0] + 1 + n[2] * n[2]);
            for (int k = 0; k < 3; k++) n[k] /= l;
            float p[3] = {x, 1.0f + g, z};
            fs_surfel_push(set, p, n, 1.2f * h / n[1]);
        }
}

/* The exact map under the bump for vertical light (radial symmetry): the ray
 * entering at radius r lands on the plane at height h at radius land(r), and
 * the irradiance there is L T(r) r dr / (r' dr') (flux L T per unit horizontal
 * area of water). Returns r' and sets *T. */
static double land(double r, double h, double *T)
{
    double g = BA * exp(-r * r / (BW * BW)), m = -2 * g * r / (BW * BW), l = sqrt(1 + m * m);
    double nr = -m / l, ny = 1 / l, eta = 1 / (double)IOR;
    double ci = ny, ct = sqrt(1 - eta * eta * (1 - ci * ci));
    double tr = (eta * ci - ct) * nr, ty = -eta + (eta * ci - ct) * ny;
    *T = fs_caustics_transmittance(ci, IOR);
    return r + tr * (1 + g - h) / -ty;
}
static double exact_irradiance(double rp, double h)
{
    double lo = 0, hi = 1, T, d = 1e-6;
    for (int i = 0; i < 60; i++) { /* land() is monotone: no fold above the planes tested */
        double mid = 0.5 * (lo + hi);
        if (land(mid, h, &T) < rp) lo = mid;
        else hi = mid;
    }
    double r1 = land(lo, h, &T), r2 = land(lo + d, h, &T);
    return rp < 1e-9 ? T * pow(d / (r2 - r1), 2) : T * lo * d / (r1 * (r2 - r1));
}
/* Its mean over the square |x|, |z| < half (the 2x2 texels around the axis). */
static double exact_centre(double h, double half)
{
    const int N = 24;
    double sum = 0;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++)
            sum += exact_irradiance(hypot(((i + 0.5) / N * 2 - 1) * half, ((j + 0.5) / N * 2 - 1) * half), h);
    return sum / (N * N);
}

/* The whole map against the exact one (texel means from 4x4 samples of a
 * radial table) over texels within radius rmax of the axis: max and RMS of the
 * relative error. Stripes or speckle would show here. */
static void map_error(const fs_caustics *c, const fs_caustics_setup *s, int plane, double rmax, double *emax,
                      double *erms)
{
    enum { NT = 2048 };
    static double tab[NT + 1];
    const double dr = 1.3 / NT;
    for (int i = 0; i <= NT; i++) tab[i] = exact_irradiance(i * dr, s->plane_height[plane]);
    int n = s->plane_res, cnt = 0;
    double dx = 3.0 / n, sum2 = 0;
    *emax = 0;
    for (int v = 0; v < n; v++)
        for (int u = 0; u < n; u++) {
            float z, x;
            texel_pos(s, u, v, &z, &x);
            if (hypot(z, x) > rmax) continue;
            double want = 0;
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++) {
                    double r = hypot(z + ((i + 0.5) / 4 - 0.5) * dx, x + ((j + 0.5) / 4 - 0.5) * dx) / dr;
                    int k = (int)r;
                    want += (tab[k] + (r - k) * (tab[k + 1] - tab[k])) / 16;
                }
            double e = map_at(c, s, plane, u, v)[1] / want - 1;
            *emax = fmax(*emax, fabs(e));
            sum2 += e * e;
            cnt++;
        }
    *erms = sqrt(sum2 / cnt);
}

static void write_png(const fs_caustics *c, const fs_caustics_setup *s, int plane, double scale, const char *name)
{
    int w = s->plane_res;
    float *pix = malloc((size_t)w * w * 3 * sizeof *pix);
    for (int v = 0; v < w; v++)
        for (int u = 0; u < w; u++) {
            const float *m = map_at(c, s, plane, u, v);
            for (int ch = 0; ch < 3; ch++) pix[3 * ((size_t)(w - 1 - v) * w + u) + ch] = (float)(m[ch] * scale);
        }
    const char *names[3] = {"R", "G", "B"};
    fs_image img = {w, w, 3, names, pix};
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", FS_TEST_OUT, name);
    CHECK(fs_write_png(path, &img) == FS_OK, "png: %s", fs_error_message());
    free(pix);
}

/* (b) focusing; and the flux balance with a curved surface. */
static void test_bump(fs_caustics *c)
{
    fs_caustics_setup s;
    setup_defaults(&s, 1.5f);
    s.plane_res = 192;
    s.nplanes = 2;
    s.plane_height[0] = 0.0f;
    s.plane_height[1] = 0.5f;
    fs_surfel_set set = {0};
    bump_surface(&set, 0.02f);
    unsigned buf = upload(&set);
    CHECK(fs_caustics_run(c, &s, buf, set.n) == FS_OK, "run: %s", fs_error_message());
    double T0 = fs_caustics_transmittance(1.0, IOR);
    float mx = 0;
    for (int k = 0; k < 2; k++) {
        int n = s.plane_res;
        double centre = 0; /* the mean of the 2x2 texels around the axis */
        for (int dv = -1; dv <= 0; dv++)
            for (int du = -1; du <= 0; du++) centre += map_at(c, &s, k, n / 2 + du, n / 2 + dv)[1] / 4.0;
        float kmax = 0;
        for (int v = 0; v < n; v++)
            for (int u = 0; u < n; u++) kmax = fmaxf(kmax, map_at(c, &s, k, u, v)[1]);
        if (!k) mx = kmax;
        float flat_v = map_at(c, &s, k, n / 2, n / 2 + (int)(1.1f / 3.0f * n))[1]; /* x = 1.1: flat water */
        double want = exact_centre(s.plane_height[k], 3.0 / n);
        printf("(b) bump, plane y=%.1f: flat %.4f (T(0) %.4f), centre %.4f = %.3f x flat (exact %.4f: %+.2f%%), max "
               "%.4f = %.3f x flat; flux in %.5f, on plane %.5f (ratio %.6f)\n",
               s.plane_height[k], flat_v, T0, centre, centre / flat_v, want, 100 * (centre / want - 1), kmax,
               kmax / flat_v, fs_caustics_flux_in(c), fs_caustics_flux_plane(c, k),
               fs_caustics_flux_plane(c, k) / fs_caustics_flux_in(c));
        CHECK(fabs(flat_v / T0 - 1) < 1e-3, "flat part %g", flat_v);
        CHECK(kmax > 1.5 * flat_v, "no focusing: max %g flat %g", kmax, flat_v);
        CHECK(fabs(centre / want - 1) < 0.06, "centre %g, exact %g", centre, want);
        CHECK(fabs(fs_caustics_flux_plane(c, k) / fs_caustics_flux_in(c) - 1) < 0.01, "flux balance");
        double emax, erms;
        map_error(c, &s, k, 1.2, &emax, &erms);
        printf("    whole map within r < 1.2 against the exact one: max error %.2f%%, rms %.3f%%\n", 100 * emax,
               100 * erms);
        CHECK(emax < 0.08 && erms < 0.01, "map error max %g rms %g", emax, erms);
    }
    /* tone: linear, the maximum white */
    write_png(c, &s, 0, 1.0 / mx, "caustics_bump_floor.png");
    glDeleteBuffers(1, &buf);
    fs_surfel_set_free(&set);
}

/* (f) past the focus: ripples y = 1 + A (cos kx + cos kz), wavelength 0.5,
 * A = 0.03 (crest focal length ~0.85 per axis) fold the light map above the
 * floor into the network of caustic lines seen on pool floors; the folds and
 * the near-degenerate triangles along them must keep the flux and stay finite. */
static void test_fold(fs_caustics *c)
{
    fs_caustics_setup s;
    setup_defaults(&s, 1.5f);
    s.plane_res = 256;
    s.screen_res = 256;
    s.plane_height[0] = 0.0f;
    const float A = 0.03f, k = 2 * (float)M_PI / 0.5f, h = 0.01f;
    fs_surfel_set set = {0};
    int m = (int)lroundf(2.6f / h);
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= m; i++) {
            float x = -1.3f + i * h, z = -1.3f + j * h;
            float p[3] = {x, 1.0f + A * (cosf(k * x) + cosf(k * z)), z};
            float nn[3] = {A * k * sinf(k * x), 1, A * k * sinf(k * z)};
            float l = sqrtf(nn[0] * nn[0] + 1 + nn[2] * nn[2]);
            for (int q = 0; q < 3; q++) nn[q] /= l;
            fs_surfel_push(&set, p, nn, 1.2f * h / nn[1]);
        }
    unsigned buf = upload(&set);
    CHECK(fs_caustics_run(c, &s, buf, set.n) == FS_OK, "run: %s", fs_error_message());
    size_t n = (size_t)s.plane_res * s.plane_res;
    double mx = 0;
    int bad = 0;
    for (size_t i = 0; i < n; i++) {
        const float *mp = fs_caustics_maps(c) + 4 * i;
        bad += !isfinite(mp[0]) || !isfinite(mp[1]) || !isfinite(mp[2]) || mp[1] < 0;
        mx = fmax(mx, mp[1]);
    }
    double ratio = fs_caustics_flux_plane(c, 0) / fs_caustics_flux_in(c);
    printf("(f) ripples past the focus: max %.3f x T(0), flux ratio %.6f, %d non-finite or negative texels\n",
           mx / fs_caustics_transmittance(1, IOR), ratio, bad);
    CHECK(bad == 0, "%d bad texels", bad);
    CHECK(fabs(ratio - 1) < 1e-3, "flux ratio past the focus %g", ratio);
    write_png(c, &s, 0, 1.0 / mx, "caustics_ripples_floor.png");
    glDeleteBuffers(1, &buf);
    fs_surfel_set_free(&set);
}

/* (e) oblique light in the a-z plane: the lit patch shifts by -tan(theta_t)
 * per unit of depth along z; interior irradiance cos(theta_i) T(theta_i). */
static void test_oblique(fs_caustics *c)
{
    fs_caustics_setup s;
    setup_defaults(&s, 2.0f);
    s.top = 1.5f;
    const double th = 30.0 * M_PI / 180.0;
    s.light_dir[0] = 0;
    s.light_dir[1] = (float)cos(th);
    s.light_dir[2] = (float)sin(th); /* axis a = z */
    s.plane_height[0] = 0.0f;
    fs_surfel_set set = {0};
    flat(&set, 1.0f, 1.0f, 0.04f);
    unsigned buf = upload(&set);
    CHECK(fs_caustics_run(c, &s, buf, set.n) == FS_OK, "run: %s", fs_error_message());
    double sum = 0, sz = 0, sx = 0;
    int n = s.plane_res;
    for (int v = 0; v < n; v++)
        for (int u = 0; u < n; u++) {
            float z, x;
            texel_pos(&s, u, v, &z, &x);
            double m = map_at(c, &s, 0, u, v)[1];
            sum += m;
            sz += m * z;
            sx += m * x;
        }
    double tt = tan(asin(sin(th) / IOR)), ci = cos(th), want = ci * fs_caustics_transmittance(ci, IOR);
    double cz = sz / sum, cx = sx / sum;
    float z0 = (float)-tt, x0 = 0; /* patch centre */
    int u0 = (int)((z0 + 2.0f) / 4.0f * n), v0 = (int)((x0 + 2.0f) / 4.0f * n);
    double centre = map_at(c, &s, 0, u0, v0)[1];
    printf("(e) oblique 30 deg: lit patch centroid z %.4f x %.4f, want %.4f 0; irradiance %.4f, want cos T = %.4f; "
           "flux ratio %.5f\n",
           cz, cx, -tt, centre, want, fs_caustics_flux_plane(c, 0) / fs_caustics_flux_in(c));
    CHECK(fabs(cz + tt) < 0.01 && fabs(cx) < 0.01, "patch centroid (%g, %g)", cz, cx);
    CHECK(fabs(centre / want - 1) < 0.02, "oblique irradiance %g vs %g", centre, want);
    CHECK(fabs(fs_caustics_flux_plane(c, 0) / fs_caustics_flux_in(c) - 1) < 0.01, "oblique flux balance");
    glDeleteBuffers(1, &buf);
    fs_surfel_set_free(&set);
}

/* A second, lower layer (y = 0.5) under the slab is hidden: the result equals
 * the slab alone. Surfels facing away from the light draw nothing. */
static void test_layers(fs_caustics *c)
{
    fs_caustics_setup s;
    setup_defaults(&s, 1.5f);
    s.plane_res = 64;
    s.screen_res = 64;
    s.plane_height[0] = 0.0f;
    fs_surfel_set one = {0}, two = {0}, down = {0};
    flat(&one, 1.0f, 1.0f, 0.05f);
    flat(&two, 1.0f, 1.0f, 0.05f);
    flat(&two, 0.5f, 1.0f, 0.05f);
    flat(&down, 1.0f, 1.0f, 0.05f);
    for (size_t i = 0; i < down.n; i++) down.s[i].normal[1] = -1;
    size_t nt = (size_t)s.plane_res * s.plane_res * 4;
    float *a = malloc(nt * sizeof *a);
    unsigned b1 = upload(&one), b2 = upload(&two), b3 = upload(&down);
    CHECK(fs_caustics_run(c, &s, b1, one.n) == FS_OK, "run: %s", fs_error_message());
    memcpy(a, fs_caustics_maps(c), nt * sizeof *a);
    CHECK(fs_caustics_run(c, &s, b2, two.n) == FS_OK, "run: %s", fs_error_message());
    double diff = 0;
    for (size_t i = 0; i < nt; i++) diff = fmax(diff, fabs(a[i] - fs_caustics_maps(c)[i]));
    printf("layers: hidden lower layer changes the floor by at most %.2e\n", diff);
    CHECK(diff < 1e-5, "a hidden layer changed the floor by %g", diff);
    CHECK(fs_caustics_run(c, &s, b3, down.n) == FS_OK, "run: %s", fs_error_message());
    double mx = 0;
    for (size_t i = 0; i < nt; i++) mx = fmax(mx, fabs(fs_caustics_maps(c)[i]));
    CHECK(mx == 0 && fs_caustics_triangles(c) == 0, "back-facing surfels lit the floor (%g)", mx);
    CHECK(fs_caustics_run(c, &s, b1, 0) == FS_OK && fs_caustics_flux_in(c) == 0, "empty set");
    unsigned bufs[3] = {b1, b2, b3};
    glDeleteBuffers(3, bufs);
    free(a);
    fs_surfel_set_free(&one);
    fs_surfel_set_free(&two);
    fs_surfel_set_free(&down);
}

static void test_bad(fs_caustics *c)
{
    fs_caustics_setup s;
    setup_defaults(&s, 1.0f);
    s.light_dir[1] = -1;
    CHECK(fs_caustics_run(c, &s, 0, 0) == FS_ERR_INPUT, "light from below accepted");
    setup_defaults(&s, 1.0f);
    s.plane_height[0] = 3.0f;
    CHECK(fs_caustics_run(c, &s, 0, 0) == FS_ERR_INPUT, "plane above the screen accepted");
    setup_defaults(&s, 1.0f);
    s.nplanes = FS_CAUSTICS_MAX_PLANES + 1;
    CHECK(fs_caustics_run(c, &s, 0, 0) == FS_ERR_INPUT, "too many planes accepted");
    setup_defaults(&s, 1.0f);
    s.rect_max[0] = s.rect_min[0];
    CHECK(fs_caustics_run(c, &s, 0, 0) == FS_ERR_INPUT, "empty rectangle accepted");
}

int main(void)
{
    fs_gl_context ctx;
    if (fs_test_gl_context(&ctx)) TEST_DONE();
    test_surfel_set();
    fs_caustics *c = fs_caustics_create();
    CHECK(c != NULL, "create: %s", fs_error_message());
    if (c) {
        test_flat(c);
        test_bump(c);
        test_fold(c);
        test_oblique(c);
        test_layers(c);
        test_bad(c);
        fs_caustics_destroy(c);
    }
    CHECK(glGetError() == GL_NO_ERROR, "GL error");
    fs_gl_context_destroy(&ctx);
    TEST_DONE();
}
