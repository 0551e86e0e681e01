/* Every numeric point array of VTK, VTU, BGEO and PLY files is read, and written
 * back by the VTK, PLY and BGEO writers (particle_arrays.h):
 *  - the DualSPHysics crop (legacy VTK, big-endian): Idp (uint32) and Rhop
 *    (float32) besides Vel (the velocity); Idp equals the file's own bytes, read
 *    here independently, and Rhop lies in the frame's 853-1087 kg/m^3;
 *  - the bundled SPlisHSPlasH VTK's id, the VTU's pressure, density (Float64) and
 *    index (Int64, kept as float64; read in a child process: the arrays cross the
 *    pipe), the BGEO's id and density;
 *  - a PLY with uchar, short, uint and double properties besides x y z;
 *  - the crop written to .vtk, .ply and .bgeo and read back: the same arrays,
 *    names and values (BGEO holds no unsigned type: Idp comes back as int32). */
#define _GNU_SOURCE /* memmem */
#include "fs_error.h"
#include "fs_test.h"
#include "particle_arrays.h"
#include "particle_io.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CROP FS_TEST_DATA "/dualsphysics/dambreak200k_t0.300_crop902.vtk"
#define SPLASH FS_TEST_DATA "/splashsurf/"

static int read_ok(fs_particles *p, const char *path)
{
    int rc = fs_particles_read(p, path, NULL);
    CHECK(rc == FS_OK, "%s: %s", path, fs_error_message());
    return rc == FS_OK;
}

/* Array name of p has ncomp components of type t. */
static const fs_point_array *expect(const fs_particles *p, const char *name, int ncomp, fs_array_type t,
                                    const char *what)
{
    const fs_point_array *a = fs_particles_array(p, name);
    CHECK(a && a->ncomp == ncomp && a->type == t, "%s: array %s: %s", what, name,
          a ? fs_array_type_name(a->type) : "missing");
    return a && a->ncomp == ncomp && a->type == t ? a : NULL;
}

/* The crop's Idp as its bytes say: big-endian uint32 after "LOOKUP_TABLE default". */
static uint32_t *crop_ids(size_t n)
{
    FILE *f = fopen(CROP, "rb");
    static char buf[1 << 16];
    size_t len = f ? fread(buf, 1, sizeof buf, f) : 0;
    if (f) fclose(f);
    const char *key = "LOOKUP_TABLE default\n", *at = memmem(buf, len, key, strlen(key));
    if (!at || (size_t)(at - buf) + strlen(key) + 4 * n > len) return NULL;
    const unsigned char *b = (const unsigned char *)at + strlen(key);
    uint32_t *ids = malloc(n * sizeof *ids);
    for (size_t i = 0; ids && i < n; i++)
        ids[i] = (uint32_t)b[4 * i] << 24 | (uint32_t)b[4 * i + 1] << 16 | (uint32_t)b[4 * i + 2] << 8 | b[4 * i + 3];
    return ids;
}

static void crop(void)
{
    fs_particles p;
    if (!read_ok(&p, CROP)) return;
    CHECK(p.n == 902 && (fs_particles_fields(&p) & FS_HAS_VELOCITY) && p.narrays == 2, "crop: %zu, %d arrays", p.n,
          p.narrays);
    const fs_point_array *id = expect(&p, "Idp", 1, FS_ARRAY_U32, "crop"),
                         *rho = expect(&p, "Rhop", 1, FS_ARRAY_F32, "crop");
    uint32_t *want = crop_ids(p.n);
    size_t bad = 0;
    for (size_t i = 0; id && want && i < p.n; i++) bad += ((const uint32_t *)id->data)[i] != want[i];
    CHECK(want && !bad, "crop: %zu ids differ from the file's bytes", bad);
    for (size_t i = 0; rho && i < p.n; i++)
        bad += !(fs_point_array_get(rho, i) >= 853 && fs_point_array_get(rho, i) <= 1087);
    CHECK(!bad, "crop: %zu densities outside 853-1087", bad);
    free(want);
    fs_particles_free(&p);
}

static void bundled(void)
{
    fs_particles p;
    if (read_ok(&p, SPLASH "dam_break_frame_23_24389_particles.vtk")) {
        const fs_point_array *id = expect(&p, "id", 1, FS_ARRAY_U32, "dam break vtk");
        CHECK(p.narrays == 1 && id && ((const uint32_t *)id->data)[0] != ((const uint32_t *)id->data)[1],
              "dam break vtk: %d arrays, ids", p.narrays);
        fs_particles_free(&p);
    }
    if (read_ok(&p, SPLASH "fluid_250_particles.vtu")) {
        CHECK(p.narrays == 3 && (fs_particles_fields(&p) & FS_HAS_VELOCITY), "vtu: %d arrays", p.narrays);
        expect(&p, "pressure", 1, FS_ARRAY_F64, "vtu"); /* Float64 in the file */
        expect(&p, "density", 1, FS_ARRAY_F64, "vtu");
        const fs_point_array *ix = expect(&p, "index", 1, FS_ARRAY_F64, "vtu"); /* Int64: kept as float64 */
        CHECK(ix && fs_point_array_get(ix, 1) != fs_point_array_get(ix, 0), "vtu: index values");
        fs_particles_free(&p);
    }
    if (read_ok(&p, SPLASH "dam_break_frame_9_6859_particles.bgeo")) {
        expect(&p, "id", 1, FS_ARRAY_I32, "bgeo");
        const fs_point_array *d = expect(&p, "density", 1, FS_ARRAY_F32, "bgeo");
        CHECK(d && fs_point_array_get(d, 0) > 0, "bgeo: density %g", d ? fs_point_array_get(d, 0) : 0.0);
        fs_particles_free(&p);
    }
}

/* An ascii PLY with uchar, short, uint and double properties: each an array. */
static void ply_types(void)
{
    const char *path = FS_TEST_OUT "/arrays.ply";
    FILE *f = fopen(path, "w");
    if (!f) return;
    fprintf(f,
            "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
            "property uchar flag\nproperty short s\nproperty uint id\nproperty double rho\nend_header\n"
            "0 0 0 7 -3 4000000000 1000.5\n1 0 0 255 12 1 0.125\n");
    fclose(f);
    fs_particles p;
    if (!read_ok(&p, path)) return;
    const fs_point_array *flag = expect(&p, "flag", 1, FS_ARRAY_I32, "ply"),
                         *s = expect(&p, "s", 1, FS_ARRAY_I32, "ply"), *id = expect(&p, "id", 1, FS_ARRAY_U32, "ply"),
                         *rho = expect(&p, "rho", 1, FS_ARRAY_F64, "ply");
    CHECK(flag && s && id && rho && fs_point_array_get(flag, 1) == 255 && fs_point_array_get(s, 0) == -3 &&
              fs_point_array_get(id, 0) == 4000000000.0 && fs_point_array_get(rho, 0) == 1000.5,
          "ply: values");
    fs_particles_free(&p);
}

/* b's arrays are a's: names, components and values (types may widen). */
static void same_arrays(const fs_particles *a, const fs_particles *b, const char *what)
{
    CHECK(b->narrays == a->narrays, "%s: %d arrays, want %d", what, b->narrays, a->narrays);
    for (int i = 0; i < a->narrays; i++) {
        const fs_point_array *x = &a->arrays[i], *y = fs_particles_array(b, x->name);
        CHECK(y && y->ncomp == x->ncomp, "%s: %s lost", what, x->name);
        size_t bad = 0;
        for (size_t k = 0; y && y->ncomp == x->ncomp && k < a->n * (size_t)x->ncomp; k++)
            bad += fs_point_array_get(x, k) != fs_point_array_get(y, k);
        CHECK(!bad, "%s: %s: %zu values differ", what, x->name, bad);
    }
}

static void round_trip(void)
{
    fs_particles p, q;
    if (!read_ok(&p, CROP)) return;
    const char *outs[] = {FS_TEST_OUT "/arrays_out.vtk", FS_TEST_OUT "/arrays_out.ply", FS_TEST_OUT "/arrays_out.bgeo"};
    for (int i = 0; i < 3; i++) {
        int rc = fs_particles_write(&p, outs[i], NULL);
        CHECK(rc == FS_OK, "%s: %s", outs[i], fs_error_message());
        if (rc || !read_ok(&q, outs[i])) continue;
        same_arrays(&p, &q, outs[i]);
        const fs_point_array *id = fs_particles_array(&q, "Idp");
        CHECK(id && id->type == (i == 2 ? FS_ARRAY_I32 : FS_ARRAY_U32), "%s: Idp is %s", outs[i],
              id ? fs_array_type_name(id->type) : "missing");
        fs_particles_free(&q);
    }
    fs_particles_free(&p);
}

int main(void)
{
    crop();
    bundled();
    ply_types();
    round_trip();
    TEST_DONE();
}
