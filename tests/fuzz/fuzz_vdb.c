/* libFuzzer harness: the vdb particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "vdb"
#include "fuzz_particles.h"
