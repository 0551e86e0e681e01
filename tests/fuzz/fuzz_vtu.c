/* libFuzzer harness: the vtu particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "vtu"
#include "fuzz_particles.h"
