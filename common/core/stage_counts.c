#include "stage_counts.h"
#include "fs_error.h"
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

static int name_ok(const char *s, size_t len)
{
    return len >= 1 && len <= FS_STAGE_NAME_MAX && !memchr(s, '=', len) && !memchr(s, ',', len) && !memchr(s, ';', len);
}

int fs_stage_counts_format(const fs_stages *st, char *buf, int size)
{
    int n = snprintf(buf, size, "1:");
    for (int i = 0; i < st->n && n < size; i++) {
        if (!name_ok(st->name[i], strlen(st->name[i])))
            return fs_fail(FS_ERR_RUNTIME, "work counts: stage name '%s' cannot be stored", st->name[i]);
        n += snprintf(buf + n, size - n, "%s%s=", i ? ";" : "", st->name[i]);
        for (int c = 0; c < FS_NCOUNTERS && n < size; c++)
            n += snprintf(buf + n, size - n, "%s%" PRIu64, c ? "," : "", st->count[i][c]);
    }
    if (n >= size) return fs_fail(FS_ERR_RUNTIME, "work counts do not fit in %d bytes", size);
    return FS_OK;
}

/* Stage names live as long as the process (fs_stages keeps pointers). */
static const char *intern(const char *s, size_t len)
{
    static char names[64][FS_STAGE_NAME_MAX + 1];
    static int n;
    for (int i = 0; i < n; i++)
        if (strlen(names[i]) == len && !strncmp(names[i], s, len)) return names[i];
    if (n == 64 || len >= sizeof names[0]) return NULL;
    memcpy(names[n], s, len);
    names[n][len] = 0;
    return names[n++];
}

/* One value: digits only, no leading zero, below 2^64; the end in *end. */
static int value(const char *p, const char **end, uint64_t *v)
{
    uint64_t x = 0;
    const char *q = p;
    for (; *q >= '0' && *q <= '9'; q++) {
        unsigned d = (unsigned)(*q - '0');
        if (x > (UINT64_MAX - d) / 10) return 0; /* would not fit: too large, as ERANGE */
        x = x * 10 + d;
    }
    if (q == p || (*p == '0' && q - p > 1)) return 0;
    *end = q;
    *v = x;
    return 1;
}

int fs_stage_counts_parse(const char *text, fs_stages *st)
{
    memset(st, 0, sizeof *st);
    if (strncmp(text, "1:", 2)) return FS_ERR_INPUT;
    const char *p = text + 2;
    do { /* one or more stages, ';' between them */
        const char *eq = strchr(p, '=');
        size_t len = eq ? (size_t)(eq - p) : 0;
        if (!eq || !name_ok(p, len) || st->n == FS_MAX_STAGES) return FS_ERR_INPUT;
        const char *name = intern(p, len);
        if (!name) return FS_ERR_INPUT;
        for (int i = 0; i < st->n; i++)
            if (st->name[i] == name) return FS_ERR_INPUT; /* a stage twice */
        st->name[st->n] = name;
        p = eq + 1;
        for (int c = 0; c < FS_NCOUNTERS; c++) {
            const char *end;
            if (!value(p, &end, &st->count[st->n][c])) return FS_ERR_INPUT;
            if (c + 1 < FS_NCOUNTERS && *end != ',') return FS_ERR_INPUT;
            p = c + 1 < FS_NCOUNTERS ? end + 1 : end;
        }
        st->n++;
        if (*p && *p != ';') return FS_ERR_INPUT;
    } while (*p && *++p); /* past the ';'; a trailing one leaves "" and fails below */
    if (p[-1] == ';') return FS_ERR_INPUT;
    for (int c = 0; c < FS_NCOUNTERS; c++) {
        uint64_t t;
        if (fs_stages_count_total(st, c, &t)) return FS_ERR_INPUT;
    }
    return FS_OK;
}
