/* Image files (PNG through stb, EXR through OpenEXRCore, in every build): EXR
 * with AOV channels and attributes, sRGB PNG, safe writes and errors, how a
 * G-buffer EXR marks empty depth; and the golden-image helper itself. */
#include "fs_error.h"
#include "fs_test.h"
#include "golden.h"
#include "image_io.h"
#include "render_output.h"
#include <dirent.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *AOV_NAMES[] = {"R",        "G",        "B",        "A",         "depth",
                                  "normal.X", "normal.Y", "normal.Z", "thickness", "coverage"};
enum { AOV_N = 10 };

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Any leftover temporary file (".NAME.tmpXXXXXX") of the given target name in dir. */
static int temp_files_left(const char *dir, const char *name)
{
    char prefix[256];
    snprintf(prefix, sizeof prefix, ".%s.tmp", name);
    DIR *d = opendir(dir);
    int found = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        if (strncmp(e->d_name, prefix, strlen(prefix)) == 0) found++;
    if (d) closedir(d);
    return found;
}

static unsigned long long file_hash(const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned long long h = 14695981039346656037ULL; /* FNV-1a */
    if (!f) return 0;
    for (int c; (c = fgetc(f)) != EOF;) h = (h ^ (unsigned)c) * 1099511628211ULL;
    fclose(f);
    return h;
}

static void test_exr_roundtrip(void)
{
    const int w = 13, h = 7;
    float *pix = malloc(sizeof(float) * w * h * AOV_N);
    unsigned s = 12345;
    for (int i = 0; i < w * h * AOV_N; i++) {
        s = s * 1664525u + 1013904223u;
        pix[i] = ((s >> 8) / 16777216.0f - 0.3f) * 7.0f; /* negative, fractional, beyond 1 */
    }
    for (int i = 0; i < w * h; i += 3) pix[i * AOV_N + 4] = INFINITY; /* empty pixels' depth */
    pix[5 * AOV_N + 8] = 1e-30f;
    fs_image img = {w, h, AOV_N, AOV_NAMES, pix};
    fs_attr attrs[] = {{"fluidsurf:version", "0.1.0 (abc123)"}, {"fluidsurf:camera", "eye 1 2 3; fovy 40"}};
    const char *path = FS_TEST_OUT "/image_io_aov.exr";
    unlink(path);
    CHECK(fs_write_exr(path, &img, attrs, 2) == FS_OK, "write exr: %s", fs_error_message());
    CHECK(temp_files_left(FS_TEST_OUT, "image_io_aov.exr") == 0, "temporary EXR left behind");

    fs_image back;
    int rc = fs_read_image(path, &back);
    CHECK(rc == FS_OK, "read exr: %s", fs_error_message());
    if (rc != FS_OK) {
        free(pix);
        return;
    }
    CHECK(back.w == w && back.h == h && back.nch == AOV_N, "exr shape %dx%dx%d", back.w, back.h, back.nch);
    for (int c = 0; c < AOV_N && back.nch == AOV_N; c++) {
        int bc = fs_image_channel(&back, AOV_NAMES[c]);
        CHECK(bc >= 0, "channel %s missing after reading", AOV_NAMES[c]);
        if (bc < 0) continue;
        int differ = 0;
        for (int i = 0; i < w * h; i++)
            differ += memcmp(&pix[i * AOV_N + c], &back.pix[i * AOV_N + bc], sizeof(float)) != 0;
        CHECK(differ == 0, "channel %s: %d pixels differ from what was written", AOV_NAMES[c], differ);
    }
    CHECK(fs_image_channel(&back, "nope") == -1, "unknown channel found");
    fs_image_free(&back);
    CHECK(back.pix == NULL && back.chnames == NULL, "fs_image_free leaves pointers");

    char buf[64];
    CHECK(fs_read_image_attr(path, "fluidsurf:version", buf, sizeof buf) == 1 && strcmp(buf, attrs[0].value) == 0,
          "version attribute: '%s'", buf);
    CHECK(fs_read_image_attr(path, "fluidsurf:camera", buf, sizeof buf) == 1 && strcmp(buf, attrs[1].value) == 0,
          "camera attribute: '%s'", buf);
    CHECK(fs_read_image_attr(path, "compression", buf, sizeof buf) == 1 && strcmp(buf, "zip") == 0, "compression: '%s'",
          buf);
    CHECK(fs_read_image_attr(path, "fluidsurf:absent", buf, sizeof buf) == 0 && buf[0] == 0, "absent attribute found");
    char small[5];
    CHECK(fs_read_image_attr(path, "fluidsurf:version", small, sizeof small) == 1 && strcmp(small, "0.1.") == 0,
          "truncated attribute: '%s'", small);
    free(pix);
}

static void test_srgb(void)
{
    for (int k = 0; k < 256; k++)
        CHECK(fs_srgb_encode8(fs_srgb_decode8((unsigned char)k)) == k, "sRGB code %d does not round-trip", k);
    CHECK(fs_srgb_encode8(-1.0f) == 0 && fs_srgb_encode8(NAN) == 0 && fs_srgb_encode8(7.0f) == 255, "sRGB clamping");
    /* The linear segment near black and the power segment above it. */
    CHECK(fs_srgb_encode8(0.002f) == (int)(0.002 * 12.92 * 255 + 0.5), "sRGB linear segment");
    CHECK_NEAR(fs_srgb_decode8(188), pow((188 / 255.0 + 0.055) / 1.055, 2.4), 1e-6, "sRGB decode");
}

static double srgb_exact(double v)
{
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1 / 2.4) - 0.055;
}

static void test_png_roundtrip(void)
{
    const int w = 16, h = 12;
    float *pix = malloc(sizeof(float) * 4 * w * h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float *p = pix + 4 * (y * w + x);
            p[0] = x / (w - 1.0f);
            p[1] = (y / (h - 1.0f)) * (y / (h - 1.0f));
            p[2] = 1.3f - x / 7.0f; /* runs out of [0,1]: clamped */
            p[3] = (x + y) / (float)(w + h - 2);
        }
    static const char *names[] = {"R", "G", "B", "A"};
    fs_image img = {w, h, 4, names, pix};
    const char *path = FS_TEST_OUT "/image_io_rgba.png";
    CHECK(fs_write_png(path, &img) == FS_OK, "write png: %s", fs_error_message());
    fs_image back;
    int rc = fs_read_image(path, &back);
    CHECK(rc == FS_OK, "read png: %s", fs_error_message());
    if (rc == FS_OK) {
        CHECK(back.w == w && back.h == h && back.nch == 4, "png shape %dx%dx%d", back.w, back.h, back.nch);
        double worst = 0, worst_lin = 0;
        int code_mismatch = 0;
        for (int i = 0; i < w * h && back.nch == 4; i++)
            for (int c = 0; c < 4; c++) {
                double v = pix[4 * i + c], vc = v < 0 ? 0 : v > 1 ? 1 : v;
                double expect = c < 3 ? srgb_exact(v) : vc;
                worst = fmax(worst, fabs(back.pix[4 * i + c] - expect));
                if (c < 3) {
                    int code = (int)lrintf(back.pix[4 * i + c] * 255);
                    code_mismatch += code != fs_srgb_encode8(pix[4 * i + c]);
                    worst_lin = fmax(worst_lin, fabs(fs_srgb_decode8((unsigned char)code) - vc));
                }
            }
        CHECK(worst <= 0.5 / 255 + 1e-6, "PNG off by %g codes after sRGB encoding", worst * 255);
        CHECK(code_mismatch == 0, "%d PNG values differ from fs_srgb_encode8", code_mismatch);
        /* Half the largest sRGB code step in linear (at white) is 1.14/255. */
        CHECK(worst_lin <= 1.15 / 255, "decoded PNG off by %g/255 in linear", worst_lin * 255);
        fs_image_free(&back);
    }
    /* Three channels: no alpha channel in the file. */
    float rgb[3 * 4] = {0, 0.5f, 1, 0.2f, 0.2f, 0.2f, 1, 1, 1, 0, 0, 0};
    fs_image img3 = {2, 2, 3, names, rgb};
    const char *path3 = FS_TEST_OUT "/image_io_rgb.png";
    CHECK(fs_write_png(path3, &img3) == FS_OK, "write rgb png: %s", fs_error_message());
    rc = fs_read_image(path3, &back);
    CHECK(rc == FS_OK, "read rgb png: %s", fs_error_message());
    if (rc == FS_OK) {
        CHECK(back.nch == 3, "rgb png has %d channels", back.nch);
        CHECK_NEAR(back.pix[1] * 255, fs_srgb_encode8(0.5f), 1e-3, "rgb png green");
        fs_image_free(&back);
    }
    free(pix);
}

static void test_errors(void)
{
    float px[4] = {0.1f, 0.2f, 0.3f, 1};
    static const char *names[] = {"R", "G", "B", "A"};
    fs_image img = {1, 1, 4, names, px};
    const char *missing_dir = FS_TEST_OUT "/image_io_no_such_dir";
    rmdir(missing_dir);
    int rc = fs_write_exr(FS_TEST_OUT "/image_io_no_such_dir/x.exr", &img, NULL, 0);
    CHECK(rc == FS_ERR_INPUT, "exr into a missing folder: rc %d", rc);
    CHECK(strncmp(fs_error_message(), missing_dir, strlen(missing_dir)) == 0, "message: %s", fs_error_message());
    rc = fs_write_png(FS_TEST_OUT "/image_io_no_such_dir/x.png", &img);
    CHECK(rc == FS_ERR_INPUT, "png into a missing folder: rc %d", rc);
    CHECK(!exists(missing_dir), "writing created the missing folder");
    CHECK(!strchr(fs_error_message(), '\n'), "error message spans lines");

    /* A write that fails must leave the existing file as it was, and no temporary. */
    const char *keep = FS_TEST_OUT "/image_io_keep.png";
    CHECK(fs_write_png(keep, &img) == FS_OK, "write png: %s", fs_error_message());
    unsigned long long before = file_hash(keep);
    /* libpng refuses widths above 1,000,000: a failure inside OpenImageIO itself. */
    int wide = 1000001;
    unsigned char *row = calloc(wide, 1);
    rc = fs_write_png8(keep, row, wide, 1, 1);
    CHECK(rc == FS_ERR_RUNTIME, "a %d-pixel-wide PNG was written", wide);
    printf("expected error: %s\n", fs_error_message());
    CHECK(strncmp(fs_error_message(), keep, strlen(keep)) == 0 && !strchr(fs_error_message(), '\n'), "message: %s",
          fs_error_message());
    free(row);
    fs_image empty = {1, 1, 4, names, NULL};
    CHECK(fs_write_png(keep, &empty) == FS_ERR_INPUT, "png without pixels accepted");
    CHECK(fs_write_exr(keep, &empty, NULL, 0) == FS_ERR_INPUT, "exr without pixels accepted");
    CHECK(file_hash(keep) == before, "a failed write changed the existing file");
    CHECK(temp_files_left(FS_TEST_OUT, "image_io_keep.png") == 0, "temporary file left behind");

    /* Reading: a missing file and a file that is no image. */
    fs_image back;
    const char *nofile = FS_TEST_OUT "/image_io_missing.exr";
    unlink(nofile);
    CHECK(fs_read_image(nofile, &back) == FS_ERR_INPUT, "missing file read");
    CHECK(strncmp(fs_error_message(), nofile, strlen(nofile)) == 0 && !strchr(fs_error_message(), '\n'), "message: %s",
          fs_error_message());
    const char *junk = FS_TEST_OUT "/image_io_junk.exr";
    FILE *f = fopen(junk, "w");
    if (f) {
        fputs("not an image at all\n", f);
        fclose(f);
    }
    CHECK(fs_read_image(junk, &back) == FS_ERR_INPUT, "junk file read as an image");
    CHECK(back.pix == NULL && back.chnames == NULL, "failed read left pointers");
    char buf[16];
    CHECK(fs_read_image_attr(nofile, "x", buf, sizeof buf) == -1, "attribute of a missing file");
    /* A folder is bad input, not an image (nor, in the lean build, an "empty file"). */
    CHECK(fs_read_image(FS_TEST_OUT, &back) == FS_ERR_INPUT, "a folder read as an image");
    printf("expected error: %s\n", fs_error_message());
    CHECK(back.pix == NULL && !strchr(fs_error_message(), '\n'), "folder read: %s", fs_error_message());
#if !FS_WITH_OIIO
    CHECK(strstr(fs_error_message(), ": is a folder") != NULL, "folder read: %s", fs_error_message());

    /* stb sizes (w*nch + 1) * h in int: refused before any pixel is read (the buffer is one byte). */
    unsigned char one = 0;
    rc = fs_write_png8(keep, &one, 30000, 30000, 4);
    CHECK(rc == FS_ERR_INPUT, "a 30000x30000 RGBA PNG: rc %d", rc);
    printf("expected error: %s\n", fs_error_message());
    CHECK(strncmp(fs_error_message(), keep, strlen(keep)) == 0 && !strchr(fs_error_message(), '\n') &&
              strstr(fs_error_message(), "too large"),
          "message: %s", fs_error_message());
    CHECK(file_hash(keep) == before, "a refused write changed the existing file");

    /* An EXR whose header claims a huge data window: bad input, refused before allocating. */
    const char *huge = FS_TEST_OUT "/image_io_huge_window.exr";
    CHECK(fs_write_exr(huge, &img, NULL, 0) == FS_OK, "write exr: %s", fs_error_message());
    f = fopen(huge, "r+b");
    unsigned char hdr[4096];
    size_t got = f ? fread(hdr, 1, sizeof hdr, f) : 0;
    static const char key[] = "dataWindow\0box2i"; /* then size 16 and xmin, ymin, xmax, ymax */
    long at = -1;
    for (size_t i = 0; i + sizeof key + 20 <= got && at < 0; i++)
        if (!memcmp(hdr + i, key, sizeof key)) at = (long)(i + sizeof key + 4);
    CHECK(at > 0, "no dataWindow attribute in the written EXR");
    if (f && at > 0) {
        const int32_t max[2] = {999999, 999999}; /* 10^12 pixels, little-endian as EXR stores them */
        fseek(f, at + 8, SEEK_SET);
        fwrite(max, sizeof max, 1, f);
    }
    if (f) fclose(f);
    rc = fs_read_image(huge, &back);
    printf("expected error: %s\n", fs_error_message());
    CHECK(rc == FS_ERR_INPUT && strstr(fs_error_message(), "1000000x1000000 is too large"),
          "huge data window: rc %d, %s", rc, fs_error_message());
    CHECK(back.pix == NULL, "failed read left pointers");
#endif
}

/* A deterministic test pattern, linear RGBA. */
static void pattern(float *rgba, int w, int h)
{
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float *p = rgba + 4 * (y * w + x);
            p[0] = x / (float)w;
            p[1] = y / (float)h;
            p[2] = ((x / 8 + y / 8) & 1) ? 0.8f : 0.1f;
            p[3] = 1;
        }
}

static void test_golden(void)
{
    const int w = 64, h = 48;
    char dir[512], ref[600], out[600], diff[600];
    snprintf(dir, sizeof dir, "%s/golden-selftest", FS_TEST_OUT);
    snprintf(ref, sizeof ref, "%s/image_io_selftest.png", dir);
    snprintf(out, sizeof out, "%s/image_io_selftest.out.png", FS_TEST_OUT);
    snprintf(diff, sizeof diff, "%s/image_io_selftest.diff.png", FS_TEST_OUT);
    setenv("FS_GOLDEN_DIR", dir, 1);
    unsetenv("FS_UPDATE_GOLDEN");
    unlink(ref);
    unlink(out);
    unlink(diff);
    float *img = malloc(sizeof(float) * 4 * w * h), *changed = malloc(sizeof(float) * 4 * w * h);
    pattern(img, w, h);

    CHECK(fs_golden_check("image_io_selftest", img, w, h, 0.5, 0.001) != 0, "a missing reference passed");
    CHECK(exists(ref), "the missing reference was not created");
    CHECK(fs_golden_check("image_io_selftest", img, w, h, 0.0, 0.0) == 0, "identical image failed");
    CHECK(!exists(out) && !exists(diff), "a passing check wrote failure images");

    /* A 10x10 block changed strongly: 100 of 3072 pixels. */
    memcpy(changed, img, sizeof(float) * 4 * w * h);
    for (int y = 20; y < 30; y++)
        for (int x = 30; x < 40; x++) changed[4 * (y * w + x) + 1] += 0.5f;
    CHECK(fs_golden_check("image_io_selftest", changed, w, h, 100.0, 0.01) != 0, "changed image passed");
    CHECK(exists(out) && exists(diff), "failure images not written");
    fs_image d;
    int rc = fs_read_image(diff, &d);
    CHECK(rc == FS_OK, "read diff image: %s", fs_error_message());
    if (rc == FS_OK) {
        int inside = 0, outside = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                int lit = d.pix[d.nch * (y * w + x) + 1] > 0;
                if (x >= 30 && x < 40 && y >= 20 && y < 30) inside += lit;
                else outside += lit;
            }
        CHECK(inside == 100 && outside == 0, "diff image marks %d inside, %d outside", inside, outside);
        fs_image_free(&d);
    }
    /* The same change within both tolerances passes; the mean alone can fail it. */
    CHECK(fs_golden_check("image_io_selftest", changed, w, h, 100.0, 0.05) == 0, "tolerated change failed");
    CHECK(fs_golden_check("image_io_selftest", changed, w, h, 0.1, 0.05) != 0, "mean threshold ignored");

    /* Size mismatch fails. */
    CHECK(fs_golden_check("image_io_selftest", img, w, h - 1, 1e9, 1.0) != 0, "size mismatch passed");

    /* FS_UPDATE_GOLDEN=1 replaces the reference and passes. */
    setenv("FS_UPDATE_GOLDEN", "1", 1);
    CHECK(fs_golden_check("image_io_selftest", changed, w, h, 0.0, 0.0) == 0, "update failed");
    unsetenv("FS_UPDATE_GOLDEN");
    CHECK(fs_golden_check("image_io_selftest", changed, w, h, 0.0, 0.0) == 0, "updated reference differs");
    CHECK(fs_golden_check("image_io_selftest", img, w, h, 0.5, 0.001) != 0, "old image passed the new reference");
    unsetenv("FS_GOLDEN_DIR");
    free(img);
    free(changed);
}

/* Every other pixel of a 4x3 G-buffer covered, depth 1 + 0.1 i there. */
static void empty_depth_gbuffer(fs_gbuffer *g)
{
    CHECK(fs_gbuffer_alloc(g, 4, 3) == FS_OK, "gbuffer: %s", fs_error_message());
    fs_gbuffer_clear(g);
    for (int i = 1; i < 12; i += 2) {
        g->coverage[i] = 1;
        g->depth[i] = 1 + 0.1f * i;
        g->normal[3 * i + 2] = 1;
    }
}

/* What fs_read_render gives back for path: infinity where empty, the depth where covered. */
static void check_read_depth(const char *path, const fs_gbuffer *want, const char *what)
{
    fs_gbuffer g;
    float *rgba = NULL, r = 0;
    CHECK(fs_read_render(path, &g, &rgba, &r) == FS_OK, "%s: read: %s", what, fs_error_message());
    int bad = 0;
    for (int i = 0; i < 12 && g.depth; i++)
        bad += want->coverage[i] ? g.depth[i] != want->depth[i] : !(isinf(g.depth[i]) && g.depth[i] > 0);
    CHECK(g.depth && bad == 0, "%s: %d pixels' depth read back wrong", what, bad);
    fs_gbuffer_free(&g);
    free(rgba);
}

/* fs_write_render writes empty depth as FS_EXR_EMPTY_DEPTH (0, so that idiff's
 * means stay finite) and says so in fluidsurf:empty_depth; fs_read_render turns
 * that, the infinity of older files, and NaN into infinity. */
static void test_empty_depth(void)
{
    fs_gbuffer g;
    empty_depth_gbuffer(&g);
    float rgba[4 * 12] = {0};
    fs_provenance prov;
    fs_provenance_init_base(&prov, NULL, "none");
    const char *path = FS_TEST_OUT "/image_io_empty_depth.exr";
    CHECK(fs_write_render(path, &g, rgba, &prov) == FS_OK, "write: %s", fs_error_message());
    fs_image raw;
    CHECK(fs_read_image(path, &raw) == FS_OK, "read raw: %s", fs_error_message());
    int dc = fs_image_channel(&raw, "depth"), nonfinite = 0, bad = 0;
    for (int i = 0; i < 12 * raw.nch; i++) nonfinite += !isfinite(raw.pix[i]);
    for (int i = 0; i < 12 && dc >= 0; i++) bad += raw.pix[i * raw.nch + dc] != (g.coverage[i] ? g.depth[i] : 0.0f);
    CHECK(dc >= 0 && nonfinite == 0 && bad == 0, "the file holds %d non-finite values, %d depths not 0 where empty",
          nonfinite, bad);
    fs_image_free(&raw);
    char buf[16];
    CHECK(fs_read_image_attr(path, "fluidsurf:empty_depth", buf, sizeof buf) == 1 && !strcmp(buf, "0"),
          "fluidsurf:empty_depth '%s'", buf);
    check_read_depth(path, &g, "empty depth 0");
    /* files that marked it otherwise: infinity (before fluidsurf:empty_depth), NaN */
    const float marks[2] = {INFINITY, NAN};
    const char *names[2] = {"empty depth inf (older files)", "empty depth NaN"};
    for (int m = 0; m < 2; m++) {
        float pix[12 * AOV_N] = {0};
        for (int i = 0; i < 12; i++) {
            pix[i * AOV_N + 4] = g.coverage[i] ? g.depth[i] : marks[m];
            pix[i * AOV_N + 7] = g.normal[3 * i + 2];
            pix[i * AOV_N + 9] = g.coverage[i];
        }
        fs_image img = {4, 3, AOV_N, AOV_NAMES, pix};
        CHECK(fs_write_exr(path, &img, NULL, 0) == FS_OK, "write: %s", fs_error_message());
        check_read_depth(path, &g, names[m]);
    }
    fs_gbuffer_free(&g);
}

int main(void)
{
    test_exr_roundtrip();
    test_empty_depth();
    test_srgb();
    test_png_roundtrip();
    test_errors();
    test_golden();
    TEST_DONE();
}
