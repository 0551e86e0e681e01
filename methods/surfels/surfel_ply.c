#include "surfel_ply.h"
#include "fs_error.h"
#include "output_file.h"
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static unsigned char *put_f32(unsigned char *b, float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    for (int k = 0; k < 4; k++) b[k] = (unsigned char)(u >> (8 * k));
    return b + 4;
}

int fs_surfels_write_ply(const fs_surfel_set *set, const char *path)
{
    fs_output out;
    int rc = fs_output_open(&out, path);
    if (rc) return rc;
    FILE *f = out.f;
    int ok = fprintf(f,
                     "ply\nformat binary_little_endian 1.0\ncomment surfels written by fluidsurf (iwasaki2006)\n"
                     "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                     "property float nx\nproperty float ny\nproperty float nz\nproperty float radius\nend_header\n",
                     set->n) > 0;
    unsigned char rec[28];
    for (size_t i = 0; ok && i < set->n; i++) {
        const fs_surfel *s = &set->s[i];
        unsigned char *w = rec;
        for (int k = 0; k < 3; k++) w = put_f32(w, s->pos[k]);
        for (int k = 0; k < 3; k++) w = put_f32(w, s->normal[k]);
        put_f32(w, s->radius);
        ok = fwrite(rec, 1, sizeof rec, f) == sizeof rec;
    }
    return fs_output_close(&out, ok);
}
