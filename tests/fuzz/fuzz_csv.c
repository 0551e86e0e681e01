/* libFuzzer harness: the csv particle reader (fuzz_particles.h). */
#define FS_FUZZ_FORMAT "csv"
#include "fuzz_particles.h"
