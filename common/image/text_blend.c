/* Glyph coverage composited into a figure (text_blend.h). */
#include "text_blend.h"
#include "srgb.h"

#include <stddef.h>

/* Blends coverage a of colour rgb over a linear pixel in sRGB-encoded values, as
 * text renderers do: blended in linear light, antialiased dark-on-light strokes
 * wash out to thin grey lines at 11-12 px. */
static void blend_encoded(float *d, const float rgb[3], float a)
{
    for (int c = 0; c < 3; c++) {
        float e = a * fs_srgb_encode8(rgb[c]) + (1 - a) * fs_srgb_encode8(d[c]);
        d[c] = fs_srgb_decode8((unsigned char)(e + 0.5f));
    }
    d[3] = a + (1 - a) * d[3];
}

void fs_text_blend(fs_rgba_image *im, int x, int y, const float *cover, int cw, int ch, const float rgb[3])
{
    for (int j = 0; j < ch; j++) {
        int py = y + j;
        if (py < 0 || py >= im->h) continue;
        for (int i = 0; i < cw; i++) {
            int px = x + i;
            float cov = cover[(size_t)j * cw + i];
            if (px < 0 || px >= im->w || !(cov > 0)) continue;
            blend_encoded(im->pix + 4 * ((size_t)py * im->w + px), rgb, cov < 1 ? cov : 1);
        }
    }
}
