/* Figures (figure.h): heatmaps with a colour bar, panels of labelled tiles.
 * Text comes from the image layer (rgba_image.h). */
#include "figure.h"
#include "fs_error.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Dark text and light grey lines on white; colours are linear. */
static const float TEXT_RGB[3] = {0.012f, 0.012f, 0.012f};
static const float FRAME_RGB[3] = {0.20f, 0.20f, 0.20f};
static const float WHITE[4] = {1, 1, 1, 1};

/* viridis (van der Walt & Smith, matplotlib), sampled at t = 0, 0.1, ..., 1:
 * sRGB 8-bit values of the published map, interpolated in sRGB. */
static const unsigned char VIRIDIS[11][3] = {
    {68, 1, 84},    {72, 36, 117},  {65, 68, 135},  {53, 95, 141},  {42, 120, 142}, {33, 145, 140},
    {34, 168, 132}, {68, 191, 112}, {122, 209, 81}, {189, 223, 38}, {253, 231, 37},
};
/* "No data": a dark grey no value of viridis comes close to. */
static const unsigned char NODATA_SRGB = 80;

/* src over dst with straight alpha, clipped; the result is opaque where dst was. */
static void composite_over(fs_rgba_image *dst, const fs_rgba_image *src, int x, int y)
{
    for (int j = 0; j < src->h; j++) {
        if (y + j < 0 || y + j >= dst->h) continue;
        for (int i = 0; i < src->w; i++) {
            if (x + i < 0 || x + i >= dst->w) continue;
            const float *s = src->pix + 4 * ((size_t)j * src->w + i);
            float *d = dst->pix + 4 * ((size_t)(y + j) * dst->w + x + i);
            float a = s[3] > 0 ? (s[3] < 1 ? s[3] : 1) : 0; /* also NaN -> 0 */
            for (int c = 0; c < 3; c++) d[c] = a * s[c] + (1 - a) * d[c];
        }
    }
}

static void fill_rect(fs_rgba_image *im, int x, int y, int w, int h, const float rgb[3])
{
    for (int j = y < 0 ? 0 : y; j < y + h && j < im->h; j++)
        for (int i = x < 0 ? 0 : x; i < x + w && i < im->w; i++) {
            float *d = im->pix + 4 * ((size_t)j * im->w + i);
            d[0] = rgb[0], d[1] = rgb[1], d[2] = rgb[2], d[3] = 1;
        }
}

/* A 1 px frame just outside the rectangle (x, y, w, h). */
static void frame_rect(fs_rgba_image *im, int x, int y, int w, int h, const float rgb[3])
{
    fill_rect(im, x - 1, y - 1, w + 2, 1, rgb);
    fill_rect(im, x - 1, y + h, w + 2, 1, rgb);
    fill_rect(im, x - 1, y, 1, h, rgb);
    fill_rect(im, x + w, y, 1, h, rgb);
}

/* Linear RGB of t in [0, 1] on the colour map (NaN -> no-data grey). */
static void colormap(double t, float rgb[3])
{
    if (isnan(t)) {
        rgb[0] = rgb[1] = rgb[2] = fs_srgb_decode8(NODATA_SRGB);
        return;
    }
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double u = t * 10;
    int k = (int)u;
    if (k > 9) k = 9;
    double f = u - k;
    for (int c = 0; c < 3; c++) {
        double v = VIRIDIS[k][c] + f * (VIRIDIS[k + 1][c] - VIRIDIS[k][c]);
        rgb[c] = fs_srgb_decode8((unsigned char)(v + 0.5));
    }
}

/* Font size for figures whose pictures are h pixels tall. */
static int figure_font(int h) { return h / 24 > 11 ? h / 24 : 11; }

static int line_height(int font, int *lh)
{
    int w;
    return fs_text_size("0", font, &w, lh);
}

static void tick_label(char *buf, size_t n, double v, const char *units)
{
    if (units && *units) snprintf(buf, n, "%.3g %s", v, units);
    else snprintf(buf, n, "%.3g", v);
}

/* Everything fs_heatmap_layout reports plus what drawing needs. */
typedef struct heatmap_geom {
    int font, line, pad, out_w, out_h, data_x, data_y;
    int bar_x, bar_w, tick_len, label_x;
    char labels[3][64]; /* 0, vmax/2, vmax */
} heatmap_geom;

static int heatmap_geom_of(int w, int h, double vmax, const char *title, const char *units, heatmap_geom *g)
{
    memset(g, 0, sizeof *g);
    if (w <= 0 || h <= 0) return fs_fail(FS_ERR_INPUT, "heatmap: bad size %dx%d", w, h);
    if (!(vmax > 0) || isinf(vmax)) return fs_fail(FS_ERR_INPUT, "heatmap: vmax %g is not a positive number", vmax);
    int rc;
    g->font = figure_font(h);
    if ((rc = line_height(g->font, &g->line))) return rc;
    g->pad = g->font / 3 > 3 ? g->font / 3 : 3;
    int label_w = 0, title_w = 0, th;
    for (int i = 0; i < 3; i++) {
        int lw, lh;
        tick_label(g->labels[i], sizeof g->labels[i], vmax * i / 2, i == 2 ? units : NULL);
        if ((rc = fs_text_size(g->labels[i], g->font, &lw, &lh))) return rc;
        if (lw > label_w) label_w = lw;
    }
    int has_title = title && *title;
    if (has_title && (rc = fs_text_size(title, g->font, &title_w, &th))) return rc;
    g->bar_w = (16 * g->font + 5) / 11;
    g->tick_len = g->font / 4 > 3 ? g->font / 4 : 3;
    int content_w = w + 2 * g->pad + g->bar_w + g->tick_len + 2 + label_w + g->pad;
    g->out_w = content_w > title_w + 2 * g->pad ? content_w : title_w + 2 * g->pad;
    g->data_x = (g->out_w - content_w) / 2;
    /* Tick labels are centred on the bar's ends: half a line must fit above and below. */
    g->data_y = has_title ? g->pad + g->line + g->pad : g->line / 2 + 1;
    g->out_h = g->data_y + h + g->line / 2 + 1;
    g->bar_x = g->data_x + w + 2 * g->pad;
    g->label_x = g->bar_x + g->bar_w + g->tick_len + 2;
    return FS_OK;
}

int fs_heatmap_layout(int w, int h, double vmax, const char *title, const char *units, int *out_w, int *out_h,
                      int *data_x, int *data_y)
{
    heatmap_geom g;
    int rc = heatmap_geom_of(w, h, vmax, title, units, &g);
    if (rc) return rc;
    *out_w = g.out_w, *out_h = g.out_h, *data_x = g.data_x, *data_y = g.data_y;
    return FS_OK;
}

int fs_heatmap(const float *values, int w, int h, double vmax, const char *title, const char *units, fs_rgba_image *out)
{
    heatmap_geom g;
    memset(out, 0, sizeof *out);
    if (!values) return fs_fail(FS_ERR_INPUT, "heatmap: no values");
    int rc = heatmap_geom_of(w, h, vmax, title, units, &g);
    if (rc || (rc = fs_rgba_alloc(out, g.out_w, g.out_h, WHITE))) return rc;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            float v = values[(size_t)j * w + i];
            float *d = out->pix + 4 * ((size_t)(g.data_y + j) * out->w + g.data_x + i);
            colormap(isnan(v) ? NAN : v / vmax, d);
        }
    /* Bar: top row is vmax, bottom row 0, framed, with ticks at both ends and the middle. */
    for (int j = 0; j < h; j++) {
        float rgb[3];
        colormap(h > 1 ? 1.0 - (double)j / (h - 1) : 1.0, rgb);
        fill_rect(out, g.bar_x, g.data_y + j, g.bar_w, 1, rgb);
    }
    frame_rect(out, g.bar_x, g.data_y, g.bar_w, h, FRAME_RGB);
    if (title && *title) {
        int tw, th;
        if ((rc = fs_text_size(title, g.font, &tw, &th))) goto fail;
        int cx = g.data_x + w / 2 - tw / 2; /* centred over the data, kept inside */
        if (cx + tw > out->w - g.pad) cx = out->w - g.pad - tw;
        if (cx < g.pad) cx = g.pad;
        if ((rc = fs_draw_text(out, cx, g.pad, title, g.font, TEXT_RGB))) goto fail;
    }
    for (int i = 0; i < 3; i++) {
        int ty = g.data_y + (h - 1) - (h - 1) * i / 2;
        fill_rect(out, g.bar_x + g.bar_w, ty, g.tick_len, 1, FRAME_RGB);
        if ((rc = fs_draw_text(out, g.label_x, ty - g.line / 2, g.labels[i], g.font, TEXT_RGB))) goto fail;
    }
    return FS_OK;
fail:
    fs_rgba_free(out);
    return rc;
}

/* ---- panels ---- */

typedef struct panel_geom {
    int font, line, title_font, title_line, pad, out_w, out_h;
    int grid_x, title_y, header_y, row_header_w;
    int *col_x, *col_w, *col_mid, *row_y, *row_h; /* one allocation */
} panel_geom;

static const char *nth(const char *const *list, int i) { return list && list[i] ? list[i] : ""; }

static int text_w(const char *text, int font, int *w)
{
    int h;
    return fs_text_size(text, font, w, &h);
}

/* The grid is sane and every tile has pixels; *max_h: the tallest tile. */
static int check_tiles(const fs_panel_spec *s, int *max_h)
{
    if (!s || s->rows <= 0 || s->cols <= 0 || s->rows > 1000 || s->cols > 1000)
        return fs_fail(FS_ERR_INPUT, "panel: bad grid %dx%d", s ? s->rows : 0, s ? s->cols : 0);
    if (!s->tiles) return fs_fail(FS_ERR_INPUT, "panel: no tile list");
    *max_h = 0;
    for (int k = 0; k < s->rows * s->cols; k++) {
        const fs_rgba_image *t = s->tiles[k];
        if (t && (t->w <= 0 || t->h <= 0 || !t->pix))
            return fs_fail(FS_ERR_INPUT, "panel: tile %d (row %d, column %d) has no pixels", k, k / s->cols,
                           k % s->cols);
        if (t && t->h > *max_h) *max_h = t->h;
    }
    return FS_OK;
}

/* Column width: widest tile, caption or header of the column; row height:
 * tallest tile; the widest row header. */
static int cell_sizes(const fs_panel_spec *s, panel_geom *g)
{
    int rc = FS_OK, w;
    for (int k = 0; k < s->rows * s->cols && !rc; k++) {
        int r = k / s->cols, c = k % s->cols;
        const fs_rgba_image *t = s->tiles[k];
        if (t && t->w > g->col_w[c]) g->col_w[c] = t->w;
        if (t && t->h > g->row_h[r]) g->row_h[r] = t->h;
        if (!(rc = text_w(nth(s->captions, k), g->font, &w)) && w > g->col_w[c]) g->col_w[c] = w;
    }
    for (int c = 0; c < s->cols && !rc; c++)
        if (!(rc = text_w(nth(s->col_headers, c), g->font, &w)) && w > g->col_w[c]) g->col_w[c] = w;
    for (int r = 0; s->row_headers && r < s->rows && !rc; r++)
        if (!(rc = text_w(nth(s->row_headers, r), g->font, &w)) && w > g->row_header_w) g->row_header_w = w;
    return rc;
}

/* Columns left to right; returns the grid's right edge. */
static int place_columns(const fs_panel_spec *s, panel_geom *g)
{
    g->grid_x = g->pad + (s->row_headers ? g->row_header_w + g->pad : 0);
    int x = g->grid_x;
    for (int c = 0; c < s->cols; c++) {
        g->col_x[c] = x;
        x += g->col_w[c] + g->pad;
        /* Labels centre on the narrowest tile: over an image and its heatmap (wider
         * by the colour bar) they then centre on both pictures. */
        int narrowest = 0;
        for (int r = 0; r < s->rows; r++) {
            const fs_rgba_image *t = s->tiles[r * s->cols + c];
            if (t && (!narrowest || t->w < narrowest)) narrowest = t->w;
        }
        g->col_mid[c] = g->col_x[c] + (narrowest ? narrowest : g->col_w[c]) / 2;
    }
    return x;
}

/* The title, the column headers and the rows top to bottom; the panel's size. */
static int place_rows(const fs_panel_spec *s, panel_geom *g, int right)
{
    int y = g->pad, title_w = 0, rc;
    g->title_y = y;
    if (s->title && *s->title) {
        if ((rc = text_w(s->title, g->title_font, &title_w))) return rc;
        y += g->title_line + g->pad;
    }
    g->header_y = y;
    if (s->col_headers) y += g->line + g->pad / 2;
    for (int r = 0; r < s->rows; r++) {
        g->row_y[r] = y;
        y += g->row_h[r] + (s->captions ? g->pad / 2 + g->line : 0) + g->pad;
    }
    g->out_w = right > title_w + 2 * g->pad ? right : title_w + 2 * g->pad;
    g->out_h = y;
    return FS_OK;
}

static int panel_geom_of(const fs_panel_spec *s, panel_geom *g)
{
    memset(g, 0, sizeof *g);
    int max_h = 0, rc = check_tiles(s, &max_h);
    if (rc) return rc;
    g->font = figure_font(max_h);
    g->title_font = g->font * 4 / 3;
    g->pad = g->font / 2 > 4 ? g->font / 2 : 4;
    if ((rc = line_height(g->font, &g->line)) || (rc = line_height(g->title_font, &g->title_line))) return rc;
    int *mem = calloc((size_t)2 * s->rows + 3 * s->cols, sizeof(int));
    if (!mem) return fs_fail(FS_ERR_RUNTIME, "panel: out of memory");
    g->col_x = mem, g->col_w = mem + s->cols, g->col_mid = mem + 2 * s->cols;
    g->row_y = mem + 3 * s->cols, g->row_h = g->row_y + s->rows;
    rc = cell_sizes(s, g);
    if (!rc) rc = place_rows(s, g, place_columns(s, g));
    if (rc) {
        free(mem);
        g->col_x = NULL;
    }
    return rc;
}

/* Top-left corner of cell k's tile (or of the cell when the tile is NULL): left
 * in its column, so an image and a heatmap of it line up; centred in its row. */
static void tile_origin(const fs_panel_spec *s, const panel_geom *g, int k, int *x, int *y)
{
    int r = k / s->cols, c = k % s->cols;
    const fs_rgba_image *t = s->tiles[k];
    *x = g->col_x[c];
    *y = g->row_y[r] + (t ? (g->row_h[r] - t->h) / 2 : 0);
}

int fs_panel_layout(const fs_panel_spec *spec, int *out_w, int *out_h, int *tile_x, int *tile_y)
{
    panel_geom g;
    int rc = panel_geom_of(spec, &g);
    if (rc) return rc;
    *out_w = g.out_w, *out_h = g.out_h;
    for (int k = 0; k < spec->rows * spec->cols; k++) {
        int x, y;
        tile_origin(spec, &g, k, &x, &y);
        if (tile_x) tile_x[k] = x;
        if (tile_y) tile_y[k] = y;
    }
    free(g.col_x);
    return FS_OK;
}

/* Draws text horizontally centred on cx, kept inside [x0, x1). */
static int draw_centred(fs_rgba_image *im, int cx, int x0, int x1, int y, const char *text, int font)
{
    int w, h, rc = fs_text_size(text, font, &w, &h);
    if (rc || !*text) return rc;
    int x = cx - w / 2;
    if (x + w > x1) x = x1 - w;
    if (x < x0) x = x0;
    return fs_draw_text(im, x, y, text, font, TEXT_RGB);
}

int fs_panel_compose(const fs_panel_spec *spec, fs_rgba_image *out)
{
    panel_geom g;
    memset(out, 0, sizeof *out);
    int rc = panel_geom_of(spec, &g);
    if (rc) return rc;
    if ((rc = fs_rgba_alloc(out, g.out_w, g.out_h, WHITE))) goto done;
    if (spec->title && *spec->title) {
        /* Centred over the grid, or over the whole panel when it is wider than the grid. */
        int grid_w = g.col_x[spec->cols - 1] + g.col_w[spec->cols - 1] - g.grid_x, tw;
        if ((rc = text_w(spec->title, g.title_font, &tw))) goto done;
        int cx = tw > grid_w ? g.out_w / 2 : g.grid_x + grid_w / 2;
        if ((rc = draw_centred(out, cx, 0, g.out_w, g.title_y, spec->title, g.title_font))) goto done;
    }
    for (int c = 0; spec->col_headers && c < spec->cols; c++)
        if ((rc = draw_centred(out, g.col_mid[c], g.col_x[c], g.col_x[c] + g.col_w[c], g.header_y,
                               nth(spec->col_headers, c), g.font)))
            goto done;
    for (int r = 0; spec->row_headers && r < spec->rows; r++) {
        int w, h;
        const char *text = nth(spec->row_headers, r);
        if ((rc = fs_text_size(text, g.font, &w, &h))) goto done;
        int y = g.row_y[r] + g.row_h[r] / 2 - h / 2; /* right-aligned, vertically centred */
        if ((rc = fs_draw_text(out, g.grid_x - g.pad - w, y, text, g.font, TEXT_RGB))) goto done;
    }
    for (int k = 0; k < spec->rows * spec->cols; k++) {
        int r = k / spec->cols, c = k % spec->cols, x, y;
        tile_origin(spec, &g, k, &x, &y);
        if (spec->tiles[k]) composite_over(out, spec->tiles[k], x, y);
        if (spec->captions) {
            int cy = g.row_y[r] + g.row_h[r] + g.pad / 2;
            if ((rc = draw_centred(out, g.col_mid[c], g.col_x[c], g.col_x[c] + g.col_w[c], cy, nth(spec->captions, k),
                                   g.font)))
                goto done;
        }
    }
done:
    free(g.col_x);
    if (rc) fs_rgba_free(out);
    return rc;
}
