/* A streaming 128-bit hash for cache keys and content checks (not cryptographic:
 * it guards against accidents, not attackers). Four 64-bit lanes take the input
 * in 32-byte stripes with a multiply-rotate round; the final step folds the
 * lanes and the length into two 64-bit words through an avalanche mix. The
 * result depends on the bytes only, so on one machine's byte order. */
#ifndef FS_HASH_H
#define FS_HASH_H
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_hash {
    uint64_t lane[4];
    unsigned char buf[32]; /* a partial stripe */
    size_t nbuf;
    uint64_t total; /* bytes so far */
} fs_hash;

/* A 128-bit digest and its 32-character lowercase hex form (+ NUL). */
typedef struct fs_digest {
    uint64_t w[2];
} fs_digest;
#define FS_DIGEST_HEX 33

void fs_hash_init(fs_hash *h);
void fs_hash_bytes(fs_hash *h, const void *data, size_t n);
/* A string with its length first, so ("ab","c") and ("a","bc") differ. */
void fs_hash_str(fs_hash *h, const char *s);
void fs_hash_u64(fs_hash *h, uint64_t v);
/* The digest of everything so far (h is left as it is). */
fs_digest fs_hash_digest(const fs_hash *h);
void fs_digest_hex(fs_digest d, char hex[FS_DIGEST_HEX]);
int fs_digest_equal(fs_digest a, fs_digest b);

/* FNV-1a's step over n bytes (xor, then multiply by its 64-bit prime),
 * continuing from h. FS_FNV1A_BASIS, FNV's 64-bit offset basis, begins a true
 * FNV-1a. FS_SCENE_HASH_START begins the scene hash of provenance (a scene file's
 * bytes, or the flags that built a scene): the same step from FNV's basis with its
 * last digit missing (1469598103934665603 for 14695981039346656037), so it is not
 * FNV-1a; it is kept so that the scene hashes recorded in committed outputs, the
 * shard manifests and diff's warnings stay comparable. */
#define FS_FNV1A_BASIS 14695981039346656037ull
#define FS_SCENE_HASH_START 1469598103934665603ull
uint64_t fs_fnv1a(uint64_t h, const void *data, size_t n);

#ifdef __cplusplus
}
#endif
#endif
