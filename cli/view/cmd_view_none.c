/* fluidsurf view without GLFW (FS_WITH_GLFW=OFF, the lean build): the window
 * needs GLFW, so the command is refused with one line, as bad usage. */
#include "cli.h"
#include <stdio.h>

int cmd_view(int argc, char **argv)
{
    (void)argc, (void)argv;
    fprintf(stderr, "fluidsurf: view needs a build with FS_WITH_GLFW=ON\n");
    return 2;
}
