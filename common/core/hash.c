#include "hash.h"
#include <stdio.h>
#include <string.h>

/* Odd 64-bit constants with well-mixed bits (the primes of the xxHash family). */
#define P1 0x9E3779B185EBCA87ull
#define P2 0xC2B2AE3D27D4EB4Full
#define P3 0x165667B19E3779F9ull
#define P4 0x85EBCA77C2B2AE63ull

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t round64(uint64_t acc, uint64_t w) { return rotl(acc + w * P2, 31) * P1; }

/* Every input bit reaches every output bit (a murmur-style finaliser). */
static uint64_t avalanche(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xFF51AFD7ED558CCDull;
    x ^= x >> 33;
    x *= 0xC4CEB9FE1A85EC53ull;
    x ^= x >> 33;
    return x;
}

static uint64_t load64(const unsigned char *p)
{
    uint64_t v;
    memcpy(&v, p, 8);
    return v;
}

static void stripe(fs_hash *h, const unsigned char *p)
{
    for (int k = 0; k < 4; k++) h->lane[k] = round64(h->lane[k], load64(p + 8 * k));
}

void fs_hash_init(fs_hash *h)
{
    memset(h, 0, sizeof *h);
    h->lane[0] = P1 + P2;
    h->lane[1] = P2;
    h->lane[2] = 0;
    h->lane[3] = -P1;
}

void fs_hash_bytes(fs_hash *h, const void *data, size_t n)
{
    const unsigned char *p = data;
    h->total += n;
    if (h->nbuf) { /* complete the partial stripe first */
        size_t take = 32 - h->nbuf < n ? 32 - h->nbuf : n;
        memcpy(h->buf + h->nbuf, p, take);
        h->nbuf += take;
        p += take;
        n -= take;
        if (h->nbuf < 32) return;
        stripe(h, h->buf);
        h->nbuf = 0;
    }
    for (; n >= 32; p += 32, n -= 32) stripe(h, p);
    memcpy(h->buf, p, n);
    h->nbuf = n;
}

void fs_hash_u64(fs_hash *h, uint64_t v) { fs_hash_bytes(h, &v, sizeof v); }

void fs_hash_str(fs_hash *h, const char *s)
{
    size_t n = s ? strlen(s) : 0;
    fs_hash_u64(h, n);
    fs_hash_bytes(h, s ? s : "", n);
}

fs_digest fs_hash_digest(const fs_hash *h)
{
    uint64_t l[4];
    memcpy(l, h->lane, sizeof l);
    unsigned char tail[32] = {0}; /* the partial stripe, zero-padded; the length tells it apart */
    memcpy(tail, h->buf, h->nbuf);
    for (int k = 0; k < 4; k++) l[k] = round64(l[k], load64(tail + 8 * k));
    uint64_t a = rotl(l[0], 1) + rotl(l[1], 7) + rotl(l[2], 12) + rotl(l[3], 18);
    uint64_t b = (l[0] * P3) ^ rotl(l[1], 23) ^ (l[2] * P4) ^ rotl(l[3], 41);
    fs_digest d;
    d.w[0] = avalanche(a ^ h->total * P4);
    d.w[1] = avalanche(b + d.w[0] + h->total * P3);
    return d;
}

void fs_digest_hex(fs_digest d, char hex[FS_DIGEST_HEX])
{
    snprintf(hex, FS_DIGEST_HEX, "%016llx%016llx", (unsigned long long)d.w[0], (unsigned long long)d.w[1]);
}

int fs_digest_equal(fs_digest a, fs_digest b) { return a.w[0] == b.w[0] && a.w[1] == b.w[1]; }

uint64_t fs_fnv1a(uint64_t h, const void *data, size_t n)
{
    for (size_t i = 0; i < n; i++) h = (h ^ ((const unsigned char *)data)[i]) * 1099511628211ull;
    return h;
}
