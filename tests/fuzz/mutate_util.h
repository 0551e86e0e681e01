/* Shared by the custom mutators (scene_mutator.c, vtu_mutator.c; tests/fuzz/README.md):
 * a small random generator seeded by libFuzzer, the values that break readers, and
 * the replacement of one span of the input by new text. */
#ifndef FS_MUTATE_UTIL_H
#define FS_MUTATE_UTIL_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* libFuzzer's own byte mutator (with the -dict entries): the fallback */
size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t max_size);

/* xorshift32 from libFuzzer's seed: the same seed gives the same mutation */
static unsigned mu_next(unsigned *s)
{
    unsigned x = *s ? *s : 0x9e3779b9u;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}
static unsigned mu_below(unsigned *s, unsigned n) { return n ? mu_next(s) % n : 0; }
#define MU_PICK(s, list) ((list)[mu_below((s), (unsigned)(sizeof(list) / sizeof(list)[0]))])

/* Numbers a reader must check before it sizes, casts or loops on them */
static const char *const mu_numbers[] = {
    "0",
    "-0",
    "1",
    "-1",
    "2",
    "3",
    "0.5",
    "-0.5",
    "1e308",
    "-1e308",
    "1e309",
    "-1e309",
    "1e-320",
    "nan",
    "NaN",
    "-nan",
    "inf",
    "Infinity",
    "-Infinity",
    "127",
    "255",
    "256",
    "65535",
    "65536",
    "16777217",
    "2147483647",
    "2147483648",
    "-2147483648",
    "-2147483649",
    "4294967295",
    "4294967296",
    "4294967297",
    "1e9",
    "1e10",
    "-1e9",
    "9007199254740993",
    "9223372036854775807",
    "9223372036854775808",
    "18446744073709551615",
    "18446744073709551616",
    "1e19",
    "0x10",
    "1.5e",
    "--1",
    "",
};

/* A number near the old one (its negative, one more, a million times, a tiny part), or
 * one of mu_numbers: written into out (at least 48 bytes) */
static void mu_number(unsigned *s, const uint8_t *old, size_t len, char *out, size_t cap)
{
    char buf[48];
    size_t n = len < sizeof buf - 1 ? len : sizeof buf - 1;
    memcpy(buf, old, n);
    buf[n] = 0;
    double v = strtod(buf, NULL);
    switch (mu_below(s, 6)) {
    case 0: snprintf(out, cap, "%.17g", -v); break;
    case 1: snprintf(out, cap, "%.17g", v + 1); break;
    case 2: snprintf(out, cap, "%.17g", v * 1e6); break;
    case 3: snprintf(out, cap, "%.17g", v * 1e-6); break;
    default: snprintf(out, cap, "%s", MU_PICK(s, mu_numbers)); break;
    }
}

/* Replaces data[at, at + len) by rep (rep_len bytes); 0 when the result would exceed
 * max_size (the caller falls back to LLVMFuzzerMutate) */
static size_t mu_splice(uint8_t *data, size_t size, size_t max_size, size_t at, size_t len, const char *rep,
                        size_t rep_len)
{
    if (size - len + rep_len > max_size) return 0;
    memmove(data + at + rep_len, data + at + len, size - at - len);
    memcpy(data + at, rep, rep_len);
    return size - len + rep_len;
}

/* A string value that breaks naive readers: empty, long, a path out of the tree, bytes
 * that are not UTF-8, control characters, printf directives (into rep, cap >= 2048) */
static size_t mu_string(unsigned *s, char *rep, size_t cap)
{
    static const char *const odd[] = {
        "",
        "a",
        "../../../../../../etc/passwd",
        "/dev/zero",
        "/proc/self/mem",
        "\\u0000",
        "\xff\xfe",
        "\xc3\x28",
        "%s%s%n",
        "\\n\\r\\t",
        "\x01\x7f",
        " ",
        ".",
        "nan",
        "-1",
    };
    if (mu_below(s, 4) == 0) { /* long: up to cap - 1 bytes */
        size_t n = 64u << mu_below(s, 6);
        if (n >= cap) n = cap - 1;
        memset(rep, 'A' + (int)mu_below(s, 26), n);
        rep[n] = 0;
        return n;
    }
    snprintf(rep, cap, "%s", MU_PICK(s, odd));
    return strlen(rep);
}

#endif
