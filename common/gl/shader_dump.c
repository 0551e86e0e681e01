#include "shader_dump.h"
#include "hash.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* FNV-1a, folded to 32 bits: names a source by its text, so identical sources share one file. */
static uint32_t text_hash(const char *s)
{
    uint64_t h = fs_fnv1a(FS_FNV1A_BASIS, s, strlen(s));
    return (uint32_t)(h ^ h >> 32);
}

/* glslangValidator takes the stage from the last extension: ".vert.glsl" -> "vert". */
static const char *stage_ext(const char *stage)
{
    static const char *const ext[] = {"vert", "geom", "frag", "comp"};
    for (int i = 0; i < 4; i++) {
        char dot[8];
        snprintf(dot, sizeof dot, ".%s.", ext[i]);
        if (strstr(stage, dot)) return ext[i];
    }
    return "glsl";
}

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (!f || fputs(text, f) < 0) fprintf(stderr, "fluidsurf: FS_SHADER_DUMP: %s: cannot write\n", path);
    if (f) fclose(f);
}

void fs_shader_dump(const char *stage, const char *defines, const char *source, int first)
{
    static int program; /* this process's programs, counted */
    const char *dir = getenv("FS_SHADER_DUMP");
    if (!dir || !*dir) return;
    program += first != 0;
    char base[512], path[1024];
    snprintf(base, sizeof base, "%s", stage);
    for (char *p = base; *p; p++)
        if (*p == '/') *p = '_';
    char name[600];
    snprintf(name, sizeof name, "%s.%08x.%s", base, (unsigned)text_hash(source), stage_ext(stage));
    snprintf(path, sizeof path, "%s/%s", dir, name);
    write_file(path, source);
    /* one line, appended: several processes of one test may dump into the same folder */
    snprintf(path, sizeof path, "%s/index.tsv", dir);
    FILE *f = fopen(path, "a");
    if (!f) {
        fprintf(stderr, "fluidsurf: FS_SHADER_DUMP: %s: cannot write\n", path);
        return;
    }
    fprintf(f, "%s\t", stage);
    for (const char *d = defines ? defines : ""; *d; d++) fputc(*d == '\n' ? ';' : *d, f);
    fprintf(f, "\t%s\t%ld.%d\n", name, (long)getpid(), program);
    fclose(f);
}
