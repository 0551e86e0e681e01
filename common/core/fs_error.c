#include "fs_error.h"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static _Thread_local char fs_msg[1024];
static _Thread_local int fs_code;

/* Length of the valid UTF-8 sequence at s (1..4), or 0 when s starts none
 * (a stray continuation byte, an overlong form, a surrogate, past U+10FFFF). */
static int utf8_length(const unsigned char *s)
{
    int n = s[0] < 0x80                ? 1
        : s[0] >= 0xc2 && s[0] <= 0xdf ? 2
        : s[0] >= 0xe0 && s[0] <= 0xef ? 3
        : s[0] >= 0xf0 && s[0] <= 0xf4 ? 4
                                       : 0;
    for (int i = 1; i < n; i++)
        if ((s[i] & 0xc0) != 0x80) return 0;
    if ((s[0] == 0xe0 && s[1] < 0xa0) || (s[0] == 0xed && s[1] > 0x9f) || (s[0] == 0xf0 && s[1] < 0x90) ||
        (s[0] == 0xf4 && s[1] > 0x8f))
        return 0;
    return n;
}

/* One line of valid UTF-8 whatever the input said: names and keys read from
 * files are echoed into messages, so control characters (a newline in a BGEO
 * attribute name) become '?', and bytes that are not UTF-8 are written \xFF. */
void fs_text_line(char *out, size_t size, const char *in)
{
    size_t o = 0;
    for (const unsigned char *s = (const unsigned char *)in; *s && o + 5 < size;) {
        int n = utf8_length(s);
        if (n == 0) o += (size_t)snprintf(out + o, size - o, "\\x%02X", *s++);
        else if (n == 1) out[o++] = *s < 0x20 || *s == 0x7f ? '?' : (char)*s, s++;
        else
            while (n--) out[o++] = (char)*s++;
    }
    out[o] = 0;
}

int fs_vfail(int code, const char *fmt, va_list ap)
{
    char raw[sizeof fs_msg];
    vsnprintf(raw, sizeof raw, fmt, ap);
    fs_text_line(fs_msg, sizeof fs_msg, raw);
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
    /* a note of several lines: each its own prefixed line, as text */
    for (char *l = line, *nl; l; l = nl) {
        if ((nl = strchr(l, '\n'))) *nl++ = 0;
        char text[sizeof line];
        fs_text_line(text, sizeof text, l);
        fprintf(stderr, "fluidsurf: note: %s\n", text);
    }
}
