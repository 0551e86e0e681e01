#include "options.h"
#include "cli.h"
#include <string.h>

static int is_named(const cli_opt *o, const char *a)
{
    return !strcmp(a, o->name) || (o->alias && !strcmp(a, o->alias));
}

static const cli_opt *find(const cli_opt *opts, const char *a)
{
    for (const cli_opt *o = opts; o->name; o++)
        if (is_named(o, a)) return o;
    return NULL;
}

/* "a|b|c" as "a, b or c", for the error message */
static void words_text(const char *words, char *buf, size_t size)
{
    const char *last = strrchr(words, '|');
    size_t n = 0;
    for (const char *w = words; *w && n + 5 < size; w++) {
        if (*w != '|') buf[n++] = *w;
        else n += (size_t)snprintf(buf + n, size - n, w == last ? " or " : ", ");
    }
    buf[n] = 0;
}

static int choose(const char *cmd, const cli_opt *o, const char *a, const char *v)
{
    int k = 0;
    for (const char *w = o->words; *w; k++) {
        size_t len = strcspn(w, "|");
        if (strlen(v) == len && !strncmp(w, v, len)) {
            *o->i = o->values ? o->values[k] : k;
            return 0;
        }
        w += len + (w[len] == '|');
    }
    char expected[200];
    words_text(o->words, expected, sizeof expected);
    return cli_usage(cmd, "%s %s: expected %s", a, v, expected);
}

/* Stores the value of option o, typed as a, whose next argument is v (NULL
 * when a is the last one). 0 or the usage error's exit status. */
static int take(const char *cmd, const cli_opt *o, const char *a, const char *v)
{
    /* numbers name a missing value themselves ("-W (missing): ...") */
    if (o->kind == CLI_INT) return cli_int(cmd, a, v, (int)o->lo, (int)o->hi, o->i);
    if (o->kind == CLI_FLOAT) return cli_float(cmd, a, v, o->lo, o->hi, o->f);
    if (o->kind == CLI_FLAG) {
        *o->i = o->value;
        return 0;
    }
    if (!v) return cli_usage(cmd, "unknown or incomplete option '%s'", a);
    if (o->kind == CLI_STRING) *o->s = v;
    else if (o->kind == CLI_CHOICE) return choose(cmd, o, a, v);
    else if (*o->n >= (int)o->hi) return cli_usage(cmd, "too many %s (at most %d)", o->name, (int)o->hi);
    else o->s[(*o->n)++] = v;
    return 0;
}

static int positional(const cli_command *c, int *n, const char *a)
{
    if (*n >= c->args.max) return cli_usage(c->name, c->args.too_many, c->args.max ? c->args.v[0] : a, a);
    c->args.v[(*n)++] = a;
    return 0;
}

int cli_parse(const cli_command *c, int argc, char **argv)
{
    int count = 0, *n = c->args.n ? c->args.n : &count, rc;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        const cli_opt *o = find(c->opts, a);
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            cli_help(c, stdout);
            return 0;
        }
        if (o) {
            if ((rc = take(c->name, o, a, v))) return rc;
            i += o->kind != CLI_FLAG;
        } else if (a[0] == '-' && a[1]) return cli_usage(c->name, "unknown or incomplete option '%s'", a);
        else if ((rc = positional(c, n, a))) return rc;
    }
    return CLI_GO_ON;
}

/* text, its continuation lines indented to column col */
static void put_indented(FILE *f, const char *text, int col)
{
    for (const char *t = text; *t; t++) {
        fputc(*t, f);
        if (*t == '\n') fprintf(f, "%*s", col, "");
    }
    fputc('\n', f);
}

/* "-W, --width N" */
static void label(const cli_opt *o, char *buf, size_t size)
{
    const char *meta = o->kind == CLI_CHOICE && !o->meta ? o->words : o->meta;
    snprintf(buf, size, "%s%s%s%s%s", o->name, o->alias ? ", " : "", o->alias ? o->alias : "", meta ? " " : "",
             meta ? meta : "");
}

void cli_help(const cli_command *c, FILE *f)
{
    const char *u = c->usage;
    for (int first = 1; *u; first = 0) {
        size_t len = strcspn(u, "\n");
        fprintf(f, "%s fluidsurf %s %.*s\n", first ? "usage:" : "      ", c->name, (int)len, u);
        u += len + (u[len] == '\n');
    }
    char buf[160];
    int width = (int)strlen("-h, --help");
    for (const cli_opt *o = c->opts; o->name; o++) {
        label(o, buf, sizeof buf);
        if ((int)strlen(buf) > width) width = (int)strlen(buf);
    }
    fprintf(f, "options:\n");
    for (const cli_opt *o = c->opts; o->name; o++) {
        label(o, buf, sizeof buf);
        fprintf(f, "  %-*s  ", width, buf);
        put_indented(f, o->help, width + 4);
    }
    fprintf(f, "  %-*s  this help\n", width, "-h, --help");
    if (c->epilogue) fputs(c->epilogue, f);
}
