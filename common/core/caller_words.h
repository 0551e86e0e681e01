/* The words a message uses for a setting its caller offers: `common/` never names
 * a command-line flag, since a C or Python caller has none. Each key has the
 * library's own phrase; the command line registers its flags at start-up
 * (cli/main.c), so its messages name its flags where the library's say "the radius". */
#ifndef FS_CALLER_WORDS_H
#define FS_CALLER_WORDS_H
#ifdef __cplusplus
extern "C" {
#endif

/* Keys: "radius", "up", "set", "counters", "reference", "import", "gl_egl", "require_gpu". */
typedef struct fs_caller_word {
    const char *key, *word;
} fs_caller_word;

/* The caller's words, a table ended by {NULL, NULL} and kept (static); NULL restores the library's. */
void fs_caller_words(const fs_caller_word *table);
/* key's word: the caller's, else the library's, else key itself. */
const char *fs_word(const char *key);

#ifdef __cplusplus
}
#endif
#endif
