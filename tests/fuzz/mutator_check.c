/* Checks a custom mutator (scene_mutator.c or vtu_mutator.c, linked with this file) without
 * libFuzzer: from every seed of a folder it makes 300 mutations (seeds 1..300) and fails
 * unless each result fits max_size, nine in ten differ from the seed, and at least half
 * keep the seed's structure (json: cJSON still parses it; xml: the same tags and
 * attributes). The stand-in for libFuzzer's byte mutator below halves the input, which
 * breaks the structure: a mutator that only fell back to it fails.
 *   mutator_check json|xml FOLDER [DICT] */
#include <cjson/cJSON.h>
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned seed);
__attribute__((weak)) int LLVMFuzzerInitialize(int *argc, char ***argv);

size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t max_size)
{
    (void)data;
    (void)max_size;
    return size / 2;
}

enum { MAX = 1 << 16, ROUNDS = 300 };

static size_t count(const uint8_t *d, size_t n, const char *what)
{
    size_t c = 0, k = strlen(what);
    for (size_t i = 0; i + k <= n; i++) c += !memcmp(d + i, what, k);
    return c;
}

static int same_structure(int json, const uint8_t *in, size_t in_n, const uint8_t *out, size_t out_n)
{
    if (json) {
        cJSON *j = cJSON_ParseWithLength((const char *)out, out_n);
        cJSON_Delete(j);
        return j != NULL;
    }
    static const char *const marks[] = {"<", ">", "=\"", "='"};
    for (size_t m = 0; m < sizeof marks / sizeof *marks; m++)
        if (count(in, in_n, marks[m]) != count(out, out_n, marks[m])) return 0;
    return 1;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: mutator_check json|xml FOLDER [DICT]\n");
        return 2;
    }
    int json = !strcmp(argv[1], "json");
    char dict[4096];
    snprintf(dict, sizeof dict, "-dict=%s", argc > 3 ? argv[3] : "");
    char *fake[] = {argv[0], dict, NULL};
    int fake_n = argc > 3 ? 2 : 1;
    char **fake_v = fake;
    if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&fake_n, &fake_v);
    static uint8_t seed[MAX], buf[MAX];
    size_t total = 0, differ = 0, kept = 0;
    DIR *d = opendir(argv[2]);
    for (struct dirent *e; d && (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", argv[2], e->d_name);
        FILE *f = fopen(path, "rb");
        size_t n = f ? fread(seed, 1, MAX, f) : 0;
        if (f) fclose(f);
        if (n == 0 || n == MAX) continue; /* empty or too large to mutate within MAX */
        for (unsigned r = 1; r <= ROUNDS; r++) {
            memcpy(buf, seed, n);
            size_t m = LLVMFuzzerCustomMutator(buf, n, MAX, r);
            if (m > MAX) {
                fprintf(stderr, "mutator_check: %s, seed %u: %zu bytes > max %d\n", path, r, m, MAX);
                return 1;
            }
            total++;
            differ += m != n || memcmp(buf, seed, n) != 0;
            kept += same_structure(json, seed, n, buf, m);
        }
    }
    if (d) closedir(d);
    printf("mutator_check %s: %zu mutations, %zu differ from the seed, %zu keep its structure\n", argv[2], total,
           differ, kept);
    if (total == 0) {
        fprintf(stderr, "mutator_check: no seeds in %s\n", argv[2]);
        return 1;
    }
    if (differ * 10 < total * 9) {
        fprintf(stderr, "mutator_check: under nine in ten mutations change the input\n");
        return 1;
    }
    if (kept * 2 < total) {
        fprintf(stderr, "mutator_check: under half the mutations keep the structure\n");
        return 1;
    }
    return 0;
}
