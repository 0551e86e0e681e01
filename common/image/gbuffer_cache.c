#include "gbuffer_cache.h"
#include "fs_error.h"
#include "image_io.h"
#include "render_output.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define KEY_ATTR "fluidsurf:cache_key"
#define DATA_ATTR "fluidsurf:cache_data"
#define COUNTS_ATTR "fluidsurf:counters"

/* mkdir -p: each missing folder of path, 0755. */
static int make_folders(const char *path)
{
    char buf[FS_GCACHE_PATH];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *s = buf + 1;; s++) {
        if (*s && *s != '/') continue;
        char keep = *s;
        *s = 0;
        if (mkdir(buf, 0755) != 0 && errno != EEXIST)
            return fs_fail(FS_ERR_RUNTIME, "%s: cannot create the cache folder: %s", path, strerror(errno));
        if (!(*s = keep)) break;
    }
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode)) return fs_fail(FS_ERR_RUNTIME, "%s: not a folder", path);
    return FS_OK;
}

/* access(W_OK) says yes to root in a read-only folder: create a file to know. */
static int probe_write(const char *dir)
{
    char probe[FS_GCACHE_PATH];
    snprintf(probe, sizeof probe, "%s/.probe.tmpXXXXXX", dir);
    int fd = mkstemp(probe);
    if (fd < 0) return fs_fail(FS_ERR_RUNTIME, "%s: cannot write to the cache folder: %s", dir, strerror(errno));
    close(fd);
    unlink(probe);
    return FS_OK;
}

int fs_gcache_open(fs_gcache *c, const char *dir)
{
    memset(c, 0, sizeof *c);
    if (!dir || !*dir) return fs_fail(FS_ERR_RUNTIME, "no cache folder given");
    if (strlen(dir) >= sizeof c->dir) return fs_fail(FS_ERR_RUNTIME, "%s: cache folder path too long", dir);
    snprintf(c->dir, sizeof c->dir, "%s", dir);
    int rc = make_folders(c->dir);
    if (!rc) rc = probe_write(c->dir);
    return rc;
}

void fs_gcache_entry(const fs_gcache *c, fs_digest key, char *path, int size)
{
    snprintf(path, size, "%s/gbuffer-%016llx.exr", c->dir, (unsigned long long)key.w[0]);
}

static void hash_masked(fs_hash *h, const fs_gbuffer *g)
{
    size_t n = (size_t)g->w * g->h;
    for (size_t i = 0; i < n; i++) {
        int cov = g->coverage[i] > 0.5f;
        float v[5] = {cov ? 1.0f : 0.0f, cov ? g->depth[i] : INFINITY, 0, 0, 0};
        if (cov) memcpy(v + 2, g->normal + 3 * i, 3 * sizeof(float));
        fs_hash_bytes(h, v, sizeof v);
    }
}

fs_digest fs_gcache_data_hash(const fs_gbuffer *g)
{
    fs_hash h;
    size_t n = (size_t)g->w * g->h;
    fs_hash_init(&h);
    fs_hash_u64(&h, (uint64_t)g->w);
    fs_hash_u64(&h, (uint64_t)g->h);
    hash_masked(&h, g);
    fs_hash_bytes(&h, g->thickness, n * sizeof(float));
    fs_hash_u64(&h, (uint64_t)g->naovs);
    for (int a = 0; a < g->naovs; a++) {
        fs_hash_str(&h, g->aov[a].name);
        fs_hash_u64(&h, (uint64_t)g->aov[a].ncomp);
        fs_hash_bytes(&h, g->aov[a].data, n * g->aov[a].ncomp * sizeof(float));
    }
    return fs_hash_digest(&h);
}

/* What cache_data holds: the G-buffer's hash, and with work counts the hash of
 * both (an entry without counts keeps the hash it always had). */
static fs_digest entry_hash(const fs_gbuffer *g, const char *counts)
{
    fs_digest d = fs_gcache_data_hash(g);
    if (!counts || !*counts) return d;
    fs_hash h;
    fs_hash_init(&h);
    fs_hash_bytes(&h, &d, sizeof d);
    fs_hash_str(&h, counts);
    return fs_hash_digest(&h);
}

/* The entry's attribute name equals want: FS_OK, else BAD with the reason. */
static int check_attr(const char *path, const char *name, const char *want, const char *what)
{
    char got[FS_DIGEST_HEX + 8];
    int found = fs_read_image_attr(path, name, got, sizeof got);
    if (found < 0) return FS_ERR_INPUT; /* the reader's message names the file */
    if (!found) return fs_fail(FS_ERR_INPUT, "%s: no %s attribute", path, name);
    if (strcmp(got, want)) return fs_fail(FS_ERR_INPUT, "%s: %s", path, what);
    return FS_OK;
}

/* Reads the pixels and the counts and checks their size and contents. */
static int read_checked(const char *path, int w, int h, fs_gbuffer *g, char *counts, int size)
{
    float *rgba = NULL, r;
    int rc = fs_read_render(path, g, &rgba, &r);
    free(rgba);
    if (rc) return rc;
    char hex[FS_DIGEST_HEX];
    int found = fs_read_image_attr(path, COUNTS_ATTR, counts, size);
    if (found <= 0) counts[0] = 0;
    if (g->w != w || g->h != h) rc = fs_fail(FS_ERR_INPUT, "%s: %dx%d, expected %dx%d", path, g->w, g->h, w, h);
    else fs_digest_hex(entry_hash(g, counts), hex);
    if (!rc) rc = check_attr(path, DATA_ATTR, hex, "contents fail their check (corrupt)");
    if (rc) fs_gbuffer_free(g);
    return rc;
}

fs_gcache_result fs_gcache_load(const fs_gcache *c, fs_digest key, int w, int h, fs_gbuffer *g, char *counts, int size)
{
    counts[0] = 0;
    char path[FS_GCACHE_PATH], hex[FS_DIGEST_HEX];
    struct stat st;
    memset(g, 0, sizeof *g);
    fs_gcache_entry(c, key, path, sizeof path);
    if (stat(path, &st) != 0) return FS_GCACHE_MISS;
    if (!S_ISREG(st.st_mode)) {
        fs_fail(FS_ERR_INPUT, "%s: not a regular file", path);
        return FS_GCACHE_BAD;
    }
    fs_digest_hex(key, hex);
    if (check_attr(path, KEY_ATTR, hex, "holds another key (a stale entry or a name collision)")) return FS_GCACHE_BAD;
    return read_checked(path, w, h, g, counts, size) ? FS_GCACHE_BAD : FS_GCACHE_HIT;
}

int fs_gcache_store(const fs_gcache *c, fs_digest key, const fs_gbuffer *g, const float *rgba,
                    const fs_provenance *prov, const char *counts)
{
    fs_provenance p;
    char path[FS_GCACHE_PATH], hex[FS_DIGEST_HEX];
    p = *prov;
    for (int i = 0; i < p.n; i++) { /* the copy's entries point into the copy */
        p.attr[i].name = p.name[i];
        p.attr[i].value = p.value[i];
    }
    fs_digest_hex(key, hex);
    fs_provenance_set(&p, "cache_key", hex);
    fs_digest_hex(entry_hash(g, counts), hex);
    fs_provenance_set(&p, "cache_data", hex);
    if (counts && *counts) { /* by pointer: a provenance value holds 640 bytes, the counts up to FS_GCACHE_COUNTS */
        if (p.n == FS_PROV_MAX) return fs_fail(FS_ERR_RUNTIME, "cache entry: no room for the work counts' attribute");
        p.attr[p.n].name = COUNTS_ATTR;
        p.attr[p.n++].value = counts;
    }
    fs_gcache_entry(c, key, path, sizeof path);
    return fs_write_render(path, g, rgba, &p);
}
