/* Bad particle files: each read must fail with FS_ERR_INPUT, a one-line message
 * starting with the path, and an empty particle set. The bad files are made
 * here, in FS_TEST_OUT, from the real data files or by hand. */
#include "fs_error.h"
#include "fs_test.h"
#include "particle_io.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#define DATA FS_TEST_DATA "/splashsurf/"

static char *out_path(const char *name)
{
    static char buf[8][512];
    static int k;
    char *s = buf[k++ % 8];
    snprintf(s, sizeof buf[0], "%s/%s", FS_TEST_OUT, name);
    return s;
}

static void write_file(const char *path, const void *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL, "cannot create %s", path);
    if (!f) return;
    if (len) fwrite(data, 1, len, f);
    fclose(f);
}

static unsigned char *load(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL, "cannot open %s", path);
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    *len = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *d = malloc(*len);
    CHECK(d && fread(d, 1, *len, f) == *len, "cannot read %s", path);
    fclose(f);
    return d;
}

/* Copies the first `keep` bytes of src to dst. */
static void truncated_copy(const char *src, const char *dst, size_t keep)
{
    size_t len;
    unsigned char *d = load(src, &len);
    if (!d) return;
    CHECK(keep < len, "cut %zu is not inside %s (%zu bytes)", keep, src, len);
    write_file(dst, d, keep < len ? keep : len);
    free(d);
}

/* The read must fail as bad input, name the file first, fit one line and leave p empty. */
static void expect_bad(const char *path, const char *format, const char *contains)
{
    fs_particles p;
    memset(&p, 0xab, sizeof p); /* a stale value must not survive */
    fs_error_clear();
    int rc = fs_particles_read(&p, path, format);
    const char *msg = fs_error_message();
    CHECK(rc == FS_ERR_INPUT, "%s: returned %d (%s)", path, rc, msg);
    size_t len = strlen(path);
    int starts = strncmp(msg, path, len) == 0 && msg[len] == ':';
    CHECK(starts, "message does not start with the path: %s", msg);
    CHECK(strchr(msg, '\n') == NULL, "message is not one line: %s", msg);
    if (contains) CHECK(starts && strstr(msg + len, contains) != NULL, "message lacks '%s': %s", contains, msg);
    CHECK(p.n == 0 && p.x == NULL && p.vx == NULL, "%s: particle set not left empty", path);
    if (rc == FS_OK) fs_particles_free(&p);
}

static void put_be32(unsigned char **w, uint32_t v)
{
    for (int k = 3; k >= 0; k--) *(*w)++ = (unsigned char)(v >> (8 * k));
}

/* An uncompressed BGEO header with npoints points and one attribute definition. */
static size_t bgeo_header(unsigned char *b, int32_t npoints, int32_t attr_type)
{
    unsigned char *w = b;
    memcpy(w, "BgeoV", 5);
    w += 5;
    int32_t h[9] = {5, npoints, 0, 0, 0, 1, 0, 0, 0};
    for (int i = 0; i < 9; i++) put_be32(&w, (uint32_t)h[i]);
    *w++ = 0;
    *w++ = 1;
    *w++ = 'v'; /* name */
    *w++ = 0;
    *w++ = 3; /* size */
    put_be32(&w, (uint32_t)attr_type);
    for (int k = 0; k < 3; k++) put_be32(&w, 0);
    return (size_t)(w - b);
}

static void test_missing_empty_unknown(void)
{
    expect_bad(out_path("no_such_file.vtk"), NULL, "No such file");
    const char *empties[] = {"empty.vtk", "empty.vtu", "empty.bgeo", "empty.ply", "empty.vdb", "empty.csv"};
    for (size_t i = 0; i < sizeof empties / sizeof empties[0]; i++) {
        write_file(out_path(empties[i]), "", 0);
        expect_bad(out_path(empties[i]), NULL, "empty");
    }
    write_file(out_path("points.obj"), "v 1 2 3\n", 8);
    expect_bad(out_path("points.obj"), NULL, "extension");
    expect_bad(DATA "cube_2366_particles.vtk", "stl", "format");
}

static void test_truncated(void)
{
    /* VTK: header ~110 bytes, then 24389*12 bytes of positions: cut half-way through them. */
    truncated_copy(DATA "dam_break_frame_23_24389_particles.vtk", out_path("cut.vtk"), 110 + 24389 * 6);
    expect_bad(out_path("cut.vtk"), NULL, "truncated");
    /* Cut in the middle of a later section (velocity) too: VTK itself must report it. */
    size_t len;
    unsigned char *d = load(DATA "dam_break_frame_23_24389_particles.vtk", &len);
    if (d) {
        write_file(out_path("cut_late.vtk"), d, len - 1000);
        expect_bad(out_path("cut_late.vtk"), NULL, NULL);
        free(d);
    }
    truncated_copy(DATA "fluid_250_particles.vtu", out_path("cut.vtu"), 3000);
    expect_bad(out_path("cut.vtu"), NULL, NULL);

    /* BGEO: the compressed stream cut half-way, and a complete gzip of a cut payload. */
    truncated_copy(DATA "dam_break_frame_9_6859_particles.bgeo", out_path("cut.bgeo"), 202771 / 2);
    expect_bad(out_path("cut.bgeo"), NULL, "gzip");
    gzFile in = gzopen(DATA "dam_break_frame_9_6859_particles.bgeo", "rb");
    unsigned char *raw = malloc(300000);
    int n = in && raw ? gzread(in, raw, 300000) : -1;
    if (in) gzclose(in);
    CHECK(n == 247028, "unzipped bgeo has %d bytes", n);
    if (n > 0) {
        gzFile out = gzopen(out_path("cut_payload.bgeo.gz"), "wb");
        gzwrite(out, raw, (unsigned)n / 2);
        gzclose(out);
        expect_bad(out_path("cut_payload.bgeo.gz"), NULL, "truncated");
    }
    free(raw);

    /* PLY: write the frame as binary PLY, then cut it half-way through the vertex data. */
    fs_particles p;
    if (fs_particles_read(&p, DATA "dam_break_frame_9_6859_particles.bgeo", NULL) == FS_OK) {
        CHECK(fs_particles_write(&p, out_path("whole.ply"), NULL) == FS_OK, "%s", fs_error_message());
        size_t body = p.n * 24; /* x y z vx vy vz floats */
        d = load(out_path("whole.ply"), &len);
        if (d) {
            write_file(out_path("cut.ply"), d, len - body / 2);
            expect_bad(out_path("cut.ply"), NULL, "truncated");
            free(d);
        }
        fs_particles_free(&p);
    } else {
        CHECK(0, "%s", fs_error_message());
    }
    const char *ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nend_header\n1 2 3\n4 5 6\n7 8";
    write_file(out_path("cut_ascii.ply"), ascii, strlen(ascii));
    expect_bad(out_path("cut_ascii.ply"), NULL, NULL);
}

static void test_wrong_magic_and_garbage(void)
{
    /* Each data file with its first bytes overwritten. */
    const char *srcs[] = {"cube_2366_particles.vtk", "fluid_250_particles.vtu",
                          "dam_break_frame_9_6859_particles.bgeo"};
    const char *dsts[] = {"magic.vtk", "magic.vtu", "magic.bgeo"};
    for (int i = 0; i < 3; i++) {
        char src[512];
        snprintf(src, sizeof src, "%s%s", DATA, srcs[i]);
        size_t len;
        unsigned char *d = load(src, &len);
        if (!d) continue;
        memcpy(d, "JUNK", 4);
        write_file(out_path(dsts[i]), d, len);
        expect_bad(out_path(dsts[i]), NULL, NULL);
        free(d);
    }
    write_file(out_path("magic.ply"), "plx\nformat ascii 1.0\n", 21);
    expect_bad(out_path("magic.ply"), NULL, "magic");
    unsigned char noise[4096];
    uint32_t s = 12345;
    for (size_t i = 0; i < sizeof noise; i++) {
        s = s * 1664525u + 1013904223u;
        noise[i] = (unsigned char)(s >> 24);
    }
    write_file(out_path("noise.vdb"), noise, sizeof noise);
    expect_bad(out_path("noise.vdb"), NULL, NULL);
    write_file(out_path("noise.vtu"), noise, sizeof noise);
    expect_bad(out_path("noise.vtu"), NULL, NULL);
    /* A legacy header followed by garbage where the points should be. */
    char garbage[4096 + 200];
    int h = snprintf(garbage, 200,
                     "# vtk DataFile Version 4.1\nbad\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 100 float\n");
    memcpy(garbage + h, noise, 1200);
    memcpy(garbage + h + 1200, "\nCELLS 100 junk\n", 16);
    memcpy(garbage + h + 1216, noise + 1200, 800);
    write_file(out_path("garbage.vtk"), garbage, (size_t)h + 2016);
    expect_bad(out_path("garbage.vtk"), NULL, NULL);
    const char *noheader = "# vtk DataFile Version 4.1\nbad\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS lots float\n";
    write_file(out_path("badcount.vtk"), noheader, strlen(noheader));
    expect_bad(out_path("badcount.vtk"), NULL, NULL);

    /* BGEO: unknown attribute type, a point count the file cannot hold, wrong version. */
    unsigned char b[256];
    size_t len = bgeo_header(b, 2, 9);
    write_file(out_path("badtype.bgeo"), b, len + 64);
    expect_bad(out_path("badtype.bgeo"), NULL, "unknown type");
    len = bgeo_header(b, 0x7fffffff, 5);
    write_file(out_path("hugecount.bgeo"), b, len + 64);
    expect_bad(out_path("hugecount.bgeo"), NULL, "truncated");
    len = bgeo_header(b, 1, 5);
    b[8] = 4; /* version 4 */
    write_file(out_path("version.bgeo"), b, len + 28);
    expect_bad(out_path("version.bgeo"), NULL, "version");

    const char *ply = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n0123456789ab";
    write_file(out_path("hugecount.ply"), ply, strlen(ply));
    expect_bad(out_path("hugecount.ply"), NULL, "truncated");
    const char *noxyz =
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n";
    write_file(out_path("noxyz.ply"), noxyz, strlen(noxyz));
    expect_bad(out_path("noxyz.ply"), NULL, "x, y or z");
    write_file(out_path("odd.raw"), noise, 13);
    expect_bad(out_path("odd.raw"), NULL, "multiple of 12");
    const char *csv = "x,y,z\n1,2,3\n4,five,6\n";
    write_file(out_path("badnum.csv"), csv, strlen(csv));
    expect_bad(out_path("badnum.csv"), NULL, "line 3");
}

static void test_non_finite_and_zero(void)
{
    const char *nan_ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nend_header\n1 2 3\n4 nan 6\n7 8 9\n";
    write_file(out_path("nan.ply"), nan_ply, strlen(nan_ply));
    expect_bad(out_path("nan.ply"), NULL, "particle 1 has a non-finite position");
    float inf_raw[6] = {1, 2, 3, 4, 5, 0};
    inf_raw[5] = INFINITY;
    write_file(out_path("inf.raw"), inf_raw, sizeof inf_raw); /* the test host is little endian */
    expect_bad(out_path("inf.raw"), NULL, "particle 1 has a non-finite position");
    const char *inf_csv = "x y z\n-inf 0 0\n";
    write_file(out_path("inf.csv"), inf_csv, strlen(inf_csv));
    expect_bad(out_path("inf.csv"), NULL, "particle 0 has a non-finite position");

    const char *zero_ply = "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n"
                           "property float y\nproperty float z\nend_header\n";
    write_file(out_path("zero.ply"), zero_ply, strlen(zero_ply));
    expect_bad(out_path("zero.ply"), NULL, "no particles");
    unsigned char b[256];
    size_t len = bgeo_header(b, 0, 5);
    b[len++] = 0;
    b[len++] = 0xff;
    write_file(out_path("zero.bgeo"), b, len);
    expect_bad(out_path("zero.bgeo"), NULL, "no particles");
    const char *zero_vtk = "# vtk DataFile Version 4.1\nnone\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 0 float\n"
                           "CELLS 0 0\nCELL_TYPES 0\n";
    write_file(out_path("zero.vtk"), zero_vtk, strlen(zero_vtk));
    expect_bad(out_path("zero.vtk"), NULL, NULL);
    write_file(out_path("zero.csv"), "x,y,z\n", 6);
    expect_bad(out_path("zero.csv"), NULL, "no particles");
}

int main(void)
{
    test_missing_empty_unknown();
    test_truncated();
    test_wrong_magic_and_garbage();
    test_non_finite_and_zero();
    TEST_DONE();
}
