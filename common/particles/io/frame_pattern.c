/* Frame patterns (frame_pattern.h). */
#include "frame_pattern.h"
#include "fs_error.h"
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The end of the %d-style conversion that starts at s ('%'), or NULL. */
static const char *conversion_end(const char *s)
{
    s++;
    while (*s && strchr("-+ 0", *s)) s++;
    while (isdigit((unsigned char)*s)) s++;
    if (*s == '.') {
        s++;
        while (isdigit((unsigned char)*s)) s++;
    }
    return *s == 'd' || *s == 'i' ? s : NULL;
}

/* The %d-style conversions in pattern ("%%" is a literal), or -1 when it holds
 * a conversion of another kind. */
static int conversions(const char *pattern)
{
    int n = 0;
    for (const char *s = strchr(pattern, '%'); s; s = strchr(s + 1, '%')) {
        if (s[1] == '%') {
            s++;
            continue;
        }
        if (!(s = conversion_end(s))) return -1;
        n++;
    }
    return n;
}

/* FS_OK when pattern has exactly one %d-style conversion. */
static int check_pattern(const char *pattern)
{
    int n = conversions(pattern);
    if (n < 0) return fs_fail(FS_ERR_INPUT, "%s: frame pattern may only contain a %%d-style conversion", pattern);
    if (n != 1)
        return fs_fail(FS_ERR_INPUT, "%s: frame pattern needs exactly one %%d-style conversion (has %d)", pattern, n);
    return FS_OK;
}

int fs_is_frame_pattern(const char *path) { return strstr(path, "{}") || conversions(path) > 0; }

int fs_frame_pattern(const char *in, char *out, size_t size)
{
    int braces = strstr(in, "{}") != NULL;
    size_t n = 0;
    for (const char *s = in; *s; s++) {
        const char *rep = !braces ? NULL : s[0] == '{' && s[1] == '}' ? "%d" : *s == '%' ? "%%" : NULL;
        size_t k = rep ? 2 : 1;
        if (n + k >= size) return fs_fail(FS_ERR_INPUT, "%s: path too long", in);
        if (rep) memcpy(out + n, rep, 2);
        else out[n] = *s;
        s += rep && *s == '{';
        n += k;
    }
    out[n] = 0;
    return braces && strstr(strstr(in, "{}") + 2, "{}")
        ? fs_fail(FS_ERR_INPUT, "%s: frame pattern needs exactly one {}", in)
        : check_pattern(out);
}

int fs_frame_path(char *out, int size, const char *pattern, int frame)
{
    int rc = check_pattern(pattern);
    if (rc) return rc;
    if (size <= 0) return fs_fail(FS_ERR_INPUT, "%s: no room for the frame path", pattern);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
    int len = snprintf(out, (size_t)size, pattern, frame); /* checked above: one int conversion */
#pragma GCC diagnostic pop
    if (len < 0 || len >= size) return fs_fail(FS_ERR_INPUT, "%s: frame path for frame %d is too long", pattern, frame);
    return FS_OK;
}

/* A number in [lo, 100000000] at *t, moving *t past it; -1 when there is none. */
static long number_at(const char **t, long lo)
{
    char *end;
    long v = strtol(*t, &end, 10);
    if (end == *t || !isdigit((unsigned char)**t) || v < lo || v > 100000000) return -1;
    *t = end;
    return v;
}

int fs_frame_range(const char *text, int *first, int *last, int *step)
{
    const char *t = text;
    long a = number_at(&t, 0), b = -1, c = 1;
    if (a < 0 || *t++ != ':' || (b = number_at(&t, a)) < 0) return -1;
    if (*t == ':' && (t++, c = number_at(&t, 1)) < 0) return -1;
    if (*t) return -1;
    *first = (int)a, *last = (int)b, *step = (int)c;
    return 0;
}
