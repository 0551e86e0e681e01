/* One harness per particle format (FS_FUZZ_FORMAT, the reader's format name and
 * extension): the real reader on the input; a read set is finite, and a failed
 * read leaves it empty. */
#include "fuzz_input.h"
#include "particle_io.h"
#include <math.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fs_particles p;
    memset(&p, 0, sizeof p);
    fs_error_clear();
    int rc = fs_particles_read(&p, fs_fuzz_file(data, size, FS_FUZZ_FORMAT), FS_FUZZ_FORMAT);
    fs_fuzz_check_message(rc);
    if (rc != FS_OK && p.n != 0) abort();
    for (size_t i = 0; rc == FS_OK && i < p.n; i++)
        if (!isfinite(p.x[i]) || !isfinite(p.y[i]) || !isfinite(p.z[i])) abort();
    if (rc == FS_OK && !(p.radius >= 0 && isfinite(p.radius))) abort();
    fs_particles_free(&p);
    return 0;
}
