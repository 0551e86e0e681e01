/* Version, errors and the one-time set-up of the library. */
#include "api_internal.h"
#include "fs_error.h"
#include "method.h"
#include "builtin_methods.h"
#include "provenance.h"

#include <pthread.h>
#include <stdio.h>

static pthread_once_t once = PTHREAD_ONCE_INIT;

static void init(void)
{
    fs_methods_register_builtin();
    fs_note_quiet(1); /* a library prints nothing: notes and progress are the CLI's */
}

void fs_api_init(void) { pthread_once(&once, init); }

int fs_api_check(const void *ptr, const char *what)
{
    return ptr ? FLUIDSURF_OK : fs_fail(FS_ERR_INPUT, "%s is NULL", what);
}

int fluidsurf_api_version(void) { return FLUIDSURF_API_VERSION; }

static char version_text[160];
static pthread_once_t version_once = PTHREAD_ONCE_INIT;
static void fill_version(void)
{
    snprintf(version_text, sizeof version_text, "%s (commit %s%s)", fs_version, fs_commit, fs_dirty ? "-dirty" : "");
}

const char *fluidsurf_version(void)
{
    pthread_once(&version_once, fill_version);
    return version_text;
}

const char *fluidsurf_last_error(void) { return fs_error_message(); }
