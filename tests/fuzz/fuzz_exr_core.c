/* libFuzzer harness: the lean build's own image readers (image_stb.c: PNG through stb, EXR through
 * OpenEXRCore in image_exr_core.c), sniffed by content. */
#define FS_FUZZ_EXT "img"
#include "fuzz_image.h"
