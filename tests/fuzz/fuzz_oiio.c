/* libFuzzer harness: images through OpenImageIO (image_oiio.cpp), as diff and --import read them. */
#define FS_FUZZ_EXT "exr"
#include "fuzz_image.h"
