#include "fs_error.h"
#include <stdarg.h>
#include <stdio.h>

static _Thread_local char fs_msg[1024];

int fs_fail(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(fs_msg, sizeof fs_msg, fmt, ap);
    va_end(ap);
    return code;
}

const char *fs_error_message(void) { return fs_msg[0] ? fs_msg : "unknown error"; }
void fs_error_clear(void) { fs_msg[0] = 0; }

static int fs_quiet;
void fs_note_quiet(int quiet) { fs_quiet = quiet; }
void fs_note(const char *fmt, ...)
{
    if (fs_quiet) return;
    char line[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    fprintf(stderr, "fluidsurf: note: %s\n", line);
}
