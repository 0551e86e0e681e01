/* Image helpers that need no OpenImageIO: sRGB transfer and channel lookup. */
#include "image_io.h"
#include <math.h>
#include <string.h>

/* IEC 61966-2-1 encode of a linear value clamped to [0,1] (NaN -> 0), in double. */
int fs_image_channel(const fs_image *img, const char *name)
{
    for (int c = 0; c < img->nch; c++)
        if (img->chnames && img->chnames[c] && strcmp(img->chnames[c], name) == 0) return c;
    return -1;
}
