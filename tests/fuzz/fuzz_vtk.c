/* libFuzzer harness: the vtk particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "vtk"
#include "fuzz_particles.h"
