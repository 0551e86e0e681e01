#include "shader.h"
#include "counters.h"
#include "fs_error.h"
#include "gl.h"
#include "gl_counters.h"
#include "shader_dump.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct fs_embedded_shader {
    const char *name;
    const char *text;
};
extern const struct fs_embedded_shader fs_embedded_shaders[];

char *fs_shader_text(const char *name)
{
    const char *dir = getenv("FLUIDSURF_SHADER_DIR");
    if (dir && *dir) {
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, name);
        FILE *f = fopen(path, "rb");
        if (!f) {
            fs_fail(FS_ERR_RUNTIME, "%s: cannot open shader (FLUIDSURF_SHADER_DIR)", path);
            return NULL;
        }
        fseek(f, 0, SEEK_END);
        long n = ftell(f);
        rewind(f);
        char *s = malloc(n + 1);
        if (s && fread(s, 1, n, f) == (size_t)n) s[n] = 0;
        else {
            free(s);
            s = NULL;
            fs_fail(FS_ERR_RUNTIME, "%s: cannot read shader", path);
        }
        fclose(f);
        return s;
    }
    for (const struct fs_embedded_shader *e = fs_embedded_shaders; e->name; e++)
        if (!strcmp(e->name, name)) return strdup(e->text);
    fs_fail(FS_ERR_RUNTIME, "shaders/%s: no such shader embedded", name);
    return NULL;
}

/* Growing string. */
typedef struct sbuf {
    char *s;
    size_t n, cap;
} sbuf;
static void sb_add(sbuf *b, const char *s, size_t n)
{
    if (b->n + n + 1 > b->cap) {
        b->cap = (b->n + n + 1) * 2;
        b->s = realloc(b->s, b->cap);
    }
    memcpy(b->s + b->n, s, n);
    b->n += n;
    b->s[b->n] = 0;
}

#define MAX_FILES 32
/* Where each line of the expanded source came from. No #line directives are
 * emitted: Mesa drops the source-string number from some diagnostics, so errors
 * are mapped back through this table instead, which works on every driver. */
typedef struct srcmap {
    int n;
    char name[MAX_FILES][256];
    int lines, cap;
    short *file; /* per expanded line: index into name, -1 for inserted lines */
    int *line;   /* per expanded line: line in that file */
} srcmap;

static void map_line(srcmap *m, int file, int line)
{
    if (m->lines == m->cap) {
        m->cap = m->cap ? 2 * m->cap : 256;
        m->file = realloc(m->file, m->cap * sizeof *m->file);
        m->line = realloc(m->line, m->cap * sizeof *m->line);
    }
    m->file[m->lines] = (short)file;
    m->line[m->lines++] = line;
}

/* Appends file `name` with includes expanded. defines go after the #version
 * line of the top file. */
static int expand(sbuf *out, const char *name, srcmap *map, const char *defines, int depth)
{
    if (depth > 8 || map->n == MAX_FILES) return fs_fail(FS_ERR_RUNTIME, "shaders/%s: includes nested too deep", name);
    char *text = fs_shader_text(name);
    if (!text) return FS_ERR_RUNTIME;
    int id = map->n++;
    snprintf(map->name[id], sizeof map->name[id], "%s", name);
    int line = 1;
    for (char *p = text; *p; line++) {
        char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        char inc[256];
        if (sscanf(p, " #include \"%255[^\"]\"", inc) == 1) {
            int rc = expand(out, inc, map, NULL, depth + 1);
            if (rc) {
                free(text);
                return rc;
            }
        } else {
            sb_add(out, p, len);
            sb_add(out, "\n", 1);
            map_line(map, id, line);
            if (!depth && !strncmp(p, "#version", 8) && defines) {
                for (const char *d = defines; *d;) {
                    const char *e = strchr(d, '\n');
                    size_t dl = e ? (size_t)(e - d) : strlen(d);
                    sb_add(out, "#define ", 8);
                    sb_add(out, d, dl);
                    sb_add(out, "\n", 1);
                    map_line(map, -1, 0);
                    d += dl + (e ? 1 : 0);
                }
            }
        }
        p += len + (nl ? 1 : 0);
    }
    free(text);
    return FS_OK;
}

/* Rewrites the first error line of a driver log ("0:12(3): error: ..." from
 * Mesa, "0(12) : error ..." from NVIDIA) as "shaders/FILE:LINE: message". */
static void report(const char *what, const char *log, const srcmap *map)
{
    const char *p = log;
    while (*p) {
        int file = 0, line = 0, used = 0;
        if ((sscanf(p, "%d:%d(%*d): %n", &file, &line, &used) == 2 && used) ||
            (sscanf(p, "%d(%d) : %n", &file, &line, &used) == 2 && used)) {
            const char *end = strchr(p, '\n');
            int len = end ? (int)(end - p - used) : (int)strlen(p + used);
            const char *fname = "(inserted #define)";
            int src_line = line;
            if (line >= 1 && line <= map->lines && map->file[line - 1] >= 0) {
                fname = map->name[map->file[line - 1]];
                src_line = map->line[line - 1];
            }
            fs_fail(FS_ERR_RUNTIME, "shaders/%s:%d: %.*s", fname, src_line, len, p + used);
            return;
        }
        const char *nl = strchr(p, '\n');
        if (!nl) break;
        p = nl + 1;
    }
    const char *nl = strchr(log, '\n');
    fs_fail(FS_ERR_RUNTIME, "%s: %.*s", what, nl ? (int)(nl - log) : (int)strlen(log), log);
}

static GLenum stage_type(const char *name)
{
    if (strstr(name, ".vert.")) return GL_VERTEX_SHADER;
    if (strstr(name, ".geom.")) return GL_GEOMETRY_SHADER;
    if (strstr(name, ".frag.")) return GL_FRAGMENT_SHADER;
    if (strstr(name, ".comp.")) return GL_COMPUTE_SHADER;
    return 0;
}

/* defines, plus the counter defines while counting (gl_counters.h): the
 * counting render's programs are variants, the timed render's are untouched. */
static char *with_counters(const char *defines)
{
    if (!fs_counting) return defines ? strdup(defines) : NULL;
    const char *cd = fs_gl_counter_defines();
    size_t n = (defines ? strlen(defines) + 1 : 0) + strlen(cd) + 1;
    char *s = malloc(n);
    if (s) snprintf(s, n, "%s%s%s", defines ? defines : "", defines ? "\n" : "", cd);
    return s;
}

/* Stage `name` expanded (includes, defines) and compiled into *sh; an error
 * names the file and line of the source it came from. */
static int compile_stage(const char *name, int first, const char *defines, srcmap *map, GLuint *sh)
{
    GLenum type = stage_type(name);
    if (!type) return fs_fail(FS_ERR_RUNTIME, "shaders/%s: unknown shader stage", name);
    sbuf src = {0};
    map->n = map->lines = 0;
    int rc = expand(&src, name, map, defines, 0);
    if (rc) {
        free(src.s);
        return rc;
    }
    fs_shader_dump(name, defines, src.s, first);
    GLuint s = *sh = glCreateShader(type);
    const char *text = src.s;
    glShaderSource(s, 1, &text, NULL);
    glCompileShader(s);
    free(src.s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (ok) return FS_OK;
    char log[4096] = "";
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    if (getenv("FS_SHADER_DEBUG")) fprintf(stderr, "%s\n", log);
    report(name, log, map);
    return FS_ERR_RUNTIME;
}

/* The program linked; a link error names the first stage. */
static int link_program(GLuint prog, const char *first)
{
    glLinkProgram(prog);
    GLint ok = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (ok) return FS_OK;
    char log[4096] = "";
    glGetProgramInfoLog(prog, sizeof log, NULL, log);
    char *nl = strchr(log, '\n');
    if (nl) *nl = 0;
    return fs_fail(FS_ERR_RUNTIME, "shaders/%s: link error: %s", first, log);
}

unsigned fs_program_build(const char *const *stages, const char *defines_in)
{
    char *defines = with_counters(defines_in);
    GLuint prog = glCreateProgram(), sh[8];
    int nsh = 0, rc = FS_OK;
    srcmap map = {0};
    for (int i = 0; stages[i] && nsh < 8 && !rc; i++) {
        GLuint s = 0;
        rc = compile_stage(stages[i], i == 0, defines, &map, &s);
        if (s) sh[nsh++] = s;
        if (!rc) glAttachShader(prog, s);
    }
    if (!rc) rc = link_program(prog, stages[0]);
    free(defines);
    free(map.file);
    free(map.line);
    for (int i = 0; i < nsh; i++) glDeleteShader(sh[i]);
    if (rc) glDeleteProgram(prog);
    return rc ? 0 : prog;
}
