/* report/gbuffer_cache.h with real EXR files: an entry comes back exactly;
 * a missing, truncated, resized, channel-less, re-keyed or altered entry is
 * never a hit; stores are atomic; an unusable folder is refused. */
#include "fs_error.h"
#include "fs_test.h"
#include "gbuffer_cache.h"
#include "image_io.h"
#include "render_output.h"
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define DIR_ FS_TEST_OUT "/gbuffer_cache/a/b" /* parents made too */

static char counts[FS_GCACHE_COUNTS]; /* the work counts an entry came back with */

static fs_digest key_n(uint64_t n)
{
    fs_hash h;
    fs_hash_init(&h);
    fs_hash_u64(&h, n);
    return fs_hash_digest(&h);
}

/* 16x8: a covered band with depth, normals, thickness, and one AOV. */
static void make_gbuffer(fs_gbuffer *g, float **rgba)
{
    CHECK(fs_gbuffer_alloc(g, 16, 8) == 0, "alloc");
    CHECK(fs_gbuffer_add_aov(g, "caustics", 1) == 0, "aov");
    *rgba = calloc(16 * 8 * 4, sizeof(float));
    for (int i = 0; i < 16 * 8; i++) {
        g->thickness[i] = 0.01f * i;
        g->aov[0].data[i] = 0.5f + i;
        (*rgba)[4 * i] = 0.25f;
        if (i % 16 < 5) continue;
        g->coverage[i] = 1;
        g->depth[i] = 1.0f + 0.001f * i;
        g->normal[3 * i + 2] = 1;
    }
}

static int same_gbuffer(const fs_gbuffer *a, const fs_gbuffer *b)
{
    size_t n = (size_t)a->w * a->h;
    if (a->w != b->w || a->h != b->h || a->naovs != b->naovs) return 0;
    int same = !memcmp(a->depth, b->depth, n * 4) && !memcmp(a->normal, b->normal, 3 * n * 4) &&
        !memcmp(a->thickness, b->thickness, n * 4) && !memcmp(a->coverage, b->coverage, n * 4);
    return same && !strcmp(a->aov[0].name, b->aov[0].name) && !memcmp(a->aov[0].data, b->aov[0].data, n * 4);
}

static int temp_files_left(const char *dir)
{
    DIR *d = opendir(dir);
    int found = 0;
    for (struct dirent *e; d && (e = readdir(d));) found += strstr(e->d_name, ".tmp") != NULL;
    if (d) closedir(d);
    return found;
}

static fs_gcache_result load(const fs_gcache *c, fs_digest k, int w, int h)
{
    fs_gbuffer g;
    fs_gcache_result r = fs_gcache_load(c, k, w, h, &g, counts, sizeof counts);
    CHECK((r == FS_GCACHE_HIT) == (g.depth != NULL), "a G-buffer comes back exactly on a hit");
    fs_gbuffer_free(&g);
    return r;
}

static void copy_file(const char *from, const char *to, long cut)
{
    FILE *a = fopen(from, "rb"), *b = fopen(to, "wb");
    char buf[4096];
    long total = 0;
    size_t n;
    while (a && b && (n = fread(buf, 1, sizeof buf, a)) > 0) {
        if (cut >= 0 && total + (long)n > cut) n = (size_t)(cut - total);
        fwrite(buf, 1, n, b);
        total += (long)n;
        if (cut >= 0 && total >= cut) break;
    }
    if (a) fclose(a);
    if (b) fclose(b);
}

static void test_roundtrip_and_bad(void)
{
    fs_gcache c;
    fs_gbuffer g, back;
    float *rgba;
    fs_provenance prov;
    char path[FS_GCACHE_PATH], path2[FS_GCACHE_PATH];
    if (system("rm -rf " FS_TEST_OUT "/gbuffer_cache")) {}
    CHECK(fs_gcache_open(&c, DIR_) == 0, "open: %s", fs_error_message());
    make_gbuffer(&g, &rgba);
    fs_provenance_init_base(&prov, NULL, NULL);
    fs_digest k = key_n(1), k2 = key_n(2);
    CHECK(load(&c, k, 16, 8) == FS_GCACHE_MISS, "an empty cache misses");
    CHECK(fs_gcache_store(&c, k, &g, rgba, &prov, NULL) == 0, "store: %s", fs_error_message());
    CHECK(temp_files_left(DIR_) == 0, "a temporary file is left behind");
    CHECK(fs_gcache_load(&c, k, 16, 8, &back, counts, sizeof counts) == FS_GCACHE_HIT, "hit: %s", fs_error_message());
    CHECK(back.depth && same_gbuffer(&g, &back), "the entry differs from what was stored");
    fs_gbuffer_free(&back);
    CHECK(load(&c, k2, 16, 8) == FS_GCACHE_MISS, "another key misses");
    CHECK(load(&c, k, 16, 9) == FS_GCACHE_BAD && strstr(fs_error_message(), "16x8"), "another size: %s",
          fs_error_message());
    fs_gcache_entry(&c, k, path, sizeof path);
    fs_gcache_entry(&c, k2, path2, sizeof path2);
    copy_file(path, path2, -1); /* k's entry under k2's name */
    CHECK(load(&c, k2, 16, 8) == FS_GCACHE_BAD && strstr(fs_error_message(), "another key"), "re-keyed: %s",
          fs_error_message());
    for (long cut = 0; cut < 2000; cut += 397) {
        copy_file(path, FS_TEST_OUT "/gbuffer_cache/whole.exr", -1);
        copy_file(FS_TEST_OUT "/gbuffer_cache/whole.exr", path, cut);
        CHECK(load(&c, k, 16, 8) == FS_GCACHE_BAD, "truncated to %ld bytes: not bad", cut);
        copy_file(FS_TEST_OUT "/gbuffer_cache/whole.exr", path, -1);
    }
    CHECK(load(&c, k, 16, 8) == FS_GCACHE_HIT, "restored entry");
    /* the right key but other contents: the content check refuses it */
    fs_provenance p2 = prov;
    char hex[FS_DIGEST_HEX];
    fs_digest_hex(k, hex);
    fs_provenance_set(&p2, "cache_key", hex);
    fs_digest_hex(key_n(3), hex);
    fs_provenance_set(&p2, "cache_data", hex);
    for (int i = 0; i < p2.n; i++) {
        p2.attr[i].name = p2.name[i];
        p2.attr[i].value = p2.value[i];
    }
    CHECK(fs_write_render(path, &g, rgba, &p2) == 0, "write");
    CHECK(load(&c, k, 16, 8) == FS_GCACHE_BAD && strstr(fs_error_message(), "corrupt"), "altered: %s",
          fs_error_message());
    /* the right key, no depth channel */
    const char *names[4] = {"R", "G", "B", "A"};
    fs_image img = {16, 8, 4, names, rgba};
    CHECK(fs_write_exr(path, &img, p2.attr, p2.n) == 0, "write");
    CHECK(load(&c, k, 16, 8) == FS_GCACHE_BAD && strstr(fs_error_message(), "no channel 'depth'"), "channel: %s",
          fs_error_message());
    /* a store replaces a bad entry */
    CHECK(fs_gcache_store(&c, k, &g, rgba, &prov, NULL) == 0 && load(&c, k, 16, 8) == FS_GCACHE_HIT,
          "store over a bad entry");
    CHECK(!counts[0], "an entry stored without work counts brings back none: '%s'", counts);
    /* the work counts come back, and are covered by the content check */
    const char *text = "1:march=12,34,5,0,0,7";
    CHECK(fs_gcache_store(&c, k, &g, rgba, &prov, text) == 0 && load(&c, k, 16, 8) == FS_GCACHE_HIT,
          "store with counts");
    CHECK(!strcmp(counts, text), "the counts come back: '%s'", counts);
    /* the longest counts text any run makes (stage_counts.h) comes back whole */
    static char longest[FS_GCACHE_COUNTS];
    memcpy(longest, "1:", 2);
    memset(longest + 2, '9', sizeof longest - 3);
    CHECK(fs_gcache_store(&c, k, &g, rgba, &prov, longest) == 0 && load(&c, k, 16, 8) == FS_GCACHE_HIT,
          "store the longest counts: %s", fs_error_message());
    CHECK(!strcmp(counts, longest), "the longest counts come back (%zu of %zu bytes)", strlen(counts), strlen(longest));
    fs_provenance p3 = prov;
    for (int i = 0; i < p3.n; i++) {
        p3.attr[i].name = p3.name[i];
        p3.attr[i].value = p3.value[i];
    }
    fs_digest_hex(k, hex);
    fs_provenance_set(&p3, "cache_key", hex);
    fs_digest_hex(fs_gcache_data_hash(&g), hex);
    fs_provenance_set(&p3, "cache_data", hex);
    fs_provenance_set(&p3, "counters", "1:march=99,34,5,0,0,7");
    fs_gcache_entry(&c, k, path, sizeof path);
    CHECK(fs_write_render(path, &g, rgba, &p3) == 0, "write");
    CHECK(load(&c, k, 16, 8) == FS_GCACHE_BAD, "altered counts are caught by the content check");
    fs_gbuffer_free(&g);
    free(rgba);
}

static void test_unusable(void)
{
    fs_gcache c;
    FILE *f = fopen(FS_TEST_OUT "/gbuffer_cache/file", "w");
    if (f) fclose(f);
    CHECK(fs_gcache_open(&c, FS_TEST_OUT "/gbuffer_cache/file/sub") != 0 &&
              strstr(fs_error_message(), "gbuffer_cache/file/sub: cannot create the cache folder"),
          "a folder under a file: %s", fs_error_message());
    CHECK(fs_gcache_open(&c, FS_TEST_OUT "/gbuffer_cache/file") != 0 && strstr(fs_error_message(), "not a folder"),
          "a file as the folder: %s", fs_error_message());
}

int main(void)
{
    test_roundtrip_and_bad();
    test_unusable();
    TEST_DONE();
}
