/* Table-driven command-line options, after OpenImageIO's ArgParse: each entry
 * binds an option to the variable it fills, so one table both parses argv and
 * prints --help, and the two cannot drift apart. */
#ifndef FS_CLI_OPTIONS_H
#define FS_CLI_OPTIONS_H
#include <stdio.h>

typedef enum {
    CLI_FLAG,   /* no value: stores .value into *i */
    CLI_STRING, /* *s = the next argument */
    CLI_INT,    /* *i = an integer in [lo, hi] */
    CLI_FLOAT,  /* *f = a number in [lo, hi] */
    CLI_LIST,   /* s[(*n)++] = the next argument, repeatable up to hi times */
    CLI_CHOICE, /* *i = values[k] (or k) for the k-th of the words "a|b|c" */
} cli_kind;

typedef struct cli_opt {
    const char *name;  /* "-W", "--radius"; NULL ends a table */
    const char *alias; /* another spelling ("--width"), or NULL */
    cli_kind kind;
    int *i;            /* FLAG, INT, CHOICE */
    float *f;          /* FLOAT */
    const char **s;    /* STRING: the variable; LIST: the array */
    int *n;            /* LIST: entries so far */
    double lo, hi;     /* INT, FLOAT: the range; LIST: hi is the most entries */
    int value;         /* FLAG: what it stores */
    const char *words; /* CHOICE */
    const int *values; /* CHOICE: what each word stores (NULL: its index) */
    const char *meta;  /* the value's name in --help (CHOICE: the words) */
    const char *help;  /* '\n' continues it on an indented line */
} cli_opt;

#define CLI_FLAG_OPT(nm, var, hlp)                                                                                     \
    {                                                                                                                  \
        .name = nm, .kind = CLI_FLAG, .i = &(var), .value = 1, .help = hlp                                             \
    }
#define CLI_STORE_OPT(nm, var, val, hlp)                                                                               \
    {                                                                                                                  \
        .name = nm, .kind = CLI_FLAG, .i = &(var), .value = val, .help = hlp                                           \
    }
#define CLI_STRING_OPT(nm, var, mv, hlp)                                                                               \
    {                                                                                                                  \
        .name = nm, .kind = CLI_STRING, .s = &(var), .meta = mv, .help = hlp                                           \
    }
#define CLI_INT_OPT(nm, var, l, h, mv, hlp)                                                                            \
    {                                                                                                                  \
        .name = nm, .kind = CLI_INT, .i = &(var), .lo = l, .hi = h, .meta = mv, .help = hlp                            \
    }
#define CLI_FLOAT_OPT(nm, var, l, h, mv, hlp)                                                                          \
    {                                                                                                                  \
        .name = nm, .kind = CLI_FLOAT, .f = &(var), .lo = l, .hi = h, .meta = mv, .help = hlp                          \
    }
#define CLI_LIST_OPT(nm, arr, cnt, most, mv, hlp)                                                                      \
    {                                                                                                                  \
        .name = nm, .kind = CLI_LIST, .s = (arr), .n = &(cnt), .hi = most, .meta = mv, .help = hlp                     \
    }
/* var may be an enum; the array size turns negative, so compiling fails,
 * unless var has int's size */
#define CLI_CHOICE_OPT(nm, var, wds, vals, hlp)                                                                        \
    {                                                                                                                  \
        .name = nm, .kind = CLI_CHOICE, .i = (int *)&(var) + 0 * sizeof(char[sizeof(var) == sizeof(int) ? 1 : -1]),    \
        .words = wds, .values = vals, .help = hlp                                                                      \
    }
#define CLI_END                                                                                                        \
    {                                                                                                                  \
        .name = NULL                                                                                                   \
    }

/* The options that several commands share, defined once (--gl wants
 * gl_context.h, --set scene.h; --require-gpu goes to fs_gl_context_require_gpu). */
#define CLI_OPT_OUT(var, mv, hlp) CLI_STRING_OPT("-o", var, mv, hlp)
#define CLI_OPT_SIZE(wvar, hvar, lo_, hi_, what, dflt)                                                                 \
    {.name = "-W",                                                                                                     \
     .alias = "--width",                                                                                               \
     .kind = CLI_INT,                                                                                                  \
     .i = &(wvar),                                                                                                     \
     .lo = lo_,                                                                                                        \
     .hi = hi_,                                                                                                        \
     .meta = "N",                                                                                                      \
     .help = what " width in pixels (default: " dflt ")"},                                                             \
    {                                                                                                                  \
        .name = "-H", .alias = "--height", .kind = CLI_INT, .i = &(hvar), .lo = lo_, .hi = hi_, .meta = "N",           \
        .help = what " height in pixels (default: " dflt ")"                                                           \
    }
#define CLI_OPT_GL(var)                                                                                                \
    CLI_CHOICE_OPT("--gl", var, "osmesa|egl", ((const int[]){FS_CTX_OSMESA, FS_CTX_EGL}),                              \
                   "OpenGL context (default " FS_CTX_DEFAULT_NAME ", or FLUIDSURF_GL)")
#define CLI_OPT_REQUIRE_GPU(var)                                                                                       \
    CLI_FLAG_OPT("--require-gpu", var,                                                                                 \
                 "refuse a software OpenGL renderer (llvmpipe, ...): exit 1,\n"                                        \
                 "nothing written (or FLUIDSURF_REQUIRE_GPU=1)")
#define CLI_OPT_SET(arr, cnt)                                                                                          \
    CLI_LIST_OPT("--set", arr, cnt, FS_MAX_SETS, "M.P=V", "set a method parameter (repeatable)")
#define CLI_OPT_CACHE(var, hlp) CLI_STRING_OPT("--cache", var, "DIR", hlp)
#define CLI_OPT_QUIET(var) CLI_FLAG_OPT("-q", var, "quiet: no notes or progress on stderr")
#define CLI_OPT_RADIUS_IN(var, l, h, dflt)                                                                             \
    CLI_FLOAT_OPT("--radius", var, l, h, "R", "particle radius r (default: " dflt ")")
#define CLI_OPT_RADIUS(var, dflt) CLI_OPT_RADIUS_IN(var, 1e-9, 1e9, dflt)
/* The field and up axis over the scene's (cli_scene_opts in cli.h); mesh,
 * which has no camera, takes the field only. */
#define CLI_OPT_UP(o)                                                                                                  \
    CLI_CHOICE_OPT("--up", (o).up, "auto|x|y|z", ((const int[]){CLI_UP_AUTO, 0, 1, 2}),                                \
                   "the up axis (default: the scene's, else y; auto for a\n"                                           \
                   "particle file: its format's convention, else its thinnest\n"                                       \
                   "axis, the pile-up breaking ties; a note names it)")
#define CLI_OPT_FIELD(o)                                                                                               \
    CLI_FLOAT_OPT("--volume-scale", (o).volume_scale, 1e-6, 1e6, "S",                                                  \
                  "particle volume V = S (2r)^3 (default: the scene's, else 1)"),                                      \
        CLI_FLOAT_OPT("--iso", (o).iso, 1e-6, 1e6, "T",                                                                \
                      "iso value of the density field (default: the\n"                                                 \
                      "scene's, else 0.6)"),                                                                           \
        CLI_FLOAT_OPT("--support", (o).support, 0.5, 64, "K",                                                          \
                      "kernel support H = K r (default: the scene's,\n"                                                \
                      "else 4)"),                                                                                      \
        CLI_CHOICE_OPT("--kernel", (o).kernel, "cubic|poly6|spiky|wyvill", NULL,                                       \
                       "the field's kernel (default: the scene's, else cubic)")
#define CLI_OPT_SCENE(o) CLI_OPT_UP(o), CLI_OPT_FIELD(o)
#define CLI_OPT_CAMERA(text, from)                                                                                     \
    CLI_STRING_OPT("--camera", text, "'eye=X,Y,Z;target=X,Y,Z[;up=..][;fov=..]'",                                      \
                   "place the camera (up: x, y, z or X,Y,Z, default the\n"                                             \
                   "scene's up axis; fov in degrees; size=WxH too)"),                                                  \
        CLI_STRING_OPT("--camera-from", from, "FILE.exr",                                                              \
                       "the camera a fluidsurf EXR was rendered with, exactly\n"                                       \
                       "(its size too): the images can be diffed")
#define CLI_OPT_FRAMES(var)                                                                                            \
    CLI_STRING_OPT("--frames", var, "A:B[:STEP]",                                                                      \
                   "frames A to B (every STEP-th) of a frame pattern input\n"                                          \
                   "({} or %04d in its name)")

/* The positional arguments: up to max of them go to v[0..], counted in *n
 * (when n is given). too_many is the error's printf format; its arguments
 * are the first positional and the extra one, and it may use neither. */
typedef struct cli_args {
    const char **v;
    int *n;
    int max;
    const char *too_many;
} cli_args;

typedef struct cli_command {
    const char *name;    /* "render" */
    const char *usage;   /* after "usage: fluidsurf NAME "; '\n' starts another form */
    const cli_opt *opts; /* ends with CLI_END */
    cli_args args;
    const char *epilogue; /* printed after the options: what is not an option */
} cli_command;

/* cli_parse's "no reason to stop": any other value is the exit status. */
#define CLI_GO_ON (-1)

/* Parses argv[1..argc-1] against c. Returns CLI_GO_ON, 0 after printing
 * --help (-h), or 2 after a one-line usage error (cli_usage). */
int cli_parse(const cli_command *c, int argc, char **argv);
/* The --help text, generated from the table. */
void cli_help(const cli_command *c, FILE *f);

#endif
