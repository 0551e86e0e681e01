/* What the OpenImageIO module reads in the full build (oiio_load.c), refused in
 * the build without it (FS_WITH_OIIO=OFF): EXRs that are not scanline images. */
#include "fs_error.h"
#include "image_exr_core.h"

#include <string.h>

int fs_read_image_oiio(const char *path, fs_image *img)
{
    memset(img, 0, sizeof *img);
    return fs_fail(
        FS_ERR_INPUT,
        "%s: a tiled or deep EXR needs a build with FS_WITH_OIIO=ON (only scanline EXRs are read without it)", path);
}
