/* Custom mutator of the scene JSON target (fuzz_scene_mut; tests/fuzz/README.md). A byte
 * mutator rarely turns a valid scene into a valid scene with one bad value, so three times
 * in four this one reads the input loosely as JSON tokens (it need not parse) and edits
 * one: a number becomes an extreme, NaN-ish, huge, negative or nearby one; a string value
 * becomes empty, long or odd; a key becomes another known key (the quoted entries of the
 * -dict file, scene.dict); a value becomes one of another type. Otherwise, or when the
 * input has no token, libFuzzer's own mutator (LLVMFuzzerMutate) runs. Compiled without
 * coverage instrumentation, so its code adds no features of its own. */
#include "mutate_util.h"

enum { TOK_NUM, TOK_STR, TOK_KEY, TOK_LIT };
typedef struct {
    size_t at, len;
    int kind;
} token;

#define MAX_KEYS 128
static char keys[MAX_KEYS][64]; /* each a JSON string literal, quotes included */
static int n_keys;

/* The keys: the dict entries that are a quoted string, "\"name\"" */
static void load_keys(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[256];
    while (f && n_keys < MAX_KEYS && fgets(line, sizeof line, f)) {
        size_t n = strcspn(line, "\r\n");
        if (n < 7 || n - 4 >= sizeof keys[0] || strncmp(line, "\"\\\"", 3) || strncmp(line + n - 3, "\\\"\"", 3))
            continue;
        snprintf(keys[n_keys++], sizeof keys[0], "\"%.*s\"", (int)(n - 6), line + 3);
    }
    if (f) fclose(f);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    for (int i = 1; i < *argc; i++)
        if (!strncmp((*argv)[i], "-dict=", 6)) load_keys((*argv)[i] + 6);
    if (n_keys == 0) { /* run without -dict: a few keys of every scene */
        static const char *const builtin[] = {"\"particles\"", "\"radius\"", "\"camera\"", "\"width\"",
                                              "\"synthetic\"", "\"frames\"", "\"set\"",    "\"obstacles\""};
        for (size_t i = 0; i < sizeof builtin / sizeof *builtin; i++)
            snprintf(keys[n_keys++], sizeof keys[0], "%s", builtin[i]);
    }
    return 0;
}

static int is_space(uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/* The input's tokens, at most cap: strings (a key when a ':' follows), numbers, words */
static size_t scan(const uint8_t *d, size_t size, token *t, size_t cap)
{
    size_t n = 0, i = 0;
    while (i < size && n < cap) {
        size_t at = i;
        int kind;
        if (d[i] == '"') {
            for (i++; i < size && d[i] != '"'; i++)
                if (d[i] == '\\') i++;
            i = i < size ? i + 1 : size;
            size_t j = i;
            while (j < size && is_space(d[j])) j++;
            kind = j < size && d[j] == ':' ? TOK_KEY : TOK_STR;
        } else if (strchr("-+.0123456789", d[i]) && d[i]) {
            while (i < size && d[i] && strchr("-+.0123456789eE", d[i])) i++;
            kind = TOK_NUM;
        } else if ((d[i] | 0x20) >= 'a' && (d[i] | 0x20) <= 'z') {
            while (i < size && (d[i] | 0x20) >= 'a' && (d[i] | 0x20) <= 'z') i++;
            kind = TOK_LIT;
        } else {
            i++;
            continue;
        }
        t[n++] = (token){at, i - at, kind};
    }
    return n;
}

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned seed)
{
    static const char *const other_type[] = {
        "\"x\"",     "null",       "true", "false", "[]", "{}", "[1e308,-1e308,0]", "[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]",
        "{\"\":{}}", "[-1,-1,-1]", "\"\""};
    static token tok[4096];
    static char rep[2048 + 2];
    unsigned s = seed;
    size_t n = mu_below(&s, 4) ? scan(data, size, tok, sizeof tok / sizeof *tok) : 0;
    if (n == 0) return LLVMFuzzerMutate(data, size, max_size);
    token t = tok[mu_below(&s, (unsigned)n)];
    int confuse = mu_below(&s, 10) < 3;
    if (t.kind == TOK_KEY)
        snprintf(rep, sizeof rep, "%.*s", (int)sizeof rep - 1,
                 confuse ? "\"\"" : keys[mu_below(&s, (unsigned)n_keys)]); /* a long key: cut */
    else if (confuse) snprintf(rep, sizeof rep, "%s", MU_PICK(&s, other_type));
    else if (t.kind == TOK_STR) {
        rep[0] = '"';
        size_t k = mu_string(&s, rep + 1, sizeof rep - 2);
        rep[k + 1] = '"';
        rep[k + 2] = 0;
    } else mu_number(&s, data + t.at, t.len, rep, sizeof rep);
    size_t r = mu_splice(data, size, max_size, t.at, t.len, rep, strlen(rep));
    return r ? r : LLVMFuzzerMutate(data, size, max_size);
}
