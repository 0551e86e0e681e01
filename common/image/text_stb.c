/* Text for the build without OpenImageIO (FS_WITH_OIIO=OFF): glyphs rasterised by
 * header-only stb_truetype from Debian's DejaVuSans.ttf (FLUIDSURF_FONT names
 * another file), with image_text.cpp's contract:
 *
 * - the line box does not depend on the letters: its top is the ascent of a
 *   reference string, its bottom that string's descent (widened where the text
 *   itself reaches further), so labels placed at the same y share a baseline;
 * - the font size is FreeType's pixel size (em height), as OpenImageIO uses it;
 * - coverage is blended into the caller's linear RGBA in sRGB-encoded values.
 *
 * - as OpenImageIO's render_text and text_size, the pen moves by each glyph's
 *   whole-pixel advance (here the unhinted advance rounded), with no kerning,
 *   every glyph starts on a whole pixel, and a glyph's bitmap replaces the
 *   coverage under it (overlapping boxes keep the later glyph's).
 *
 * Glyph shapes differ slightly from FreeType's (no hinting), so panels are not
 * bit-identical to the full build's. A missing font file is a soft condition
 * here (the full build fails with FS_ERR_RUNTIME): text is measured with a fixed
 * estimate (0.6 em a code point), nothing is drawn, and one note says so, so a
 * bare GPU node still writes every image of `compare`. */
#include "rgba_image.h"
#include "fs_error.h"
#include "text_blend.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb_truetype.h>
#pragma GCC diagnostic pop

static const char *const kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
static const char *const kLineRef = "Hg|()"; /* tall and deep glyphs: the line box */

static unsigned char *font_data;
static stbtt_fontinfo font;
static int have_font;
static pthread_once_t font_once = PTHREAD_ONCE_INIT;

static void load_font(void)
{
    const char *path = getenv("FLUIDSURF_FONT");
    if (!path || !*path) path = kFontFile;
    FILE *f = fopen(path, "rb");
    long n = -1;
    if (f && fseek(f, 0, SEEK_END) == 0) n = ftell(f);
    if (n > 0 && fseek(f, 0, SEEK_SET) == 0 && (font_data = malloc((size_t)n)) &&
        fread(font_data, 1, (size_t)n, f) == (size_t)n &&
        stbtt_InitFont(&font, font_data, stbtt_GetFontOffsetForIndex(font_data, 0)))
        have_font = 1;
    if (f) fclose(f);
    if (!have_font) {
        free(font_data);
        font_data = NULL;
        fs_note("%s: font not found or unreadable (install fonts-dejavu-core): figures are written without text", path);
    }
}

/* Next code point of UTF-8 text (invalid bytes read as '?'). */
static int next_cp(const char **s)
{
    const unsigned char *p = (const unsigned char *)*s;
    int cp = *p++, more = cp >= 0xf0 ? 3 : cp >= 0xe0 ? 2 : cp >= 0xc0 ? 1 : 0;
    if (cp >= 0x80 && !more) cp = '?';
    if (more) cp &= 0x3f >> more;
    for (; more; more--, p++) {
        if ((*p & 0xc0) != 0x80) {
            cp = '?';
            break;
        }
        cp = cp << 6 | (*p & 0x3f);
    }
    *s = (const char *)p;
    return cp;
}

/* Walks the glyphs of text at pixel size `size`: box (relative to pen start and
 * baseline) and, if cover is given, their coverage written at (ox, oy) + glyph offset. */
typedef struct box {
    int x0, y0, x1, y1, any;
} box;

static void layout(const char *text, int size, box *b, float *cover, int cw, int ch, int ox, int oy)
{
    float scale = stbtt_ScaleForMappingEmToPixels(&font, (float)size);
    int pen = 0;
    memset(b, 0, sizeof *b);
    unsigned char *glyph = NULL;
    size_t glyph_cap = 0;
    for (const char *s = text; *s;) {
        int cp = next_cp(&s), adv, lsb, x0, y0, x1, y1;
        stbtt_GetCodepointBitmapBox(&font, cp, scale, scale, &x0, &y0, &x1, &y1);
        if (x1 > x0 && y1 > y0) {
            int gx = pen + x0;
            if (!b->any || gx < b->x0) b->x0 = gx;
            if (!b->any || gx + (x1 - x0) > b->x1) b->x1 = gx + (x1 - x0);
            if (!b->any || y0 < b->y0) b->y0 = y0;
            if (!b->any || y1 > b->y1) b->y1 = y1;
            b->any = 1;
            size_t need = (size_t)(x1 - x0) * (y1 - y0);
            if (cover && need > glyph_cap) {
                free(glyph);
                glyph = malloc(need);
                glyph_cap = glyph ? need : 0;
            }
            if (cover && glyph) {
                stbtt_MakeCodepointBitmap(&font, glyph, x1 - x0, y1 - y0, x1 - x0, scale, scale, cp);
                for (int j = 0; j < y1 - y0; j++)
                    for (int i = 0; i < x1 - x0; i++) {
                        int px = ox + gx + i, py = oy + y0 + j;
                        if (px < 0 || py < 0 || px >= cw || py >= ch) continue;
                        /* Set, not added: where glyph boxes overlap, the later glyph's
                         * bitmap replaces the earlier one's, as in render_text. */
                        cover[(size_t)py * cw + px] = glyph[(size_t)j * (x1 - x0) + i] / 255.0f;
                    }
            }
        }
        stbtt_GetCodepointHMetrics(&font, cp, &adv, &lsb);
        pen += (int)lroundf(scale * adv);
    }
    free(glyph);
    if (!b->any) b->x1 = pen;
}

/* Where text goes relative to its top-left corner: pen offset and box size. */
typedef struct placement {
    int pen_x, baseline, w, h;
} placement;

static void place(const char *text, int size, placement *p)
{
    if (!have_font) { /* no font: an estimate of DejaVuSans' metrics, so layouts keep their shape */
        p->pen_x = 0;
        p->baseline = (size * 19 + 10) / 20;
        size_t n = 0;
        for (const char *s = text; *s; n++) next_cp(&s);
        p->w = (int)(n * size * 0.6 + 0.5);
        p->h = (size * 6 + 2) / 5;
        return;
    }
    box ref, r;
    layout(kLineRef, size, &ref, NULL, 0, 0, 0, 0);
    layout(text, size, &r, NULL, 0, 0, 0, 0);
    int left = r.x0 < 0 ? r.x0 : 0, top = ref.y0 < r.y0 || !r.any ? ref.y0 : r.y0;
    int bottom = ref.y1 > r.y1 || !r.any ? ref.y1 : r.y1;
    p->pen_x = -left;
    p->baseline = -top;
    p->w = r.x1 - left > 0 ? r.x1 - left : 0;
    p->h = bottom - top;
}

int fs_text_size(const char *text, int size, int *w, int *h)
{
    *w = *h = 0;
    if (size <= 0) return fs_fail(FS_ERR_INPUT, "text: font size %d is not positive", size);
    pthread_once(&font_once, load_font);
    if (!text || !*text) return FS_OK;
    placement p;
    place(text, size, &p);
    *w = p.w;
    *h = p.h;
    return FS_OK;
}

int fs_draw_text(fs_rgba_image *im, int x, int y, const char *text, int size, const float rgb[3])
{
    if (!im || !im->pix || im->w <= 0 || im->h <= 0) return fs_fail(FS_ERR_INPUT, "text: no image to draw on");
    if (size <= 0) return fs_fail(FS_ERR_INPUT, "text: font size %d is not positive", size);
    pthread_once(&font_once, load_font);
    if (!have_font || !text || !*text) return FS_OK;
    placement p;
    place(text, size, &p);
    /* Coverage into a one-channel buffer around the text box (1 px of slack). */
    const int m = 1, cw = p.w + 2 * m, ch = p.h + 2 * m;
    float *cover = calloc((size_t)cw * ch, sizeof *cover);
    if (!cover) return fs_fail(FS_ERR_RUNTIME, "text \"%s\": out of memory", text);
    box b;
    layout(text, size, &b, cover, cw, ch, m + p.pen_x, m + p.baseline);
    fs_text_blend(im, x - m, y - m, cover, cw, ch, rgb);
    free(cover);
    return FS_OK;
}
