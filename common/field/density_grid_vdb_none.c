/* OpenVDB left out (FS_WITH_OPENVDB=OFF, the lean build): density grids are not
 * written to or read from .vdb; one line naming the option, bad input, no file. */
#include "density_grid.h"
#include "fs_error.h"
#include <string.h>

int fs_density_grid_write_vdb(const fs_density_grid *g, const char *path, const char *name)
{
    (void)g, (void)name;
    return fs_fail(FS_ERR_INPUT, "%s: VDB output needs a build with FS_WITH_OPENVDB=ON", path);
}

int fs_density_grid_read_vdb(fs_density_grid *g, const char *path, const char *name)
{
    (void)name;
    memset(g, 0, sizeof *g);
    return fs_fail(FS_ERR_INPUT, "%s: VDB input needs a build with FS_WITH_OPENVDB=ON", path);
}
