/* The words messages use for the caller's settings (caller_words.h). */
#include "caller_words.h"
#include <string.h>

static const fs_caller_word library_words[] = {
    {"radius", "the radius"},
    {"up", "the up axis"},
    {"set", "setting"},
    {"counters", "counting"},
    {"reference", "reference"},
    {"import", "import"},
    {"gl_egl", "FLUIDSURF_GL=egl"},
    {"require_gpu", "a required GPU"},
    {NULL, NULL},
};
static const fs_caller_word *caller = NULL;

void fs_caller_words(const fs_caller_word *table) { caller = table; }

static const char *find(const fs_caller_word *t, const char *key)
{
    for (; t && t->key; t++)
        if (!strcmp(t->key, key)) return t->word;
    return NULL;
}

const char *fs_word(const char *key)
{
    const char *w = find(caller, key);
    if (!w) w = find(library_words, key);
    return w ? w : key;
}
