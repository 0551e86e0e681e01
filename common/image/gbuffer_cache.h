/* A folder of cached G-buffers (docs/DESIGN.md, "Reference cache"): one EXR per
 * key, written by fs_write_render with the provenance plus two attributes,
 * fluidsurf:cache_key (the full 128-bit key) and fluidsurf:cache_data (a hash
 * of the G-buffer's contents). An entry is trusted only when both match. */
#ifndef FS_GBUFFER_CACHE_H
#define FS_GBUFFER_CACHE_H
#include "gbuffer.h"
#include "hash.h"
#include "provenance.h"
#include "stage_counts.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_GCACHE_PATH 1100
#define FS_GCACHE_COUNTS FS_STAGE_COUNTS_MAX /* the work counts' text (stage_counts.h), any run's */

typedef struct fs_gcache {
    char dir[FS_GCACHE_PATH - 64]; /* room for "/gbuffer-<hex>.exr" */
} fs_gcache;

typedef enum {
    FS_GCACHE_MISS = 0, /* no entry */
    FS_GCACHE_HIT,      /* g holds the entry */
    FS_GCACHE_BAD,      /* an entry that cannot be trusted; fs_error_message says why */
} fs_gcache_result;

/* Uses folder dir, made with its parents when missing; checks that a file can
 * be created in it. FS_ERR_RUNTIME "DIR: cannot ..." otherwise. */
int fs_gcache_open(fs_gcache *c, const char *dir);
/* DIR/gbuffer-<the key's first 64 bits in hex>.exr */
void fs_gcache_entry(const fs_gcache *c, fs_digest key, char *path, int size);
/* The entry of key, expected w x h, into g (allocated here on a hit, empty
 * otherwise) and the work counts it was stored with into counts ("" when
 * none). A file that is unreadable, truncated, of another size, lacks a
 * channel, holds another key or fails the content check (which covers the
 * counts) is BAD, never a hit. */
fs_gcache_result fs_gcache_load(const fs_gcache *c, fs_digest key, int w, int h, fs_gbuffer *g, char *counts, int size);
/* Stores g (rgba: its shaded image, kept so the entry can be viewed) and the
 * work counts' text (attribute fluidsurf:counters; NULL or "": none) under key,
 * atomically (a temporary file in the folder, renamed), replacing any entry. */
int fs_gcache_store(const fs_gcache *c, fs_digest key, const fs_gbuffer *g, const float *rgba,
                    const fs_provenance *prov, const char *counts);
/* The hash of g as fs_read_render brings it back: size, coverage, depth and
 * normal where covered, thickness, every AOV by name. */
fs_digest fs_gcache_data_hash(const fs_gbuffer *g);

#ifdef __cplusplus
}
#endif
#endif
