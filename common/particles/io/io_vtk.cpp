// Thin VTK 9 adapter: legacy .vtk and XML .vtu readers (positions, plus
// "velocity", colour and phase arrays when present); the legacy binary writer
// is written by hand (big-endian, VTK 4.x layout, vertex cells).
//
// VTK reports problems through vtkErrorMacro and may still hand back partial
// data, so every read captures the errors (observer on the reader and on the
// output window, which is muted meanwhile) and checks the point count against
// the file's own declaration. The capture changes process-wide VTK state
// (output window, logger) for the duration of a read: read VTK files from
// one thread at a time.
#include "particle_io.h"
#include "fs_error.h"
#include "output_file.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
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
#include <string>
#include <strings.h>
#include <sys/stat.h>

namespace {

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
class ErrorCapture {
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
            if (a && name_is(a->GetName(), names) && a->GetNumberOfComponents() == comps &&
                a->GetNumberOfTuples() == n)
                return a;
        }
    }
    return nullptr;
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
    return FS_OK;
}

size_t legacy_type_size(const char *t)
{
    static const struct { const char *name; size_t size; } types[] = {
        {"float", 4}, {"double", 8}, {"int", 4}, {"unsigned_int", 4}, {"short", 2}, {"unsigned_short", 2},
        {"char", 1}, {"unsigned_char", 1}, {"long", 8}, {"unsigned_long", 8}, {"vtktypeint64", 8},
        {"vtktypeuint64", 8},
    };
    for (const auto &e : types)
        if (strcasecmp(t, e.name) == 0) return e.size;
    return 0;
}

// Reads the legacy header ourselves: magic, ASCII/BINARY, and the POINTS line.
// *declared is the POINTS count (-1 when the dataset has no POINTS line, e.g.
// structured points). For binary files the point data must fit in the file.
int check_legacy_header(const char *path, long long *declared)
{
    *declared = -1;
    FILE *f = fopen(path, "rb");
    if (!f) return fs_fail(FS_ERR_INPUT, "%s: cannot open", path);
    struct stat st;
    char line[512];
    int rc = FS_OK, binary = 0;
    if (fstat(fileno(f), &st) != 0)
        rc = fs_fail(FS_ERR_INPUT, "%s: cannot stat", path);
    else if (!fgets(line, sizeof line, f) || strncmp(line, "# vtk DataFile Version", 22) != 0)
        rc = fs_fail(FS_ERR_INPUT, "%s: not a legacy VTK file (bad magic)", path);
    if (!rc && (!fgets(line, sizeof line, f) || !fgets(line, sizeof line, f)))
        rc = fs_fail(FS_ERR_INPUT, "%s: truncated VTK header", path);
    if (!rc) {
        binary = strncasecmp(line, "BINARY", 6) == 0;
        if (!binary && strncasecmp(line, "ASCII", 5) != 0)
            rc = fs_fail(FS_ERR_INPUT, "%s: VTK file is neither ASCII nor BINARY", path);
    }
    // The POINTS line follows DATASET within a few lines; stop after 64 lines.
    for (int k = 0; !rc && k < 64 && fgets(line, sizeof line, f); k++) {
        char type[64];
        long long n;
        if (strncasecmp(line, "POINTS", 6) != 0) continue;
        if (sscanf(line + 6, "%lld %63s", &n, type) != 2 || n < 0) {
            rc = fs_fail(FS_ERR_INPUT, "%s: bad VTK POINTS line", path);
            break;
        }
        *declared = n;
        size_t tsize = legacy_type_size(type);
        long long left = static_cast<long long>(st.st_size) - ftell(f);
        if (binary && tsize && n > left / static_cast<long long>(3 * tsize))
            rc = fs_fail(FS_ERR_INPUT, "%s: truncated VTK file: POINTS declares %lld points but only %lld bytes follow",
                         path, n, left);
        break;
    }
    fclose(f);
    return rc;
}

int fail_vtk(const char *path, const ErrorLog &log, const char *fallback)
{
    return fs_fail(FS_ERR_INPUT, "%s: %s", path, log.count ? log.first.c_str() : fallback);
}

} // namespace

extern "C" int fs_read_vtk(fs_particles *p, const char *path)
{
    long long declared;
    int rc = check_legacy_header(path, &declared);
    if (rc) return rc;
    vtkNew<vtkDataSetReader> reader;
    ErrorLog log;
    {
        ErrorCapture capture(reader, &log);
        reader->SetFileName(path);
        // Without these the reader keeps only the first SCALARS/VECTORS section.
        reader->ReadAllScalarsOn();
        reader->ReadAllVectorsOn();
        reader->ReadAllColorScalarsOn();
        reader->ReadAllFieldsOn();
        reader->Update();
    }
    vtkDataSet *ds = reader->GetOutput();
    if (log.count || !ds) return fail_vtk(path, log, "VTK could not read a dataset");
    if (declared >= 0 && ds->GetNumberOfPoints() != declared)
        return fs_fail(FS_ERR_INPUT, "%s: VTK read %lld points but the file declares %lld", path,
                       static_cast<long long>(ds->GetNumberOfPoints()), declared);
    return copy_dataset(p, path, ds);
}

extern "C" int fs_read_vtu(fs_particles *p, const char *path)
{
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    ErrorLog log;
    vtkDataSet *ds = nullptr;
    {
        ErrorCapture capture(reader, &log);
        if (!reader->CanReadFile(path))
            return fs_fail(FS_ERR_INPUT, "%s: not a VTK XML UnstructuredGrid (.vtu) file", path);
        reader->SetFileName(path);
        reader->Update();
        ds = reader->GetOutput();
    }
    if (log.count || !ds || reader->GetErrorCode()) return fail_vtk(path, log, "VTK could not read the file");
    if (ds->GetNumberOfPoints() != reader->GetNumberOfPoints())
        return fs_fail(FS_ERR_INPUT, "%s: VTK read %lld points but the file declares %lld", path,
                       static_cast<long long>(ds->GetNumberOfPoints()),
                       static_cast<long long>(reader->GetNumberOfPoints()));
    return copy_dataset(p, path, ds);
}

// ---- legacy binary writer (by hand: big-endian, one vertex cell per particle) ----

namespace {

struct BeWriter {
    FILE *f;
    bool ok;
    unsigned char buf[1 << 16];
    size_t len = 0;

    void flush()
    {
        if (ok && len && fwrite(buf, 1, len, f) != len) ok = false;
        len = 0;
    }
    void u32(uint32_t v)
    {
        if (len + 4 > sizeof buf) flush();
        buf[len++] = static_cast<unsigned char>(v >> 24);
        buf[len++] = static_cast<unsigned char>(v >> 16);
        buf[len++] = static_cast<unsigned char>(v >> 8);
        buf[len++] = static_cast<unsigned char>(v);
    }
    void f32(float x)
    {
        uint32_t u;
        memcpy(&u, &x, 4);
        u32(u);
    }
    void text(const char *s)
    {
        flush();
        if (ok && fputs(s, f) < 0) ok = false;
    }
};

} // namespace

extern "C" int fs_write_vtk(const fs_particles *p, const char *path)
{
    if (p->n > INT32_MAX / 2) return fs_fail(FS_ERR_INPUT, "%s: too many particles for legacy VTK (%zu)", path, p->n);
    char tmp[4096];
    int rc = fs_output_begin(path, tmp, sizeof tmp);
    if (rc) return rc;
    BeWriter writer, *w = &writer;
    w->f = fopen(tmp, "wb");
    w->ok = w->f != nullptr;
    const size_t n = p->n;
    const unsigned fields = fs_particles_fields(p);
    char line[256];
    snprintf(line, sizeof line,
             "# vtk DataFile Version 3.0\nfluidsurf particles\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS %zu float\n", n);
    w->text(line);
    for (size_t i = 0; i < n; i++) {
        w->f32(p->x[i]);
        w->f32(p->y[i]);
        w->f32(p->z[i]);
    }
    snprintf(line, sizeof line, "\nCELLS %zu %zu\n", n, 2 * n);
    w->text(line);
    for (size_t i = 0; i < n; i++) {
        w->u32(1);
        w->u32(static_cast<uint32_t>(i));
    }
    snprintf(line, sizeof line, "\nCELL_TYPES %zu\n", n);
    w->text(line);
    for (size_t i = 0; i < n; i++) w->u32(1); // VTK_VERTEX
    w->text("\n");
    if (fields) {
        snprintf(line, sizeof line, "POINT_DATA %zu\n", n);
        w->text(line);
    }
    if (fields & FS_HAS_VELOCITY) {
        w->text("VECTORS velocity float\n");
        for (size_t i = 0; i < n; i++) {
            w->f32(p->vx[i]);
            w->f32(p->vy[i]);
            w->f32(p->vz[i]);
        }
        w->text("\n");
    }
    if (fields & FS_HAS_COLOR) {
        w->text("SCALARS color float 3\nLOOKUP_TABLE default\n");
        for (size_t i = 0; i < 3 * n; i++) w->f32(p->color[i]);
        w->text("\n");
    }
    if (fields & FS_HAS_PHASE) {
        w->text("SCALARS phase int 1\nLOOKUP_TABLE default\n");
        for (size_t i = 0; i < n; i++) w->u32(static_cast<uint32_t>(p->phase[i]));
        w->text("\n");
    }
    w->flush();
    bool ok = w->ok;
    if (w->f && fclose(w->f) != 0) ok = false;
    if (!ok) {
        fs_output_end(path, tmp, 0);
        return fs_fail(FS_ERR_RUNTIME, "%s: error writing VTK data", path);
    }
    return fs_output_end(path, tmp, 1);
}
