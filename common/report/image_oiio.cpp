// Thin OpenImageIO adapter behind image_io.h: EXR writing, and reading EXR and PNG.
// Every write goes to a temporary file next to the target (output_file.h), so the
// format is named explicitly: the temporary name has no useful extension. PNGs are
// written by png_write.c in every build; fs_image_free and the checks before a read
// are in image_util.c, shared with the build without OIIO.
#include "image_io.h"
#include "alloc_cap.h"
#include "fs_error.h"
#include "output_file.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

using namespace OIIO;

namespace {

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
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01}, png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
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

bool valid_image(const fs_image *img)
{
    return img && img->w > 0 && img->h > 0 && img->nch > 0 && img->pix;
}

// Opens the temporary file, writes pixels of type fmt, renames on success.
int write_safely(const char *path, const char *format, const ImageSpec &spec, TypeDesc fmt,
                 const void *pix)
{
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    auto out = ImageOutput::create(format);
    bool ok = out && out->open(tmp, spec) && out->write_image(fmt, pix) && out->close();
    std::string err = ok ? std::string() : out ? out->geterror() : OIIO::geterror();
    out.reset();
    if (!ok) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: %s", path, first_line(err).c_str());
    }
    return fs_output_end(path, tmp, 1);
}

} // namespace

extern "C" int fs_write_exr(const char *path, const fs_image *img, const fs_attr *attrs, int nattrs)
{
    if (!valid_image(img)) return fs_fail(FS_ERR_INPUT, "%s: no image to write", path);
    ImageSpec spec(img->w, img->h, img->nch, TypeDesc::FLOAT);
    spec.channelnames.clear();
    for (int c = 0; c < img->nch; c++) {
        const char *n = img->chnames ? img->chnames[c] : nullptr;
        spec.channelnames.push_back(n && *n ? n : "C" + std::to_string(c));
    }
    spec.alpha_channel = -1;
    for (int c = 0; c < img->nch; c++)
        if (spec.channelnames[c] == "A") spec.alpha_channel = c;
    spec.attribute("compression", "zip");
    for (int i = 0; i < nattrs; i++)
        if (attrs[i].name && attrs[i].value) spec.attribute(attrs[i].name, attrs[i].value);
    return write_safely(path, "openexr", spec, TypeDesc::FLOAT, img->pix);
}

namespace {

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
        fs_fail(FS_ERR_INPUT, "%s: OpenImageIO asked for a buffer larger than the file can fill (a damaged or forged size)",
                path);
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
