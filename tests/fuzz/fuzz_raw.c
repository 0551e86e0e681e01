/* libFuzzer harness: the raw particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "raw"
#include "fuzz_particles.h"
