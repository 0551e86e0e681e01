/* core/hash.h and method/render_key.h: the hash does not depend on how the
 * input is split, and the key changes with every input it holds. */
#include "fs_test.h"
#include "hash.h"
#include "provenance.h" /* fs_commit */
#include "render_key.h"
#include <stdlib.h>
#include <string.h>

typedef struct toy_params {
    double a;
    int b;
} toy_params;
#define FIELD(f) FS_PARAM_FIELD(toy_params, f)
static const fs_param_def toy_defs[] = {
    {FIELD(a), FS_PARAM_FLOAT, 1.0, 0, 10, NULL, "a"},
    {FIELD(b), FS_PARAM_INT, 2, 0, 10, NULL, "b"},
};
static const fs_aov_def toy_color[] = {{"color", 4, 1}};
static const fs_method toy = {.name = "toy", .params = toy_defs, .nparams = 2, .params_size = sizeof(toy_params)};
static const fs_method toy_c = {
    .name = "toy", .params = toy_defs, .nparams = 2, .params_size = sizeof(toy_params), .aovs = toy_color, .naovs = 1};

static fs_digest digest_in_pieces(const unsigned char *d, size_t n, size_t piece)
{
    fs_hash h;
    fs_hash_init(&h);
    for (size_t i = 0; i < n; i += piece) fs_hash_bytes(&h, d + i, n - i < piece ? n - i : piece);
    return fs_hash_digest(&h);
}

static void test_hash(void)
{
    unsigned char d[1000];
    for (int i = 0; i < 1000; i++) d[i] = (unsigned char)(i * 37 + 11);
    fs_digest whole = digest_in_pieces(d, sizeof d, sizeof d);
    const size_t pieces[] = {1, 3, 7, 31, 32, 33, 64, 999};
    for (size_t k = 0; k < sizeof pieces / sizeof *pieces; k++)
        CHECK(fs_digest_equal(whole, digest_in_pieces(d, sizeof d, pieces[k])), "pieces of %zu give another digest",
              pieces[k]);
    /* every length and every single-bit change gives another digest */
    fs_digest prev = digest_in_pieces(d, 0, 1);
    for (size_t n = 1; n <= 70; n++) {
        fs_digest x = digest_in_pieces(d, n, n);
        CHECK(!fs_digest_equal(x, prev), "length %zu collides with %zu", n, n - 1);
        prev = x;
    }
    for (int bit = 0; bit < 8 * 40; bit++) {
        d[bit / 8] ^= (unsigned char)(1u << (bit % 8));
        CHECK(!fs_digest_equal(whole, digest_in_pieces(d, sizeof d, sizeof d)), "flipping bit %d keeps the digest",
              bit);
        d[bit / 8] ^= (unsigned char)(1u << (bit % 8));
    }
    unsigned char zeros[33] = {0};
    CHECK(!fs_digest_equal(digest_in_pieces(zeros, 32, 32), digest_in_pieces(zeros, 33, 33)),
          "trailing zero byte ignored");
    fs_hash a, b;
    fs_hash_init(&a);
    fs_hash_str(&a, "ab");
    fs_hash_str(&a, "c");
    fs_hash_init(&b);
    fs_hash_str(&b, "a");
    fs_hash_str(&b, "bc");
    CHECK(!fs_digest_equal(fs_hash_digest(&a), fs_hash_digest(&b)), "strings are not delimited");
    char hex[FS_DIGEST_HEX];
    fs_digest_hex(whole, hex);
    CHECK(strlen(hex) == 32 && strspn(hex, "0123456789abcdef") == 32, "hex form '%s'", hex);
}

typedef struct key_input {
    double values[2];
    fs_field f;
    fs_camera cam;
    fs_particles p;
} key_input;

static fs_digest key_of(const fs_method *m, const key_input *in)
{
    return fs_render_key(m, in->values, &in->f, &in->cam, &in->p);
}

static void test_key(void)
{
    key_input in = {{1.0, 2},
                    {0.025f, 1e-4f, FS_KERNEL_CUBIC, 0.1f, 0.6f},
                    {{1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 40, 128, 128, 0.1f, 10},
                    {0}};
    CHECK(fs_particles_alloc(&in.p, 5, FS_HAS_COLOR) == 0, "alloc");
    for (int i = 0; i < 5; i++) {
        in.p.x[i] = 0.05f * i;
        in.p.y[i] = 0.01f;
        in.p.z[i] = -0.02f * i;
    }
    fs_digest k0 = key_of(&toy, &in);
    CHECK(fs_digest_equal(k0, key_of(&toy, &in)), "the key is not reproducible");
    /* change one thing at a time, check the key changes, put it back */
#define CHANGES(field, v)                                                                                              \
    do {                                                                                                               \
        __typeof__(in.field) keep = in.field;                                                                          \
        in.field = v;                                                                                                  \
        CHECK(!fs_digest_equal(k0, key_of(&toy, &in)), "changing " #field " keeps the key");                           \
        in.field = keep;                                                                                               \
        CHECK(fs_digest_equal(k0, key_of(&toy, &in)), "restoring " #field " changes the key");                         \
    } while (0)
    CHANGES(values[0], 1.5);
    CHANGES(values[1], 3);
    CHANGES(f.r, 0.026f);
    CHANGES(f.volume, 2e-4f);
    CHANGES(f.kernel, FS_KERNEL_POLY6);
    CHANGES(f.H, 0.11f);
    CHANGES(f.iso, 0.5f);
    CHANGES(cam.eye[2], 3.001f);
    CHANGES(cam.target[0], 0.01f);
    CHANGES(cam.up[0], 0.1f);
    CHANGES(cam.fovy_deg, 41);
    CHANGES(cam.width, 127);
    CHANGES(cam.height, 129);
    CHANGES(cam.znear, 0.2f);
    CHANGES(cam.zfar, 11);
    CHANGES(p.x[4], 0.2001f);
    CHANGES(p.y[0], 0.0101f);
    CHANGES(p.z[2], -0.05f);
    CHANGES(p.n, 4);
    /* colour counts only for a method with a colour layer */
    in.p.color[0] = 0.5f;
    CHECK(fs_digest_equal(k0, key_of(&toy, &in)), "colour changed the key of a method without a colour layer");
    fs_digest kc = key_of(&toy_c, &in);
    in.p.color[0] = 0.25f;
    CHECK(!fs_digest_equal(kc, key_of(&toy_c, &in)), "colour did not change the key of a method with a colour layer");
    fs_method other = toy;
    other.name = "toy2";
    CHECK(!fs_digest_equal(k0, key_of(&other, &in)), "the method's name is not in the key");
    char build[256];
    fs_render_key_build(build, sizeof build);
    CHECK(strstr(build, fs_commit) != NULL, "build '%s' lacks the commit", build);
    CHECK(!fs_dirty || strstr(build, "exe:"), "a dirty build '%s' lacks the executable's identity", build);
    fs_particles_free(&in.p);
}

int main(void)
{
    test_hash();
    test_key();
    TEST_DONE();
}
