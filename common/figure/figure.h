/* Figures: heatmaps with a colour bar and scale, and panels of labelled tiles,
 * drawn on RGBA images with their text (common/image/rgba_image.h). */
#ifndef FS_FIGURE_H
#define FS_FIGURE_H
#include "rgba_image.h"
#ifdef __cplusplus
extern "C" {
#endif

/* A heatmap of values (NAN = no data, drawn dark grey) from 0 to vmax with a
 * perceptual colour map (values above vmax saturate), plus a vertical colour bar
 * on the right labelled "0", the midpoint and "vmax" with units, and a title
 * line on top (e.g. "normal error (deg)"). Output size: w + bar width, h + title. */
int fs_heatmap(const float *values, int w, int h, double vmax, const char *title, const char *units,
               fs_rgba_image *out);
/* fs_heatmap's geometry without drawing: the output is out_w x out_h, white,
 * with the w x h data pixels at (data_x, data_y). Font size max(11, h/24) px;
 * out_h = data_y + h + half a text line (room for the "0" label); out_w = w +
 * gap + colour bar (16 px at font 11, scaled with the font) + ticks + widest
 * label + margin, or more if the title is wider (the data is then centred). */
int fs_heatmap_layout(int w, int h, double vmax, const char *title, const char *units, int *out_w, int *out_h,
                      int *data_x, int *data_y);

/* A panel: rows x cols tiles of equal size, each with a caption under it
 * (e.g. "spheres  41.2 ms"), optional column headers on top and row headers on
 * the left (NULL for none), white background, dark text. */
typedef struct fs_panel_spec {
    int rows, cols;
    const fs_rgba_image *const *tiles; /* rows*cols, row-major; NULL leaves a cell empty */
    const char *const *captions;       /* rows*cols or NULL */
    const char *const *col_headers;    /* cols or NULL */
    const char *const *row_headers;    /* rows or NULL */
    const char *title;                 /* or NULL */
} fs_panel_spec;
/* Tiles are composited over white with their (straight) alpha. Layout, with font
 * f = max(11, tallest tile / 24) px, line height L (fs_text_size of any one-line
 * text at f), pad p = max(4, f/2), title font f*4/3 with line height Lt:
 *   column width  = max(tile widths, caption widths, header width) of the column
 *   row height    = tallest tile of the row; a tile sits at its cell's left edge
 *                   (an image above its heatmap lines up), centred vertically;
 *                   captions and headers centre on the column's narrowest tile
 *   width  = p + [widest row header + p] + sum(column widths + p), at least title width + 2p
 *   height = p + [Lt + p] + [L + p/2] + sum(row height + [p/2 + L] + p)
 * ([...] only when there is a title, column headers, row headers or captions;
 * p/2 is integer division). Captions sit p/2 under their row's tiles. */
int fs_panel_compose(const fs_panel_spec *spec, fs_rgba_image *out);
/* fs_panel_compose's geometry without drawing: the output size and the top-left
 * corner of each tile (rows*cols entries, row-major; either may be NULL). */
int fs_panel_layout(const fs_panel_spec *spec, int *out_w, int *out_h, int *tile_x, int *tile_y);

#ifdef __cplusplus
}
#endif
#endif
