/* Figure building blocks: text lands inside its measured box, heatmap colours and
 * colour bar, panel layout (size, tile positions, captions and headers). Writes
 * heatmap and panel PNGs to FS_TEST_OUT for a look. */
#include "figure.h"
#include "fs_error.h"
#include "fs_test.h"
#include "image_io.h"
#include <string.h>

static const float WHITE[4] = {1, 1, 1, 1};
static const float BLACK_RGB[3] = {0, 0, 0};

static const float *px(const fs_rgba_image *im, int x, int y) { return im->pix + 4 * ((size_t)y * im->w + x); }

static int same_rgb(const float *a, const float *b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

static int is_white(const float *p) { return p[0] > 0.98f && p[1] > 0.98f && p[2] > 0.98f; }

static double luminance(const float *p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

/* Pixels in [x0,x1) x [y0,y1) (clipped) that are not white. */
static int ink_in(const fs_rgba_image *im, int x0, int y0, int x1, int y1)
{
    int n = 0;
    for (int y = y0 < 0 ? 0 : y0; y < y1 && y < im->h; y++)
        for (int x = x0 < 0 ? 0 : x0; x < x1 && x < im->w; x++) n += !is_white(px(im, x, y));
    return n;
}

static void write_png(const char *name, const fs_rgba_image *im)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", FS_TEST_OUT, name);
    fs_image img = {im->w, im->h, 4, NULL, im->pix};
    CHECK(fs_write_png(path, &img) == FS_OK, "%s: %s", path, fs_error_message());
}

static void test_text(void)
{
    const char *text = "Fluid 42 (deg)";
    int w = 0, h = 0, w2 = 0, h2 = 0;
    CHECK(fs_text_size(text, 12, &w, &h) == FS_OK, "%s", fs_error_message());
    CHECK(w > 40 && w < 160 && h >= 10 && h <= 24, "text box %dx%d at size 12", w, h);
    CHECK(fs_text_size(text, 24, &w2, &h2) == FS_OK, "%s", fs_error_message());
    CHECK(w2 > 17 * w / 10 && h2 > 17 * h / 10, "size 24 box %dx%d vs size 12 %dx%d", w2, h2, w, h);

    fs_rgba_image im;
    const int x = 20, y = 15;
    CHECK(fs_rgba_alloc(&im, 200, 50, WHITE) == FS_OK, "alloc");
    CHECK(fs_draw_text(&im, x, y, text, 12, BLACK_RGB) == FS_OK, "%s", fs_error_message());
    int inside = ink_in(&im, x, y, x + w, y + h), all = ink_in(&im, 0, 0, im.w, im.h);
    int left = ink_in(&im, x, y, x + w / 4, y + h), right = ink_in(&im, x + 3 * w / 4, y, x + w, y + h);
    CHECK(inside > w * h / 10, "only %d inked pixels in the %dx%d text box", inside, w, h);
    CHECK(left > 0 && right > 0, "text spans its box: left quarter %d, right quarter %d", left, right);
    CHECK(ink_in(&im, x - 1, y - 1, x + w + 1, y + h + 1) == all, "%d inked pixels outside the box + 1 px",
          all - ink_in(&im, x - 1, y - 1, x + w + 1, y + h + 1));
    float darkest = 1;
    for (int i = 0; i < im.w * im.h; i++) darkest = im.pix[4 * i] < darkest ? im.pix[4 * i] : darkest;
    CHECK(darkest < 0.05f, "text colour reached: darkest %g", darkest);
    CHECK(px(&im, 5, 5)[3] == 1 && px(&im, x + w / 2, y + h / 2)[3] == 1, "alpha stays 1");

    /* Coloured text on black: only red ink. */
    const float red[3] = {1, 0, 0}, black[4] = {0, 0, 0, 1};
    fs_rgba_image dark;
    CHECK(fs_rgba_alloc(&dark, 120, 30, black) == FS_OK, "alloc");
    CHECK(fs_draw_text(&dark, 2, 2, "red", 14, red) == FS_OK, "%s", fs_error_message());
    double r = 0, gb = 0;
    for (int i = 0; i < dark.w * dark.h; i++) r += dark.pix[4 * i], gb += dark.pix[4 * i + 1] + dark.pix[4 * i + 2];
    CHECK(r > 10 && gb == 0, "red text: red sum %g, green+blue sum %g", r, gb);

    CHECK(fs_draw_text(&im, 0, 0, "x", 0, BLACK_RGB) == FS_ERR_INPUT, "font size 0 must be rejected");
    CHECK(fs_text_size("", 12, &w, &h) == FS_OK && w == 0, "empty text is 0 wide");
    fs_rgba_free(&im);
    fs_rgba_free(&dark);
    CHECK(im.pix == NULL, "free clears");
}

static void test_heatmap(void)
{
    enum { W = 128, H = 128, RAMP_ROWS = 96, NAN_ROW = 100, HIGH_ROW = 116 };
    const double vmax = 10;
    static float v[W * H];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float *p = &v[y * W + x];
            if (y < RAMP_ROWS) *p = (float)(vmax * x / (W - 1));
            else if (y < HIGH_ROW) *p = NAN;
            else *p = x < W / 2 ? (float)(2 * vmax) : -1.0f; /* above vmax; below 0 */
        }
    int ow, oh, dx, dy;
    CHECK(fs_heatmap_layout(W, H, vmax, "normal error (deg)", "deg", &ow, &oh, &dx, &dy) == FS_OK, "%s",
          fs_error_message());
    fs_rgba_image hm;
    CHECK(fs_heatmap(v, W, H, vmax, "normal error (deg)", "deg", &hm) == FS_OK, "%s", fs_error_message());
    if (!hm.pix) return;
    CHECK(hm.w == ow && hm.h == oh, "heatmap %dx%d, layout says %dx%d", hm.w, hm.h, ow, oh);
    CHECK(dx == 0 && dy > 11 && ow >= W + 16 + 20 && ow <= W + 120 && oh >= H + dy && oh <= H + 3 * dy,
          "layout %dx%d data at (%d,%d)", ow, oh, dx, dy);

    /* Ramp: luminance never falls and rises overall; every ramp row is the same. */
    const float *first = px(&hm, dx, dy), *last = px(&hm, dx + W - 1, dy);
    int falls = 0;
    for (int x = 1; x < W; x++) falls += luminance(px(&hm, dx + x, dy)) < luminance(px(&hm, dx + x - 1, dy)) - 1e-4;
    CHECK(falls == 0, "ramp luminance falls %d times", falls);
    for (int k = 1; k <= 8; k++) {
        double a = luminance(px(&hm, dx + (k - 1) * (W - 1) / 8, dy)), b = luminance(px(&hm, dx + k * (W - 1) / 8, dy));
        CHECK(b > a + 0.005, "ramp eighth %d: luminance %g -> %g", k, a, b);
    }
    CHECK(!same_rgb(first, last) && first[2] > first[1] && last[1] > last[2], "0 is blue-purple, vmax yellow");
    CHECK(same_rgb(px(&hm, dx + 5, dy), px(&hm, dx + 5, dy + RAMP_ROWS - 1)), "ramp rows agree");

    /* NaN: dark grey, unlike any value; above vmax = vmax, below 0 = 0. */
    const float *nan = px(&hm, dx + 40, dy + NAN_ROW);
    CHECK(nan[0] == nan[1] && nan[1] == nan[2] && nan[0] > 0.02f && nan[0] < 0.2f, "no data grey %g %g %g", nan[0],
          nan[1], nan[2]);
    int grey_in_ramp = 0;
    for (int x = 0; x < W; x++) grey_in_ramp += same_rgb(px(&hm, dx + x, dy), nan);
    CHECK(grey_in_ramp == 0, "no-data grey appears %d times in the ramp", grey_in_ramp);
    CHECK(same_rgb(px(&hm, dx + 3, dy + HIGH_ROW), last), "above vmax saturates to vmax's colour");
    CHECK(same_rgb(px(&hm, dx + W - 3, dy + HIGH_ROW), first), "below 0 clips to 0's colour");

    /* Colour bar right of the data: vmax colour on top, 0 at the bottom, framed. */
    int bar_x = -1;
    for (int x = dx + W; x < hm.w && bar_x < 0; x++)
        if (same_rgb(px(&hm, x, dy), last) && same_rgb(px(&hm, x, dy + H - 1), first)) bar_x = x;
    CHECK(bar_x > dx + W, "colour bar found at x %d", bar_x);
    if (bar_x > 0) {
        int bw = 0;
        while (bar_x + bw < hm.w && same_rgb(px(&hm, bar_x + bw, dy), last)) bw++;
        CHECK(bw >= 14 && bw <= 20, "bar is %d px wide", bw);
        CHECK(!is_white(px(&hm, bar_x - 1, dy + H / 2)), "bar has a frame");
        CHECK(ink_in(&hm, bar_x + bw + 1, dy - 8, hm.w, dy + 8) > 10, "vmax label at the bar's top");
        CHECK(ink_in(&hm, bar_x + bw + 1, dy + H - 8, hm.w, hm.h) > 5, "0 label at the bar's bottom");
        CHECK(ink_in(&hm, bar_x + bw + 1, dy + H / 2 - 6, hm.w, dy + H / 2 + 6) > 5, "midpoint label");
    }
    CHECK(ink_in(&hm, 0, 0, hm.w, dy - 1) > 30, "title drawn");
    write_png("figure_heatmap.png", &hm);
    fs_rgba_free(&hm);

    /* Larger tiles get a larger font: more room for the bar and labels. */
    enum { BIG = 512 };
    static float big[BIG * BIG];
    for (int y = 0; y < BIG; y++)
        for (int x = 0; x < BIG; x++) big[y * BIG + x] = (x + y) < 64 ? NAN : 0.5f * x / (BIG - 1) + 0.3f * y / BIG;
    fs_rgba_image hb;
    CHECK(fs_heatmap(big, BIG, BIG, 0.5, "depth error (r)", "r", &hb) == FS_OK, "%s", fs_error_message());
    CHECK(hb.w - BIG > ow - W && hb.h - BIG > oh - H, "512 px margins %dx%d vs 128 px %dx%d", hb.w - BIG, hb.h - BIG,
          ow - W, oh - H);
    write_png("figure_heatmap512.png", &hb);
    fs_rgba_free(&hb);

    CHECK(fs_heatmap(v, W, H, 0, "t", "u", &hm) == FS_ERR_INPUT && hm.pix == NULL, "vmax 0 rejected");
    CHECK(fs_heatmap(v, W, H, NAN, "t", "u", &hm) == FS_ERR_INPUT && hm.pix == NULL, "vmax NaN rejected");
    CHECK(fs_heatmap(v, 0, H, 1, "t", "u", &hm) == FS_ERR_INPUT, "width 0 rejected");
}

static int text_w(const char *t, int font)
{
    int w, h;
    fs_text_size(t, font, &w, &h);
    return w;
}

static void test_panel(void)
{
    enum { R = 2, C = 3, T = 128 };
    const float colours[R * C][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1},
                                     {1, 1, 0, 1}, {0, 1, 1, 1}, {1, 0, 1, 1}};
    fs_rgba_image tiles[R * C];
    const fs_rgba_image *tp[R * C];
    for (int k = 0; k < R * C; k++) {
        CHECK(fs_rgba_alloc(&tiles[k], T, T, colours[k]) == FS_OK, "alloc");
        tp[k] = &tiles[k];
    }
    const char *captions[R * C] = {"spheres 41.2 ms", "reference", "ssf 3.1 ms", "a", "b", "c"};
    const char *cols[C] = {"H = 2r", "H = 3r", "H = 4r"};
    const char *rows[R] = {"iso 0.5", "iso 0.6"};
    fs_panel_spec spec = {R, C, tp, captions, cols, rows, "kernel support vs iso value"};

    /* The documented size, from the text sizes. */
    const int f = 11, p = 5, tf = f * 4 / 3;
    int L, Lt, dummy;
    fs_text_size("0", f, &dummy, &L);
    fs_text_size("0", tf, &dummy, &Lt);
    int rhw = text_w(rows[0], f) > text_w(rows[1], f) ? text_w(rows[0], f) : text_w(rows[1], f);
    int want_w = p + rhw + p + C * (T + p), want_h = p + (Lt + p) + (L + p / 2) + R * (T + p / 2 + L + p);
    int ow, oh, tx[R * C], ty[R * C];
    CHECK(fs_panel_layout(&spec, &ow, &oh, tx, ty) == FS_OK, "%s", fs_error_message());
    fs_rgba_image out;
    CHECK(fs_panel_compose(&spec, &out) == FS_OK, "%s", fs_error_message());
    if (!out.pix) return;
    CHECK(out.w == want_w && out.h == want_h, "panel %dx%d, documented %dx%d", out.w, out.h, want_w, want_h);
    CHECK(ow == out.w && oh == out.h, "layout %dx%d vs compose %dx%d", ow, oh, out.w, out.h);

    int grid_x = p + rhw + p, grid_y = p + Lt + p + L + p / 2;
    for (int k = 0; k < R * C; k++) {
        int r = k / C, c = k % C, x = grid_x + c * (T + p), y = grid_y + r * (T + p / 2 + L + p);
        CHECK(tx[k] == x && ty[k] == y, "tile %d at (%d,%d), documented (%d,%d)", k, tx[k], ty[k], x, y);
        CHECK(same_rgb(px(&out, x, y), colours[k]) && same_rgb(px(&out, x + T - 1, y + T - 1), colours[k]) &&
                  same_rgb(px(&out, x + T / 2, y + T / 2), colours[k]),
              "tile %d's pixels", k);
        CHECK(is_white(px(&out, x - 1, y + T / 2)) && is_white(px(&out, x + T, y + T / 2)) &&
                  is_white(px(&out, x + T / 2, y - 1)),
              "white gap around tile %d", k);
        int cy = y + T + p / 2;
        CHECK(ink_in(&out, x, cy, x + T, cy + L) > 5, "caption of tile %d", k);
        CHECK(ink_in(&out, x, cy + L, x + T, cy + L + p) == 0, "caption of tile %d stays on its line", k);
        if (r == 0) CHECK(ink_in(&out, x, grid_y - L - p / 2, x + T, grid_y) > 10, "header of column %d", c);
        if (c == 0) CHECK(ink_in(&out, p, y, grid_x - p, y + T) > 10, "header of row %d", r);
    }
    CHECK(ink_in(&out, 0, 0, out.w, p + Lt) > 40, "title drawn");
    CHECK(ink_in(&out, 0, 0, out.w, p) == 0 && ink_in(&out, 0, out.h - p, out.w, out.h) == 0 &&
              ink_in(&out, out.w - p, 0, out.w, out.h) == 0,
          "margins stay white");
    fs_rgba_free(&out);

    /* NULL captions/headers/title: just the tiles with gaps; a NULL tile stays white. */
    fs_panel_spec bare = {R, C, tp, NULL, NULL, NULL, NULL};
    tp[4] = NULL;
    CHECK(fs_panel_compose(&bare, &out) == FS_OK, "%s", fs_error_message());
    CHECK(out.w == p + C * (T + p) && out.h == p + R * (T + p), "bare panel %dx%d", out.w, out.h);
    if (out.pix) {
        CHECK(same_rgb(px(&out, p, p), colours[0]), "first tile at (p, p)");
        CHECK(is_white(px(&out, p + T + p + T / 2, p + T + p + T / 2)), "empty cell is white");
    }
    fs_rgba_free(&out);

    fs_panel_spec bad = {0, 3, tp, NULL, NULL, NULL, NULL};
    CHECK(fs_panel_compose(&bad, &out) == FS_ERR_INPUT && out.pix == NULL, "0 rows rejected");
    for (int k = 0; k < R * C; k++) fs_rgba_free(&tiles[k]);
}

/* A publishable-looking panel: shaded discs over heatmaps of their error, for a look. */
static void test_panel_look(void)
{
    enum { T = 128 };
    fs_rgba_image im[3], hm[3];
    static float err[T * T];
    const char *names[3] = {"spheres", "raycast_pca", "aniso_ssf"};
    const double vmax = 10;
    for (int m = 0; m < 3; m++) {
        const float sky[4] = {0.55f, 0.65f, 0.8f, 1};
        fs_rgba_alloc(&im[m], T, T, sky);
        for (int y = 0; y < T; y++)
            for (int x = 0; x < T; x++) {
                double u = (x - T / 2 + 0.5) / (T * 0.38), w = (y - T / 2 + 0.5) / (T * 0.38), rr = u * u + w * w;
                float *p = im[m].pix + 4 * (y * T + x);
                float *e = &err[y * T + x];
                if (rr > 1) {
                    *e = NAN;
                    continue;
                }
                double n = sqrt(1 - rr), d = 0.2 + 0.8 * fmax(0, (-0.4 * u - 0.5 * w + 0.77 * n));
                p[0] = (float)(0.05 * d), p[1] = (float)(0.25 * d), p[2] = (float)(0.6 * d);
                *e = (float)(vmax * (0.3 * (m + 1)) * rr * (1 + 0.3 * sin(9 * u + m)));
            }
        char title[64];
        snprintf(title, sizeof title, "normal error (deg)");
        CHECK(fs_heatmap(err, T, T, vmax, title, "deg", &hm[m]) == FS_OK, "%s", fs_error_message());
    }
    const fs_rgba_image *tp[6] = {&im[0], &im[1], &im[2], &hm[0], &hm[1], &hm[2]};
    const char *captions[6] = {"spheres  41.2 ms", "raycast_pca  88.0 ms", "aniso_ssf  12.5 ms",
                               "mean 1.9 deg",     "mean 3.8 deg",         "mean 5.6 deg"};
    const char *rows[2] = {"image", "error"};
    fs_panel_spec spec = {2, 3, tp, captions, names, rows, "dam break, frame 120"};
    fs_rgba_image out;
    CHECK(fs_panel_compose(&spec, &out) == FS_OK, "%s", fs_error_message());
    if (out.pix) {
        /* Columns are as wide as their heatmaps; an image lines up with its heatmap's data. */
        int ow, oh, tx[6], ty[6];
        fs_panel_layout(&spec, &ow, &oh, tx, ty);
        CHECK(tx[1] - tx[0] >= hm[0].w && tx[2] - tx[1] >= hm[1].w, "columns as wide as the heatmaps");
        CHECK(tx[0] == tx[3] && tx[1] == tx[4], "image tiles line up with their heatmaps");
        CHECK(same_rgb(px(&out, tx[0] + T - 1, ty[0] + 2), im[0].pix) && is_white(px(&out, tx[0] + T, ty[0] + 2)),
              "image tile ends at its width");
        CHECK(same_rgb(px(&out, tx[3], ty[3]), hm[0].pix), "heatmap tile placed");
        write_png("figure_panel.png", &out);
    }
    fs_rgba_free(&out);
    for (int m = 0; m < 3; m++) fs_rgba_free(&im[m]), fs_rgba_free(&hm[m]);
}

int main(void)
{
    test_text();
    test_heatmap();
    test_panel();
    test_panel_look();
    TEST_DONE();
}
