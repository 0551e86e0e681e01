/* Readers: every bundled splashsurf file loads with the count and bounding box
 * of its README; small hand-made PLY (ascii / big endian), CSV and raw files;
 * format detection and frame patterns. */
#include "fs_error.h"
#include "fs_test.h"
#include "particle_io.h"
#include <stdint.h>
#include <string.h>

#define DATA FS_TEST_DATA "/splashsurf/"

static void write_file(const char *path, const void *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL, "cannot create %s", path);
    if (!f) return;
    fwrite(data, 1, len, f);
    fclose(f);
}

static double max_speed(const fs_particles *p)
{
    double m = 0;
    for (size_t i = 0; i < p->n; i++) {
        double s = sqrt((double)p->vx[i] * p->vx[i] + (double)p->vy[i] * p->vy[i] + (double)p->vz[i] * p->vz[i]);
        if (s > m) m = s;
    }
    return m;
}

/* Values from experiments/data/splashsurf/README.md (measured independently there). */
static void check_data_file(const char *name, size_t n, const float lo[3], const float hi[3], int velocity,
                            double speed_max)
{
    char path[512];
    snprintf(path, sizeof path, "%s%s", DATA, name);
    fs_particles p;
    int rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "%s: %s", name, fs_error_message());
    if (rc) return;
    CHECK(p.n == n, "%s: %zu particles, expected %zu", name, p.n, n);
    for (int k = 0; k < 3; k++) {
        CHECK_NEAR(p.bmin[k], lo[k], 1e-3, name);
        CHECK_NEAR(p.bmax[k], hi[k], 1e-3, name);
    }
    CHECK(!!(fs_particles_fields(&p) & FS_HAS_VELOCITY) == velocity, "%s: velocity presence", name);
    if (velocity && speed_max > 0) CHECK_NEAR(max_speed(&p), speed_max, 0.05, name);
    if (velocity) CHECK(max_speed(&p) > 0.0, "%s: velocity is all zero", name);
    fs_particles_free(&p);
}

static void test_data_files(void)
{
    check_data_file("dam_break_frame_23_24389_particles.vtk", 24389, (float[]){-1.5133f, 0.0314f, -0.7645f},
                    (float[]){1.5161f, 3.9659f, 0.7657f}, 1, 9.0);
    check_data_file("double_dam_break_frame_01_4732_particles.vtk", 4732, (float[]){-1.45f, 0.05f, -1.45f},
                    (float[]){1.45f, 0.70f, 1.45f}, 1, 0);
    check_data_file("double_dam_break_frame_26_4732_particles.vtk", 4732, (float[]){-1.5153f, -0.0153f, -1.5151f},
                    (float[]){1.5152f, 1.0168f, 1.5152f}, 1, 3.84);
    check_data_file("cube_2366_particles.vtk", 2366, (float[]){0.85f, 0.05f, 0.85f}, (float[]){1.45f, 0.70f, 1.45f}, 0,
                    0);
    check_data_file("fluid_250_particles.vtu", 250, (float[]){0.1133f, 0.1478f, 0.1097f},
                    (float[]){5.0708f, 1.1394f, 1.0902f}, 1, 0);
    check_data_file("dam_break_frame_9_6859_particles.bgeo", 6859, (float[]){-1.9516f, 0.0357f, -0.7104f},
                    (float[]){-0.3876f, 0.6817f, 0.7109f}, 1, 0);
}

/* The same three particles in ascii, big-endian (with a face list and normals to skip) and CSV. */
static const float ref[3][3] = {{0.5f, -1.25f, 2.0f}, {1e-3f, 4.0f, -0.75f}, {3.0f, 2.5f, 1.0f}};

static void check_ref(const fs_particles *p, const char *what)
{
    CHECK(p->n == 3, "%s: %zu particles", what, p->n);
    for (size_t i = 0; i < 3 && i < p->n; i++) {
        CHECK_NEAR(p->x[i], ref[i][0], 1e-6, what);
        CHECK_NEAR(p->y[i], ref[i][1], 1e-6, what);
        CHECK_NEAR(p->z[i], ref[i][2], 1e-6, what);
    }
}

static void put_be(unsigned char **w, const void *v, int n)
{
    for (int k = 0; k < n; k++) (*w)[k] = ((const unsigned char *)v)[n - 1 - k];
    *w += n;
}

static void test_ply_variants(void)
{
    char path[512];
    fs_particles p;
    snprintf(path, sizeof path, "%s/io_ascii.ply", FS_TEST_OUT);
    const char *ascii = "ply\r\nformat ascii 1.0\r\ncomment radius 0.05\r\nelement vertex 3\r\n"
                        "property float x\r\nproperty float y\r\nproperty double z\r\nproperty float nx\r\n"
                        "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
                        "element face 0\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
                        "0.5 -1.25 2 0 255 0 51\r\n1e-3 4 -0.75 1 0 0 0\r\n3 2.5 1 0 0 0 0\r\n";
    write_file(path, ascii, strlen(ascii));
    int rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "ascii ply: %s", fs_error_message());
    if (!rc) {
        check_ref(&p, "ascii ply");
        CHECK(p.color != NULL, "ascii ply: colour missing");
        if (p.color) CHECK_NEAR(p.color[0] + p.color[1] + p.color[2], 1.2, 1e-6, "ascii ply uchar colour /255");
        CHECK_NEAR(p.radius, 0.05, 1e-7, "ascii ply radius comment");
        fs_particles_free(&p);
    }

    /* Big endian: a 2-entry "camera" element before the vertices, double z, a list property in the vertex. */
    snprintf(path, sizeof path, "%s/io_be.ply", FS_TEST_OUT);
    unsigned char buf[1024], *w = buf;
    const char *head = "ply\nformat binary_big_endian 1.0\nelement camera 2\nproperty short id\n"
                       "property list uchar float params\nelement vertex 3\nproperty float x\n"
                       "property list uchar int extra\nproperty float y\nproperty double z\n"
                       "property float vx\nproperty float vy\nproperty float vz\nend_header\n";
    memcpy(w, head, strlen(head));
    w += strlen(head);
    for (int c = 0; c < 2; c++) {
        int16_t id = (int16_t)c;
        put_be(&w, &id, 2);
        *w++ = 2; /* two params */
        float f = 1.0f;
        put_be(&w, &f, 4);
        put_be(&w, &f, 4);
    }
    for (int i = 0; i < 3; i++) {
        put_be(&w, &ref[i][0], 4);
        *w++ = (unsigned char)i; /* i list items */
        for (int k = 0; k < i; k++) {
            int32_t v = k;
            put_be(&w, &v, 4);
        }
        put_be(&w, &ref[i][1], 4);
        double z = ref[i][2];
        put_be(&w, &z, 8);
        float v[3] = {(float)i, 2.0f * (float)i, -1.0f};
        for (int k = 0; k < 3; k++) put_be(&w, &v[k], 4);
    }
    write_file(path, buf, (size_t)(w - buf));
    rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "big-endian ply: %s", fs_error_message());
    if (!rc) {
        check_ref(&p, "big-endian ply");
        CHECK(p.vx && p.vy && p.vz, "big-endian ply: velocity missing");
        if (p.vy) CHECK_NEAR(p.vy[2], 4.0, 0, "big-endian ply vy");
        if (p.vz) CHECK_NEAR(p.vz[1], -1.0, 0, "big-endian ply vz");
        fs_particles_free(&p);
    }
}

/* Legacy ASCII POLYDATA (not SPlisHSPlasH's binary UNSTRUCTURED_GRID) goes through VTK too. */
static void test_vtk_ascii_polydata(void)
{
    char path[512];
    fs_particles p;
    snprintf(path, sizeof path, "%s/io_ascii_poly.vtk", FS_TEST_OUT);
    const char *vtk = "# vtk DataFile Version 3.0\nascii points\nASCII\nDATASET POLYDATA\nPOINTS 3 double\n"
                      "0.5 -1.25 2\n0.001 4 -0.75\n3 2.5 1\nVERTICES 3 6\n1 0\n1 1\n1 2\n"
                      "POINT_DATA 3\nSCALARS density float 1\nLOOKUP_TABLE default\n1 1 1\n"
                      "VECTORS Velocity float\n1 2 3\n4 5 6\n7 8 9\n";
    write_file(path, vtk, strlen(vtk));
    int rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "ascii polydata vtk: %s", fs_error_message());
    if (!rc) {
        check_ref(&p, "ascii polydata vtk");
        CHECK(p.vx != NULL, "ascii polydata vtk: velocity missing");
        if (p.vx) CHECK(p.vx[1] == 4 && p.vz[2] == 9, "ascii polydata vtk: velocity values");
        fs_particles_free(&p);
    }
}

static void test_csv_raw(void)
{
    char path[512];
    fs_particles p;
    snprintf(path, sizeof path, "%s/io_header.csv", FS_TEST_OUT);
    const char *csv = "# a comment line\nid, Z, y, x, vx, vy, vz, phase\n"
                      "7, 2, -1.25, 0.5, 1, 2, 3, 4\n8, -0.75, 4, 0.001, 0, 0, 0, 5\n\n9, 1, 2.5, 3, 0, 0, 0, 6\n";
    write_file(path, csv, strlen(csv));
    int rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "csv with header: %s", fs_error_message());
    if (!rc) {
        check_ref(&p, "csv with header");
        CHECK(p.vx && p.phase, "csv: velocity or phase missing");
        if (p.vz) CHECK_NEAR(p.vz[0], 3, 0, "csv vz by name");
        if (p.phase) CHECK(p.phase[2] == 6, "csv phase %d", p.phase[2]);
        CHECK(!p.color, "csv: no colour columns, yet colour");
        fs_particles_free(&p);
    }

    snprintf(path, sizeof path, "%s/io_plain.txt", FS_TEST_OUT);
    const char *plain = "0.5 -1.25 2 9\n0.001\t4 -0.75 9\r\n3 2.5 1 9";
    write_file(path, plain, strlen(plain));
    rc = fs_particles_read(&p, path, "csv");
    CHECK(rc == FS_OK, "csv without header, forced format: %s", fs_error_message());
    if (!rc) {
        check_ref(&p, "csv without header");
        fs_particles_free(&p);
    }

    snprintf(path, sizeof path, "%s/io_points.xyz", FS_TEST_OUT);
    unsigned char raw[36];
    for (int i = 0; i < 9; i++) {
        uint32_t u;
        memcpy(&u, &ref[i / 3][i % 3], 4);
        for (int k = 0; k < 4; k++) raw[4 * i + k] = (unsigned char)(u >> (8 * k));
    }
    write_file(path, raw, sizeof raw);
    rc = fs_particles_read(&p, path, NULL);
    CHECK(rc == FS_OK, "raw xyz: %s", fs_error_message());
    if (!rc) {
        check_ref(&p, "raw xyz");
        fs_particles_free(&p);
    }
}

static void test_formats_and_frames(void)
{
    struct {
        const char *path, *format;
    } cases[] = {
        {"a/b.vtk", "vtk"}, {"B.VTU", "vtu"}, {"x.bgeo", "bgeo"}, {"x.bgeo.gz", "bgeo"}, {"x.ply", "ply"},
        {"x.vdb", "vdb"},   {"x.raw", "raw"}, {"x.xyz", "raw"},   {"x.csv", "csv"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *f = fs_format_from_path(cases[i].path);
        CHECK(f && strcmp(f, cases[i].format) == 0, "%s -> %s", cases[i].path, f ? f : "NULL");
    }
    CHECK(fs_format_from_path("x.gz") == NULL, "x.gz has no particle format");
    CHECK(fs_format_from_path("vtk") == NULL, "a bare name has no format");

    char out[64];
    CHECK(fs_frame_path(out, sizeof out, "out/frame_%04d.vtk", 7) == FS_OK && strcmp(out, "out/frame_0007.vtk") == 0,
          "%%04d gave %s", out);
    CHECK(fs_frame_path(out, sizeof out, "100%%_%d.ply", 12) == FS_OK && strcmp(out, "100%_12.ply") == 0,
          "%%%% literal gave %s", out);
    const char *bad[] = {"frame.vtk", "f_%d_%d.vtk", "f_%s.vtk", "f_%ld.vtk", "f_%f.vtk", "f_%", "f_%5"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int rc = fs_frame_path(out, sizeof out, bad[i], 1);
        CHECK(rc == FS_ERR_INPUT, "pattern %s accepted", bad[i]);
        CHECK(strncmp(fs_error_message(), bad[i], strlen(bad[i])) == 0, "message: %s", fs_error_message());
    }
    CHECK(fs_frame_path(out, 8, "long_name_%06d.vtk", 1) == FS_ERR_INPUT, "over-long frame path accepted");
}

static void test_particles_basics(void)
{
    fs_particles p;
    CHECK(fs_particles_alloc(&p, 4, FS_HAS_COLOR | FS_HAS_PHASE) == FS_OK, "alloc");
    CHECK(fs_particles_fields(&p) == (FS_HAS_COLOR | FS_HAS_PHASE), "fields %u", fs_particles_fields(&p));
    CHECK(p.vx == NULL && p.x[3] == 0.0f && p.color[11] == 0.0f, "zero-filled, no velocity");
    for (int i = 0; i < 4; i++) {
        p.x[i] = (float)i;
        p.y[i] = -(float)i;
        p.z[i] = 2.0f;
    }
    fs_particles_bounds(&p);
    CHECK(p.bmin[0] == 0 && p.bmax[0] == 3 && p.bmin[1] == -3 && p.bmax[1] == 0 && p.bmin[2] == 2, "bounds");
    CHECK(fs_particles_validate(&p, "mem") == FS_OK, "valid set rejected: %s", fs_error_message());
    p.z[2] = INFINITY;
    CHECK(fs_particles_validate(&p, "mem") == FS_ERR_INPUT, "infinite position accepted");
    CHECK(strcmp(fs_error_message(), "mem: particle 2 has a non-finite position") == 0, "%s", fs_error_message());
    fs_particles_free(&p);
    CHECK(p.x == NULL && p.n == 0, "free clears the struct");
    fs_particles_free(&p); /* twice is harmless */
}

int main(void)
{
    test_data_files();
    test_ply_variants();
    test_vtk_ascii_polydata();
    test_csv_raw();
    test_formats_and_frames();
    test_particles_basics();
    TEST_DONE();
}
