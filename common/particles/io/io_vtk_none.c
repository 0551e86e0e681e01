/* VTK left out (FS_WITH_VTK=OFF, the lean build): .vtu files are refused with
 * one line naming the option, as bad input. Legacy .vtk files need no VTK
 * (io_vtk_legacy.c). */
#include "particle_io.h"
#include "fs_error.h"

static int refuse(const char *path, const char *what)
{
    return fs_fail(FS_ERR_INPUT, "%s: VTK %s needs a build with FS_WITH_VTK=ON", path, what);
}

int fs_read_vtu(fs_particles *p, const char *path)
{
    (void)p;
    return refuse(path, "XML (.vtu) input");
}
