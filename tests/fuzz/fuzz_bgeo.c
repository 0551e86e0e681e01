/* libFuzzer harness: the bgeo particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "bgeo"
#include "fuzz_particles.h"
