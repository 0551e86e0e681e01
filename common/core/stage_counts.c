#include "stage_counts.h"
#include "fs_error.h"
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fs_stage_counts_format(const fs_stages *st, char *buf, int size)
{
    int n = snprintf(buf, size, "1:");
    for (int i = 0; i < st->n && n < size; i++) {
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
    static char names[64][32];
    static int n;
    for (int i = 0; i < n; i++)
        if (strlen(names[i]) == len && !strncmp(names[i], s, len)) return names[i];
    if (n == 64 || len >= sizeof names[0]) return NULL;
    memcpy(names[n], s, len);
    names[n][len] = 0;
    return names[n++];
}

int fs_stage_counts_parse(const char *text, fs_stages *st)
{
    memset(st, 0, sizeof *st);
    if (strncmp(text, "1:", 2)) return FS_ERR_INPUT;
    for (const char *p = text + 2; *p;) {
        const char *eq = strchr(p, '=');
        if (!eq || st->n == FS_MAX_STAGES || !(st->name[st->n] = intern(p, (size_t)(eq - p)))) return FS_ERR_INPUT;
        p = eq + 1;
        for (int c = 0; c < FS_NCOUNTERS; c++) {
            char *end;
            st->count[st->n][c] = strtoull(p, &end, 10);
            if (end == p || *end != (c + 1 < FS_NCOUNTERS ? ',' : *end == ';' ? ';' : 0)) return FS_ERR_INPUT;
            p = *end ? end + 1 : end;
        }
        st->n++;
    }
    return FS_OK;
}
