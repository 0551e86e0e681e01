#include "fs_error.h"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static _Thread_local char fs_msg[1024];
static _Thread_local int fs_code;

int fs_vfail(int code, const char *fmt, va_list ap)
{
    vsnprintf(fs_msg, sizeof fs_msg, fmt, ap);
    /* One line whatever the file said: names and keys read from input are echoed
     * into messages, so control characters (a newline in a BGEO attribute name)
     * become '?' here, once for every caller. */
    for (char *c = fs_msg; *c; c++)
        if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
    fs_code = code;
    return code;
}

int fs_fail(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fs_vfail(code, fmt, ap);
    va_end(ap);
    return code;
}

const char *fs_error_message(void) { return fs_msg[0] ? fs_msg : "unknown error"; }
int fs_error_code(void) { return fs_msg[0] && fs_code ? fs_code : FS_ERR_RUNTIME; }
void fs_error_clear(void)
{
    fs_msg[0] = 0;
    fs_code = 0;
}

static int fs_quiet;
void fs_note_quiet(int quiet) { fs_quiet = quiet; }
int fs_note_is_quiet(void) { return fs_quiet; }
void fs_note(const char *fmt, ...)
{
    if (fs_quiet) return;
    char line[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    /* a note of several lines: each its own prefixed line */
    for (char *l = line, *nl; l; l = nl) {
        if ((nl = strchr(l, '\n'))) *nl++ = 0;
        fprintf(stderr, "fluidsurf: note: %s\n", l);
    }
}
