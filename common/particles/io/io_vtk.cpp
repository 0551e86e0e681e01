// Thin VTK 9 adapter: the XML .vtu reader (positions, plus "velocity", colour
// and phase arrays when present, and every other numeric point array as a
// point array of its own, particle_arrays.h). Legacy .vtk files are read and written by our
// own code (io_vtk_legacy.c): VTK's legacy readers crash on malformed files.
//
// VTK reports problems through vtkErrorMacro and may still hand back partial
// data, so every read captures the errors (observer on the reader and on the
// output window, which is muted meanwhile) and checks the point count against
// the file's own declaration. The read runs in a forked child (fs_read_vtu), so
// the capture's change to process-wide VTK state (output window, logger) and
// anything VTK breaks on a damaged file stay there.
#include "particle_io.h"
#include "alloc_cap.h"
#include "particle_arrays.h"
#include "fs_error.h"
#include "read_in_child.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <strings.h>
#include <sys/stat.h>

namespace
{

// Keeps the first VTK error as one line, without VTK's "ERROR: In file, line" prefix.
struct ErrorLog {
    int count = 0;
    std::string first;
};

void on_error(vtkObject *, unsigned long, void *client, void *call)
{
    ErrorLog *log = static_cast<ErrorLog *>(client);
    if (log->count++ || !call) return;
    std::string s = static_cast<const char *>(call);
    // Drop "ERROR: In FILE, line N" / "Generic Warning: In FILE, line N" and "vtkClass (0x...): ".
    size_t nl = s.find('\n');
    if (nl != std::string::npos && s.rfind(", line ", nl) != std::string::npos) s = s.substr(nl + 1);
    size_t obj = s.find("): ");
    if (obj != std::string::npos && s.compare(0, 3, "vtk") == 0) s = s.substr(obj + 3);
    std::string one;
    for (char c : s) {
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
        if (c != ' ' || (!one.empty() && one.back() != ' ')) one += c;
    }
    while (!one.empty() && one.back() == ' ') one.pop_back();
    log->first = "VTK: " + (one.empty() ? std::string("unknown error") : one);
}

// Routes VTK errors and warnings of `reader` and of any helper object into `log`
// while alive, and keeps them off stderr.
class ErrorCapture
{
  public:
    ErrorCapture(vtkAlgorithm *reader, ErrorLog *log) : reader_(reader)
    {
        cb_->SetCallback(on_error);
        cb_->SetClientData(log);
        window_ = vtkOutputWindow::GetInstance();
        mode_ = window_->GetDisplayMode();
        window_->SetDisplayModeToNever();
        // Helper objects inside the readers also log straight to stderr through vtkLogger.
        verbosity_ = vtkLogger::GetCurrentVerbosityCutoff();
        vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
        // Warnings count as failures: the legacy reader only warns about truncated data.
        for (unsigned long event : {vtkCommand::ErrorEvent, vtkCommand::WarningEvent}) {
            tags_[n_tags_++] = reader_->AddObserver(event, cb_);
            tags_[n_tags_++] = window_->AddObserver(event, cb_);
        }
    }
    ~ErrorCapture()
    {
        for (int i = 0; i < n_tags_; i += 2) {
            reader_->RemoveObserver(tags_[i]);
            window_->RemoveObserver(tags_[i + 1]);
        }
        vtkLogger::SetStderrVerbosity(verbosity_);
        window_->SetDisplayMode(mode_);
    }
    ErrorCapture(const ErrorCapture &) = delete;
    ErrorCapture &operator=(const ErrorCapture &) = delete;

  private:
    vtkAlgorithm *reader_;
    vtkOutputWindow *window_;
    vtkNew<vtkCallbackCommand> cb_;
    unsigned long tags_[4] = {0, 0, 0, 0};
    int n_tags_ = 0;
    int mode_ = vtkOutputWindow::DEFAULT;
    vtkLogger::Verbosity verbosity_ = vtkLogger::VERBOSITY_WARNING;
};

bool name_is(const char *name, const char *const *names)
{
    for (; name && *names; names++)
        if (strcasecmp(name, *names) == 0) return true;
    return false;
}

// A point-data or field-data array with one of the names, `comps` components and n tuples.
vtkDataArray *find_array(vtkDataSet *ds, const char *const *names, int comps, vtkIdType n)
{
    vtkFieldData *sets[2] = {ds->GetPointData(), ds->GetFieldData()};
    for (vtkFieldData *fd : sets) {
        for (int i = 0; fd && i < fd->GetNumberOfArrays(); i++) {
            vtkDataArray *a = fd->GetArray(i);
            if (a && name_is(a->GetName(), names) && a->GetNumberOfComponents() == comps && a->GetNumberOfTuples() == n)
                return a;
        }
    }
    return nullptr;
}

// The point array type that holds a VTK array's values (64-bit integers as float64).
fs_array_type array_type_of(vtkDataArray *a)
{
    switch (a->GetDataType()) {
    case VTK_FLOAT: return FS_ARRAY_F32;
    case VTK_UNSIGNED_INT: return FS_ARRAY_U32;
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT: return FS_ARRAY_I32;
    default: return FS_ARRAY_F64;
    }
}

// Every numeric point-data array of n tuples but the used ones as a point array of p.
int copy_others(fs_particles *p, vtkDataSet *ds, vtkIdType n, const vtkDataArray *const used[3])
{
    vtkPointData *pd = ds->GetPointData();
    for (int i = 0; pd && i < pd->GetNumberOfArrays() && p->narrays < FS_MAX_POINT_ARRAYS; i++) {
        vtkDataArray *a = pd->GetArray(i); // NULL for a string array
        if (!a || a == used[0] || a == used[1] || a == used[2] || a->GetNumberOfTuples() != n) continue;
        int nc = a->GetNumberOfComponents();
        if (nc < 1 || nc > FS_MAX_ARRAY_COMPONENTS) continue;
        fs_point_array *out;
        int rc = fs_particles_add_array(p, a->GetName() ? a->GetName() : "", nc, array_type_of(a), &out);
        if (rc) return rc;
        for (vtkIdType t = 0; t < n; t++)
            for (int c = 0; c < nc; c++)
                fs_point_array_set(out, static_cast<size_t>(t) * nc + c, a->GetComponent(t, c));
    }
    return FS_OK;
}

// Copies positions and the optional arrays of ds into p.
int copy_dataset(fs_particles *p, const char *path, vtkDataSet *ds)
{
    static const char *const vel_names[] = {"velocity", "velocities", "vel", "v", nullptr};
    static const char *const color_names[] = {"color", "colors", "colour", "Cd", "rgb", nullptr};
    static const char *const phase_names[] = {"phase", nullptr};
    vtkIdType n = ds->GetNumberOfPoints();
    vtkDataArray *vel = find_array(ds, vel_names, 3, n);
    vtkDataArray *col = find_array(ds, color_names, 3, n);
    vtkDataArray *ph = find_array(ds, phase_names, 1, n);
    unsigned fields = (vel ? FS_HAS_VELOCITY : 0) | (col ? FS_HAS_COLOR : 0) | (ph ? FS_HAS_PHASE : 0);
    int rc = fs_particles_alloc(p, static_cast<size_t>(n), fields);
    if (rc) return rc;
    double cscale = col && vtkUnsignedCharArray::SafeDownCast(col) ? 1.0 / 255.0 : 1.0;
    for (vtkIdType i = 0; i < n; i++) {
        double x[3];
        ds->GetPoint(i, x);
        p->x[i] = static_cast<float>(x[0]);
        p->y[i] = static_cast<float>(x[1]);
        p->z[i] = static_cast<float>(x[2]);
        if (vel) {
            vel->GetTuple(i, x);
            p->vx[i] = static_cast<float>(x[0]);
            p->vy[i] = static_cast<float>(x[1]);
            p->vz[i] = static_cast<float>(x[2]);
        }
        if (col) {
            col->GetTuple(i, x);
            for (int k = 0; k < 3; k++) p->color[3 * i + k] = static_cast<float>(x[k] * cscale);
        }
        if (ph) {
            double v = ph->GetComponent(i, 0);
            if (!(v >= INT32_MIN && v <= INT32_MAX)) {
                fs_particles_free(p);
                return fs_fail(FS_ERR_INPUT, "%s: phase of point %lld out of range", path, (long long)i);
            }
            p->phase[i] = static_cast<int32_t>(v);
        }
    }
    const vtkDataArray *const used[3] = {vel, col, ph};
    return copy_others(p, ds, n, used);
}

int fail_vtk(const char *path, const ErrorLog &log, const char *fallback)
{
    return fs_fail(FS_ERR_INPUT, "%s: %s", path, log.count ? log.first.c_str() : fallback);
}

// A forged VTU can declare far more points or cells than its bytes hold; VTK would
// then allocate for them (4294967296 cells: a 4 GB malloc for their types from a
// 735-byte file, tests/fuzz/regress_vtu/cells_4294967296.vtu). The declared counts of
// every Piece, at 12 bytes a point and 1 a cell (its type), must fit in 1032 times the
// file's size (zlib's largest ratio; raw and base64 data need at least the size
// itself), and each must be a number >= 0: VTK read NumberOfCells="-1e309" as -1 and
// cleared SIZE_MAX bytes (regress_vtu/cells_minus_1e309.vtu). head: the file's start.
int check_vtu_count(const char *path, const std::string &head, double file_size, const char *what, double bytes)
{
    std::string key = std::string(what) + "=\"";
    double declared = 0;
    for (size_t at = head.find(key); at != std::string::npos; at = head.find(key, at + 1)) {
        double n = strtod(head.c_str() + at + key.size(), nullptr);
        if (!(n >= 0)) return fs_fail(FS_ERR_INPUT, "%s: bad %s in the VTU file", path, what);
        declared += n;
    }
    if (declared * bytes > 1032.0 * file_size)
        return fs_fail(FS_ERR_INPUT, "%s: VTU file declares %.0f %s, more than its %.0f bytes can hold", path, declared,
                       strcmp(what, "NumberOfPoints") ? "cells" : "points", file_size);
    return FS_OK;
}

int check_vtu_counts(const char *path, const std::string &head, double file_size)
{
    int rc = check_vtu_count(path, head, file_size, "NumberOfPoints", 12);
    return rc ? rc : check_vtu_count(path, head, file_size, "NumberOfCells", 1);
}

// The value of attribute `name` in the tag that holds position at, or "".
std::string attr_in_tag(const std::string &s, size_t at, const char *name)
{
    size_t lo = s.rfind('<', at), hi = s.find('>', at);
    if (lo == std::string::npos || hi == std::string::npos) return "";
    std::string tag = s.substr(lo, hi - lo), key = std::string(" ") + name + "=\"";
    size_t k = tag.find(key);
    if (k == std::string::npos) return "";
    size_t v = k + key.size(), e = tag.find('"', v);
    return e == std::string::npos ? "" : tag.substr(v, e - v);
}

// VTK's reader loops over an array's NumberOfComponents (vtkXMLReader::CreateArray looks
// up a ComponentName attribute for each) before it allocates anything, so a forged count
// such as 4294967295 (read as INT_MAX) hangs it for minutes without touching memory
// (tests/fuzz/regress_vtu/components_4294967295.vtu). Every DataArray's count must be a
// number up to 1024, as in the legacy reader. f: the file or its start; tags only (the
// appended data is not XML).
int check_vtu_components(const char *path, const std::string &f)
{
    static const char key[] = "NumberOfComponents=\"";
    size_t stop = f.find("<AppendedData");
    for (size_t at = f.find(key); at < stop && at != std::string::npos; at = f.find(key, at + 1)) {
        size_t v = at + sizeof key - 1, e = f.find('"', v);
        std::string value = f.substr(v, e == std::string::npos ? 32 : e - v);
        if (strtod(value.c_str(), nullptr) <= 1024) continue;
        std::string name = attr_in_tag(f, at, "Name").substr(0, 32);
        name = name.empty() ? "a VTU DataArray" : "VTU DataArray '" + name + "'";
        return fs_fail(FS_ERR_INPUT, "%s: %s has NumberOfComponents '%.32s' (at most 1024)", path, name.c_str(),
                       value.c_str());
    }
    return FS_OK;
}

// How a VTU file's binary arrays are laid out, from its root element.
struct Layout {
    int hs = 4;          // header word size
    bool zipped = false; // compressed blocks
    bool little = true;
};

Layout layout_of(const std::string &f)
{
    Layout l;
    size_t root = f.find("<VTKFile");
    if (root == std::string::npos) return l;
    l.hs = attr_in_tag(f, root + 1, "header_type") == "UInt64" ? 8 : 4;
    l.zipped = !attr_in_tag(f, root + 1, "compressor").empty();
    l.little = attr_in_tag(f, root + 1, "byte_order") != "BigEndian";
    return l;
}

// Up to n bytes of an array's stream that starts at f[at]: raw, or base64 decoded
// (whitespace skipped, ending at padding or at anything else that is not base64).
std::string stream_bytes(const std::string &f, size_t at, size_t n, bool base64)
{
    if (!base64) return at < f.size() ? f.substr(at, n) : std::string();
    static const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    uint32_t acc = 0;
    int bits = 0;
    for (size_t i = at; i < f.size() && out.size() < n; i++) {
        if (f[i] == ' ' || f[i] == '\n' || f[i] == '\r' || f[i] == '\t') continue;
        size_t d = digits.find(f[i]);
        if (d == std::string::npos) break;
        acc = (acc << 6) | static_cast<uint32_t>(d);
        if ((bits += 6) >= 8) out += static_cast<char>((acc >> (bits -= 8)) & 0xffu);
    }
    return out;
}

// Header word k of bytes (at least (k + 1) * hs of them).
double header_word(const std::string &bytes, const Layout &l, size_t k)
{
    uint64_t u = 0;
    for (int b = 0; b < l.hs; b++)
        u |= static_cast<uint64_t>(static_cast<unsigned char>(bytes[k * l.hs + (l.little ? b : l.hs - 1 - b)]))
            << (8 * b);
    return static_cast<double>(u);
}

// One binary array's header, read before VTK sizes its buffers from it.
// Uncompressed: its byte count must fit in the file. Compressed: its block count
// and compressed sizes must fit in the file, what they unpack to must lie within
// zlib's largest ratio (1032:1), and the blocks must be ones VTK copies safely.
// budget: the file's bytes not yet claimed by headers; all headers share the file,
// so a forged block count in each of many arrays is refused early, not read.
bool header_fits(const std::string &f, size_t at, bool base64, const Layout &l, double *budget)
{
    const double size = static_cast<double>(f.size());
    size_t hs = static_cast<size_t>(l.hs);
    std::string h = stream_bytes(f, at, l.zipped ? 3 * hs : hs, base64);
    if (h.size() < (l.zipped ? 3 * hs : hs)) return false;
    double nb = header_word(h, l, 0);
    if (!l.zipped) return nb <= size;
    double bs = header_word(h, l, 1), lbs = header_word(h, l, 2), cs = 0;
    if ((*budget -= nb * static_cast<double>(hs)) < 0) return false;
    h = stream_bytes(f, at, (3 + static_cast<size_t>(nb)) * hs, base64);
    if (h.size() < (3 + static_cast<size_t>(nb)) * hs) return false;
    for (size_t k = 0; k < static_cast<size_t>(nb); k++)
        if ((cs += header_word(h, l, 3 + k)) > size) return false;
    if (nb == 0) return true;
    // VTK divides by the block size, and copies a partial last block larger than a
    // full one past its output buffer (vtkXMLDataParser::ReadCompressedData)
    if (!(bs > 0 && lbs <= bs)) return false;
    return (nb - 1) * bs + (lbs > 0 ? lbs : bs) <= 1032.0 * cs + 1032.0;
}

// Every binary array's header: appended ones (raw, VTK's own writer's default, or
// base64) at their offsets, inline ones (format="binary", base64) in their element.
int check_vtu_headers(const char *path, const std::string &f)
{
    Layout l = layout_of(f);
    double budget = static_cast<double>(f.size());
    size_t app = f.find("<AppendedData");
    std::string encoding = app == std::string::npos ? "" : attr_in_tag(f, app + 1, "encoding");
    size_t base = app == std::string::npos ? std::string::npos : f.find('_', app);
    if (app != std::string::npos && base == std::string::npos)
        return fs_fail(FS_ERR_INPUT, "%s: VTU appended data has no '_' marker", path);
    for (size_t at = f.find("format=\"appended\""); app != std::string::npos && at < app;
         at = f.find("format=\"appended\"", at + 1)) {
        std::string off = attr_in_tag(f, at, "offset");
        char *end;
        double o = strtod(off.c_str(), &end);
        bool ok = !off.empty() && !*end && o >= 0 && base + 1 + o < static_cast<double>(f.size());
        if (!ok || !header_fits(f, base + 1 + static_cast<size_t>(o), encoding != "raw", l, &budget))
            return fs_fail(FS_ERR_INPUT, "%s: VTU array header at appended offset '%.32s' does not fit the file", path,
                           off.c_str());
    }
    size_t stop = app == std::string::npos ? f.size() : app;
    for (size_t at = f.find("format=\"binary\""); at < stop; at = f.find("format=\"binary\"", at + 1)) {
        size_t hi = f.find('>', at);
        if (hi == std::string::npos || f[hi - 1] == '/') continue; // no data: VTK refuses it
        if (!header_fits(f, hi + 1, true, l, &budget))
            return fs_fail(FS_ERR_INPUT,
                           "%s: VTU array header of inline binary DataArray '%.32s' does not fit the file", path,
                           attr_in_tag(f, at, "Name").c_str());
    }
    return FS_OK;
}

// Reads the file once for both checks: whole up to 256 MB (a forged file is
// small), else its first 64 kB for the counts, the rest left to VTK.
int check_vtu(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return fs_fail(FS_ERR_INPUT, "%s: cannot open", path);
    struct stat st;
    int rc = fstat(fileno(fp), &st) == 0 ? FS_OK : fs_fail(FS_ERR_INPUT, "%s: cannot stat", path);
    bool whole = !rc && st.st_size <= (256 << 20);
    std::string f(rc ? 0 : whole ? static_cast<size_t>(st.st_size) : 65536, '\0');
    f.resize(fread(&f[0], 1, f.size(), fp));
    fclose(fp);
    if (!rc) rc = check_vtu_counts(path, f.substr(0, 65536), static_cast<double>(st.st_size));
    if (!rc) rc = check_vtu_components(path, f);
    if (!rc && whole) rc = check_vtu_headers(path, f);
    return rc;
}

// VTK's read, in this process: fs_fail set on failure, p left empty then.
int read_here(fs_particles *p, const char *path)
{
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    ErrorLog log;
    vtkDataSet *ds = nullptr;
    try { // VTK's XML parser throws std::length_error / std::bad_alloc on forged compression headers
        ErrorCapture capture(reader, &log);
        fs::AllocCap cap(path); // VTK sizes arrays from the file's headers
        if (!reader->CanReadFile(path))
            return fs_fail(FS_ERR_INPUT, "%s: not a VTK XML UnstructuredGrid (.vtu) file", path);
        reader->SetFileName(path);
        reader->Update();
        ds = reader->GetOutput();
    } catch (const std::bad_alloc &) {
        return fs_fail(FS_ERR_INPUT,
                       "%s: VTK asked for a buffer larger than the file can fill (a damaged or forged size)", path);
    } catch (const std::exception &e) {
        return fs_fail(FS_ERR_INPUT, "%s: VTK: %s", path, e.what());
    }
    if (log.count || !ds || reader->GetErrorCode()) return fail_vtk(path, log, "VTK could not read the file");
    if (ds->GetNumberOfPoints() != reader->GetNumberOfPoints())
        return fs_fail(FS_ERR_INPUT, "%s: VTK read %lld points but the file declares %lld", path,
                       static_cast<long long>(ds->GetNumberOfPoints()),
                       static_cast<long long>(reader->GetNumberOfPoints()));
    return copy_dataset(p, path, ds);
}

} // namespace

// VTK reads the file in a child process (read_in_child.h): its XML parser has more
// ways to write past a buffer on forged headers than the checks above can rule out
// (a partial last block larger than a full one was found by CI's fuzz smoke run:
// tests/fuzz/regress_vtu/partial_block_larger_than_block.vtu).
extern "C" int fs_read_vtu(fs_particles *p, const char *path)
{
    int rc = check_vtu(path); // here, for precise messages and for the fuzzer to see
    if (rc) return rc;
    return fs_read_in_child(p, path, read_here, "damaged VTU file: VTK's XML reader");
}
