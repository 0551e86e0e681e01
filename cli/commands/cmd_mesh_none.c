/* fluidsurf mesh without OpenVDB (FS_WITH_OPENVDB=OFF, the lean build): the
 * mesh method meshes through OpenVDB, so the command is refused with one line. */
#include "cli.h"
#include <stdio.h>

int cmd_mesh(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "fluidsurf: mesh needs a build with FS_WITH_OPENVDB=ON\n");
    return 2;
}
