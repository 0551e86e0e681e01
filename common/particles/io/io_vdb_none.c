/* OpenVDB left out (FS_WITH_OPENVDB=OFF, the lean build): VDB point files are
 * refused with one line naming the option, as bad input, before anything is written. */
#include "particle_io.h"
#include "fs_error.h"

int fs_read_vdb(fs_particles *p, const char *path)
{
    (void)p;
    return fs_fail(FS_ERR_INPUT, "%s: VDB input needs a build with FS_WITH_OPENVDB=ON", path);
}

int fs_write_vdb(const fs_particles *p, const char *path)
{
    (void)p;
    return fs_fail(FS_ERR_INPUT, "%s: VDB output needs a build with FS_WITH_OPENVDB=ON", path);
}
