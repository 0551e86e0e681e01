// Thin VTK 9 adapter of the mesh export (mesh_export.h): the mesh as
// vtkPolyData (float points, triangle cells, point normals, and the point
// arrays "velocity" and "color" when the mesh has them; the provenance as
// field data) written by
// vtkPolyDataWriter (legacy binary .vtk) or vtkXMLPolyDataWriter (.vtp,
// appended binary, zlib).
#include "mesh_export.h"
#include "fs_error.h"

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <clocale>
#include <exception>
#include <locale>
#include <new>
#include <string>

namespace
{

// A 3-component point array named name (a is 3 nv floats).
void add_array(vtkPolyData *pd, const fs_trimesh *m, const float *a, const char *name)
{
    vtkNew<vtkFloatArray> arr;
    arr->SetNumberOfComponents(3);
    arr->SetName(name);
    arr->SetNumberOfTuples((vtkIdType)m->nv);
    for (size_t i = 0; i < 3 * m->nv; i++) arr->SetValue((vtkIdType)i, a[i]);
    pd->GetPointData()->AddArray(arr);
}

void fill(vtkPolyData *pd, const fs_trimesh *m)
{
    vtkNew<vtkFloatArray> xyz, nrm;
    xyz->SetNumberOfComponents(3);
    nrm->SetNumberOfComponents(3);
    nrm->SetName("Normals");
    xyz->SetNumberOfTuples((vtkIdType)m->nv);
    nrm->SetNumberOfTuples((vtkIdType)m->nv);
    for (size_t i = 0; i < 3 * m->nv; i++) {
        xyz->SetValue((vtkIdType)i, m->pos[i]);
        nrm->SetValue((vtkIdType)i, m->nrm[i]);
    }
    vtkNew<vtkPoints> pts;
    pts->SetData(xyz);
    vtkNew<vtkIdTypeArray> offsets, conn;
    offsets->SetNumberOfTuples((vtkIdType)m->nt + 1);
    conn->SetNumberOfTuples((vtkIdType)(3 * m->nt));
    for (size_t t = 0; t <= m->nt; t++) offsets->SetValue((vtkIdType)t, (vtkIdType)(3 * t));
    for (size_t i = 0; i < 3 * m->nt; i++) conn->SetValue((vtkIdType)i, (vtkIdType)m->tri[i]);
    vtkNew<vtkCellArray> polys;
    polys->SetData(offsets, conn);
    pd->SetPoints(pts);
    pd->SetPolys(polys);
    pd->GetPointData()->SetNormals(nrm);
    if (m->vel) add_array(pd, m, m->vel, "velocity");
    if (m->col) add_array(pd, m, m->col, "color");
}

// The provenance as field data: one string array of one value per entry, named
// as its EXR attribute (fluidsurf:NAME).
void add_provenance(vtkPolyData *pd, const fs_provenance *prov)
{
    for (int i = 0; prov && i < prov->n; i++) {
        vtkNew<vtkStringArray> a;
        a->SetName(prov->name[i]);
        a->InsertNextValue(prov->value[i]);
        pd->GetFieldData()->AddArray(a);
    }
}

// The process's locale, put back when this goes out of scope: VTK 9.1's legacy
// writer (vtkDataWriter::OpenVTKFile) sets the global locale to "C" and leaves it,
// which in Python turns open()'s default encoding into ASCII for the rest of the session.
struct keep_locale {
    std::locale cxx;
    std::string c = std::setlocale(LC_ALL, nullptr);
    ~keep_locale()
    {
        std::locale::global(cxx);
        std::setlocale(LC_ALL, c.c_str());
    }
};

} // namespace

extern "C" int fs_mesh_write_vtk(const fs_trimesh *m, const char *path, const char *tmp, int xml,
                                 const fs_provenance *prov)
{
    try {
        keep_locale keep;
        vtkNew<vtkPolyData> pd;
        fill(pd, m);
        add_provenance(pd, prov);
        int ok;
        if (xml) {
            vtkNew<vtkXMLPolyDataWriter> w;
            w->SetFileName(tmp);
            w->SetInputData(pd);
            w->SetDataModeToAppended();
            w->SetCompressorTypeToZLib();
            ok = w->Write() == 1 && w->GetErrorCode() == 0;
        } else {
            vtkNew<vtkPolyDataWriter> w;
            w->SetFileName(tmp);
            w->SetInputData(pd);
            w->SetFileTypeToBinary();
            ok = w->Write() == 1 && w->GetErrorCode() == 0;
        }
        return ok ? FS_OK : fs_fail(FS_ERR_RUNTIME, "%s: VTK could not write the mesh", path);
    } catch (const std::bad_alloc &) {
        return fs_fail(FS_ERR_RUNTIME, "%s: out of memory writing the mesh through VTK", path);
    } catch (const std::exception &e) {
        return fs_fail(FS_ERR_RUNTIME, "%s: VTK: %s", path, e.what());
    }
}
