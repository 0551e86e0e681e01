// Thin OpenImageIO adapter behind image_io.h: reading EXR and PNG, for the files
// that image_stb.c hands to the module (tiled and deep EXRs; it reads PNGs and
// scanline EXRs itself), and for tests/fuzz/fuzz_oiio.c. Both are written without
// OpenImageIO (png_write.c, image_exr_core.c); fs_image_free and the checks before a
// read are in image_util.c, shared with them.
#include "image_io.h"
#include "alloc_cap.h"
#include "fs_error.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

using namespace OIIO;

namespace
{

// The first line of an OpenImageIO message, control characters (from the file) as '?'.
std::string first_line(const std::string &msg)
{
    std::string s = msg.substr(0, msg.find('\n'));
    for (char &c : s)
        if ((unsigned char)c < 0x20 || c == 0x7f) c = '?';
    return s.empty() ? std::string("unknown OpenImageIO error") : s;
}

// The format by its magic number: "openexr" or "png", else nullptr. Only these two
// are read (G-buffers are EXRs, the tests read PNGs back); handing any other bytes
// to OpenImageIO would let it try every plugin it has on them.
const char *sniff(const char *path)
{
    unsigned char m[8] = {0};
    FILE *f = std::fopen(path, "rb");
    size_t n = f ? std::fread(m, 1, sizeof m, f) : 0;
    if (f) std::fclose(f);
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01},
                               png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (n >= 4 && !std::memcmp(m, exr, 4)) return "openexr";
    if (n == 8 && !std::memcmp(m, png, 8)) return "png";
    return nullptr;
}

// Opens path with the plugin of its magic number; nullptr with fs_fail set otherwise.
std::unique_ptr<ImageInput> open_image(const char *path, const ImageSpec *config)
{
    const char *format = sniff(path);
    if (!format) {
        FILE *f = std::fopen(path, "rb");
        if (!f) fs_fail(FS_ERR_INPUT, "%s: cannot open: %s", path, std::strerror(errno));
        else fs_fail(FS_ERR_INPUT, "%s: not an EXR or PNG image", path);
        if (f) std::fclose(f);
        return nullptr;
    }
    // libpng prints its own errors on stderr whatever OpenImageIO's callbacks do, and
    // it and OpenEXR size buffers from the file: a damaged file is refused here, in one line
    if (fs_image_structure_check(path)) return nullptr;
    auto in = ImageInput::create(format);
    ImageSpec spec;
    if (!in || !in->open(path, spec, config ? *config : ImageSpec())) {
        std::string err = in ? in->geterror() : OIIO::geterror();
        fs_fail(FS_ERR_INPUT, "%s: %s", path, first_line(err).c_str());
        return nullptr;
    }
    return in;
}

int read_image(const char *path, fs_image *img)
{
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // pixels as stored
    auto in = open_image(path, &config);
    if (!in) return FS_ERR_INPUT;
    const ImageSpec &spec = in->spec();
    int w = spec.width, h = spec.height, nch = spec.nchannels;
    if (w <= 0 || h <= 0 || nch <= 0) return fs_fail(FS_ERR_INPUT, "%s: image has no pixels", path);
    if (fs_image_fits_file(path, w, h, nch)) return FS_ERR_INPUT;
    size_t count = (size_t)w * h * nch;
    float *pix = (float *)std::malloc(count * sizeof(float));
    const char **names = (const char **)std::calloc(nch, sizeof(char *));
    bool ok = pix && names;
    for (int c = 0; ok && c < nch; c++) {
        std::string n = c < (int)spec.channelnames.size() ? spec.channelnames[c] : "C" + std::to_string(c);
        char *copy = strdup(n.c_str());
        names[c] = copy;
        ok = copy != nullptr;
    }
    img->w = w;
    img->h = h;
    img->nch = nch;
    img->chnames = names;
    img->pix = pix;
    if (!ok) {
        fs_image_free(img);
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory for a %dx%dx%d image", path, w, h, nch);
    }
    if (!in->read_image(0, 0, 0, nch, TypeDesc::FLOAT, pix)) {
        std::string err = in->geterror();
        fs_image_free(img);
        return fs_fail(FS_ERR_INPUT, "%s: %s", path, first_line(err).c_str());
    }
    return FS_OK;
}

int read_image_attr(const char *path, const char *name, char *buf, int size)
{
    auto in = open_image(path, nullptr);
    if (!in) return -1;
    const ParamValue *p = in->spec().find_attribute(name, TypeDesc::STRING);
    if (!p) return 0;
    if (size > 0) {
        std::strncpy(buf, p->get_string().c_str(), size - 1);
        buf[size - 1] = 0;
    }
    return 1;
}

// OpenEXR sizes header attributes (strings, previews) from the file before reading
// them: under the cap, such a size throws std::bad_alloc instead of taking the memory.
template <class F> int capped(const char *path, int failed, F read)
{
    try {
        fs::AllocCap cap(path);
        return read();
    } catch (const std::bad_alloc &) {
        fs_fail(FS_ERR_INPUT,
                "%s: OpenImageIO asked for a buffer larger than the file can fill (a damaged or forged size)", path);
    } catch (const std::exception &e) {
        fs_fail(FS_ERR_INPUT, "%s: %s", path, first_line(e.what()).c_str());
    }
    return failed;
}

} // namespace

extern "C" int fs_read_image(const char *path, fs_image *img)
{
    std::memset(img, 0, sizeof *img);
    int rc = capped(path, FS_ERR_INPUT, [&] { return read_image(path, img); });
    if (rc) fs_image_free(img);
    return rc;
}

extern "C" int fs_read_image_attr(const char *path, const char *name, char *buf, int size)
{
    if (size > 0) buf[0] = 0;
    return capped(path, -1, [&] { return read_image_attr(path, name, buf, size); });
}
