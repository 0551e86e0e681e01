/* The progress bar and lines of progress.h. */
#include "progress.h"
#include "fs_error.h"
#include "timing.h"

#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static struct {
    const char *cmd, *unit;
    long total;
    atomic_long done, sub_done, sub_total;
    atomic_int drawing;
    double t0, last_draw;
    int active, tty;
    char detail[160];
} P;

void fs_progress_begin(const char *cmd, const char *unit, long total)
{
    P.cmd = cmd, P.unit = unit, P.total = total > 0 ? total : 1;
    atomic_store(&P.done, 0);
    atomic_store(&P.sub_done, 0);
    atomic_store(&P.sub_total, 0);
    P.t0 = fs_now_ms(), P.last_draw = 0, P.detail[0] = 0;
    P.tty = isatty(STDERR_FILENO);
    P.active = !fs_note_is_quiet();
}

/* Fraction of the job done, counting the current item's finished parts. */
static double fraction(void)
{
    long st = atomic_load(&P.sub_total), sd = atomic_load(&P.sub_done);
    double item = st > 0 ? (double)(sd < st ? sd : st) / st : 0;
    return (atomic_load(&P.done) + item) / P.total;
}

static void eta(char *buf, size_t size, double f, double elapsed_s)
{
    if (f > 0.02 && f < 1) snprintf(buf, size, ", ETA %.0f s", elapsed_s / f - elapsed_s);
    else buf[0] = 0;
}

static void draw_bar(void)
{
    double f = fraction(), el = (fs_now_ms() - P.t0) / 1000;
    char bar[31], e[32];
    int fill = (int)(f * 30);
    for (int i = 0; i < 30; i++) bar[i] = i < fill ? '#' : '.';
    bar[30] = 0;
    eta(e, sizeof e, f, el);
    fprintf(stderr, "\r%s [%s] %3.0f%%  %ld/%ld %s  %.0f s%s  %s\033[K", P.cmd, bar, 100 * f, atomic_load(&P.done),
            P.total, P.unit, el, e, P.detail);
    fflush(stderr);
}

/* Redraws at most 10 times a second, one thread at a time. */
static void maybe_draw(int force)
{
    if (!P.active || !P.tty) return;
    int expected = 0;
    if (!atomic_compare_exchange_strong(&P.drawing, &expected, 1)) return;
    double now = fs_now_ms();
    if (force || now - P.last_draw > 100) {
        P.last_draw = now;
        draw_bar();
    }
    atomic_store(&P.drawing, 0);
}

void fs_progress_item(const char *detail)
{
    if (!P.cmd) return;
    atomic_fetch_add(&P.done, 1);
    atomic_store(&P.sub_done, 0);
    atomic_store(&P.sub_total, 0);
    snprintf(P.detail, sizeof P.detail, "%s", detail ? detail : "");
    if (P.active && !P.tty && P.total > 1) { /* a one-item job says nothing off a terminal */
        double f = fraction(), el = (fs_now_ms() - P.t0) / 1000;
        char e[32];
        eta(e, sizeof e, f, el);
        fprintf(stderr, "fluidsurf: %s: %ld/%ld %s%s%s, %.1f s%s\n", P.cmd, atomic_load(&P.done), P.total, P.unit,
                P.detail[0] ? ": " : "", P.detail, el, e);
    }
    maybe_draw(1);
}

void fs_progress_sub_total(long sub_total) { atomic_store(&P.sub_total, sub_total); }

void fs_progress_sub(long n)
{
    if (!P.cmd) return;
    atomic_fetch_add(&P.sub_done, n);
    maybe_draw(0);
}

void fs_progress_end(void)
{
    if (P.cmd && P.active && P.tty) fprintf(stderr, "\r\033[K");
    P.cmd = NULL;
}

/* Appends s to buf (size left in *left): no stdio, for the signal handler. */
static char *put(char *at, size_t *left, const char *s)
{
    while (*s && *left > 1) *at++ = *s++, (*left)--;
    *at = 0;
    return at;
}

static char *put_long(char *at, size_t *left, long v)
{
    char digits[24];
    int n = 0;
    do digits[n++] = (char)('0' + v % 10);
    while ((v /= 10) > 0 && n < 23);
    char s[24];
    for (int i = 0; i < n; i++) s[i] = digits[n - 1 - i];
    s[n] = 0;
    return put(at, left, s);
}

void fs_progress_summary(char *buf, size_t size)
{
    if (!size) return;
    buf[0] = 0;
    const char *unit = P.unit;
    if (!P.cmd || !unit) return;
    char *at = buf;
    at = put_long(at, &size, atomic_load(&P.done));
    at = put(at, &size, " of ");
    at = put_long(at, &size, P.total);
    at = put(at, &size, " ");
    at = put(at, &size, unit);
    put(at, &size, " finished");
}
