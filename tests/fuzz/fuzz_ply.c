/* libFuzzer harness: the ply particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "ply"
#include "fuzz_particles.h"
