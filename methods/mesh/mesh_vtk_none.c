/* The mesh export's .vtk/.vtp writer in a build without VTK: a refusal. */
#include "fs_error.h"
#include "mesh_export.h"

int fs_mesh_write_vtk(const fs_trimesh *m, const char *path, const char *tmp, int xml, const fs_provenance *prov)
{
    (void)m;
    (void)tmp;
    (void)prov;
    return fs_fail(FS_ERR_INPUT, "%s: %s output needs a build with FS_WITH_VTK=ON", path, xml ? ".vtp" : ".vtk");
}
