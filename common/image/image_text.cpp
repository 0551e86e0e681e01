// Thin OpenImageIO adapter behind figure.h: text measured and drawn with
// ImageBufAlgo::text_size / render_text in DejaVuSans (fonts-dejavu-core).
//
// Layout wants a line box that does not depend on the letters of the text, so
// that labels placed at the same y share a baseline: the box's top is the
// ascent of a reference string, its bottom the descent of that string (both
// widened where the text itself reaches further).
//
// render_text draws glyph coverage into a small one-channel buffer; the
// coverage is blended into the caller's linear RGBA in sRGB-encoded values
// (text_blend.c, shared with text_stb.c).
#include "rgba_image.h"
#include "fs_error.h"
#include "image_io.h"
#include "text_blend.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cstring>
#include <string>

using namespace OIIO;

namespace
{

const char *const kFontName = "DejaVuSans";
const char *const kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
// Tall and deep glyphs: the line box of every text.
const char *const kLineRef = "Hg|()";

// The font as OpenImageIO finds it: by name, else Debian's file; "" if neither.
const std::string &font()
{
    static const std::string found = [] {
        for (const char *f : {kFontName, kFontFile}) {
            if (ImageBufAlgo::text_size(kLineRef, 12, f).defined()) return std::string(f);
            (void)OIIO::geterror(); // drop the failed lookup's message
        }
        return std::string();
    }();
    return found;
}

int font_missing() { return fs_fail(FS_ERR_RUNTIME, "%s: font not found (install fonts-dejavu-core)", kFontFile); }

// Where text goes relative to its top-left corner: pen offset and box size.
struct Placement {
    int pen_x, baseline, w, h;
};

bool place(const char *text, int size, Placement *p)
{
    ROI ref = ImageBufAlgo::text_size(kLineRef, size, font());
    ROI r = ImageBufAlgo::text_size(text, size, font());
    if (!ref.defined() || !r.defined()) return false;
    int left = std::min(0, r.xbegin), top = std::min(ref.ybegin, r.ybegin);
    int bottom = std::max(ref.yend, r.yend);
    p->pen_x = -left;
    p->baseline = -top;
    p->w = std::max(0, r.xend - left);
    p->h = bottom - top;
    return true;
}

extern "C" int fs_text_size(const char *text, int size, int *w, int *h)
{
    *w = *h = 0;
    if (size <= 0) return fs_fail(FS_ERR_INPUT, "text: font size %d is not positive", size);
    if (font().empty()) return font_missing();
    if (!text || !*text) return FS_OK;
    Placement p;
    if (!place(text, size, &p)) return fs_fail(FS_ERR_RUNTIME, "text \"%s\": cannot measure it", text);
    *w = p.w;
    *h = p.h;
    return FS_OK;
}

} // namespace

extern "C" int fs_draw_text(fs_rgba_image *im, int x, int y, const char *text, int size, const float rgb[3])
{
    if (!im || !im->pix || im->w <= 0 || im->h <= 0) return fs_fail(FS_ERR_INPUT, "text: no image to draw on");
    if (size <= 0) return fs_fail(FS_ERR_INPUT, "text: font size %d is not positive", size);
    if (font().empty()) return font_missing();
    if (!text || !*text) return FS_OK;
    Placement p;
    if (!place(text, size, &p)) return fs_fail(FS_ERR_RUNTIME, "text \"%s\": cannot measure it", text);
    // Glyph coverage into a one-channel buffer around the text box (1 px of
    // slack for antialiasing), then blended into the caller's pixels.
    const int m = 1;
    ImageBuf cover(ImageSpec(p.w + 2 * m, p.h + 2 * m, 1, TypeDesc::FLOAT));
    const float one[1] = {1.0f};
    if (!ImageBufAlgo::zero(cover) ||
        !ImageBufAlgo::render_text(cover, m + p.pen_x, m + p.baseline, text, size, font(), one)) {
        std::string err = cover.geterror();
        err = err.substr(0, err.find('\n'));
        return fs_fail(FS_ERR_RUNTIME, "text \"%s\": %s", text, err.empty() ? "cannot draw it" : err.c_str());
    }
    fs_text_blend(im, x - m, y - m, (const float *)cover.localpixels(), p.w + 2 * m, p.h + 2 * m, rgb);
    return FS_OK;
}
