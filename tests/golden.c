#include "golden.h"
#include "fs_error.h"
#include "image_io.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define GOLDEN_DIFF_THRESHOLD 16 /* per channel, 0..255 */
#define GOLDEN_DIFF_GAIN 8

static const char *golden_dir(void)
{
    const char *d = getenv("FS_GOLDEN_DIR");
    return d && *d ? d : FS_SOURCE_DIR "/tests/golden";
}

/* The output as the PNG would store it: sRGB colour, linear alpha, 8-bit. */
static unsigned char *encode(const float *rgba, int w, int h)
{
    size_t n = (size_t)w * h;
    unsigned char *out = malloc(4 * n);
    if (!out) return NULL;
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) out[4 * i + c] = fs_srgb_encode8(rgba[4 * i + c]);
        float a = rgba[4 * i + 3];
        a = a > 0 ? (a < 1 ? a : 1) : 0;
        out[4 * i + 3] = (unsigned char)(a * 255.0f + 0.5f);
    }
    return out;
}

/* Reference as 8-bit RGBA; gray or RGB references get the missing channels filled. */
static unsigned char *load_reference(const char *path, int *w, int *h)
{
    fs_image ref;
    if (fs_read_image(path, &ref) != FS_OK) return NULL;
    size_t n = (size_t)ref.w * ref.h;
    unsigned char *out = malloc(4 * n);
    for (size_t i = 0; out && i < n; i++) {
        const float *p = ref.pix + i * ref.nch;
        float v[4];
        if (ref.nch >= 3) {
            v[0] = p[0];
            v[1] = p[1];
            v[2] = p[2];
            v[3] = ref.nch >= 4 ? p[3] : 1.0f;
        } else {
            v[0] = v[1] = v[2] = p[0];
            v[3] = ref.nch == 2 ? p[1] : 1.0f;
        }
        for (int c = 0; c < 4; c++) out[4 * i + c] = (unsigned char)lrintf(fminf(fmaxf(v[c], 0.0f), 1.0f) * 255.0f);
    }
    *w = ref.w;
    *h = ref.h;
    fs_image_free(&ref);
    return out;
}

static int write_reference(const char *path, const unsigned char *px, int w, int h)
{
    if (mkdir(golden_dir(), 0755) != 0 && errno != EEXIST) {
        fprintf(stderr, "golden: cannot create %s: %s\n", golden_dir(), strerror(errno));
        return 1;
    }
    if (fs_write_png8(path, px, w, h, 4) != FS_OK) {
        fprintf(stderr, "golden: %s\n", fs_error_message());
        return 1;
    }
    return 0;
}

static void write_failure_images(const char *name, const unsigned char *out, const unsigned char *ref, int w, int h)
{
    char out_path[1024], diff_path[1024];
    snprintf(out_path, sizeof out_path, "%s/%s.out.png", FS_TEST_OUT, name);
    snprintf(diff_path, sizeof diff_path, "%s/%s.diff.png", FS_TEST_OUT, name);
    if (fs_write_png8(out_path, out, w, h, 4) != FS_OK) fprintf(stderr, "golden: %s\n", fs_error_message());
    else fprintf(stderr, "golden: %s: output written to %s\n", name, out_path);
    if (!ref) return;
    size_t n = (size_t)w * h;
    unsigned char *diff = malloc(3 * n);
    if (!diff) return;
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            /* Alpha differences show in every channel so they are not lost. */
            int d = abs(out[4 * i + c] - ref[4 * i + c]), da = abs(out[4 * i + 3] - ref[4 * i + 3]);
            int v = (d > da ? d : da) * GOLDEN_DIFF_GAIN;
            diff[3 * i + c] = (unsigned char)(v > 255 ? 255 : v);
        }
    if (fs_write_png8(diff_path, diff, w, h, 3) != FS_OK) fprintf(stderr, "golden: %s\n", fs_error_message());
    else fprintf(stderr, "golden: %s: difference (x%d) written to %s\n", name, GOLDEN_DIFF_GAIN, diff_path);
    free(diff);
}

int fs_golden_check(const char *name, const float *rgba_linear, int w, int h, double max_mean_abs,
                    double max_pixel_frac)
{
    char ref_path[1024];
    snprintf(ref_path, sizeof ref_path, "%s/%s.png", golden_dir(), name);
    const char *upd = getenv("FS_UPDATE_GOLDEN");
    int update = upd && strcmp(upd, "1") == 0;
    unsigned char *out = encode(rgba_linear, w, h);
    if (!out) {
        fprintf(stderr, "golden: %s: out of memory\n", name);
        return 1;
    }

    struct stat st;
    if (update || stat(ref_path, &st) != 0) {
        int existed = stat(ref_path, &st) == 0;
        int rc = write_reference(ref_path, out, w, h);
        free(out);
        if (rc) return 1;
        fprintf(stderr, "golden: %s: reference %s %s\n", name, ref_path, existed ? "re-created" : "created");
        if (!update) fprintf(stderr, "golden: %s: FAIL: no reference existed; check the new one and commit it\n", name);
        return update ? 0 : 1;
    }

    int rw = 0, rh = 0;
    unsigned char *ref = load_reference(ref_path, &rw, &rh);
    if (!ref || rw != w || rh != h) {
        if (!ref) fprintf(stderr, "golden: %s: FAIL: cannot read reference: %s\n", name, fs_error_message());
        else fprintf(stderr, "golden: %s: FAIL: reference is %dx%d, output %dx%d\n", name, rw, rh, w, h);
        write_failure_images(name, out, NULL, w, h);
        free(ref);
        free(out);
        return 1;
    }

    size_t n = (size_t)w * h, bad = 0;
    double sum = 0;
    int max_d = 0;
    for (size_t i = 0; i < n; i++) {
        int off = 0;
        for (int c = 0; c < 4; c++) {
            int d = abs(out[4 * i + c] - ref[4 * i + c]);
            sum += d;
            if (d > max_d) max_d = d;
            if (d > GOLDEN_DIFF_THRESHOLD) off = 1;
        }
        bad += off;
    }
    double mean = sum / (4.0 * n), frac = (double)bad / n;
    int fail = mean > max_mean_abs || frac > max_pixel_frac;
    fprintf(stderr, "golden: %s: %s: mean |diff| %.4f (max %.4f), pixels off by >%d: %.5f (max %.5f), largest %d\n",
            name, fail ? "FAIL" : "ok", mean, max_mean_abs, GOLDEN_DIFF_THRESHOLD, frac, max_pixel_frac, max_d);
    if (fail) write_failure_images(name, out, ref, w, h);
    free(ref);
    free(out);
    return fail;
}
