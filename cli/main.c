/* fluidsurf: command-line entry point; one file per subcommand (cli/commands/cmd_*.c,
 * the viewer in cli/view/). */
#include "caller_words.h"
#include "method.h"
#include "builtin_methods.h"
#include "cli.h"
#include "fs_error.h"
#include "interrupt.h"
#include "provenance.h"
#include <stdio.h>
#include <string.h>

static const struct {
    const char *name;
    int (*run)(int, char **);
    const char *what;
} commands[] = {
    {"render", cmd_render, "render one view of a scene or particle file with one method"},
    {"compare", cmd_compare, "render several methods on the same scene; metrics, timings, figures"},
    {"merge", cmd_merge, "join the shard folders of compare --shard K/N into one compare output"},
    {"report", cmd_report, "(re)write a study folder's report.html, the interactive comparison page"},
    {"diff", cmd_diff, "metrics between two EXR outputs, with thresholds for regression checks"},
    {"info", cmd_info, "print a particle file's count, bounds, spacing and density"},
    {"convert", cmd_convert, "convert a particle file to another format"},
    {"mesh", cmd_mesh, "mesh particles (a file, scene or {} sequence) into .ply/.obj/.vtk/.vtp files"},
    {"methods", cmd_methods, "list the methods, their papers and parameters"},
    {"simulate", cmd_simulate, "run the SPH simulator on a built-in scene; write a particle sequence"},
    {"view", cmd_view, "interactive window: play a scene or run the simulator live, switch methods"},
};

static int usage(FILE *f)
{
    fprintf(f, "usage: fluidsurf COMMAND [options]   (fluidsurf COMMAND --help for details)\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        fprintf(f, "  %-9s %s\n", commands[i].name, commands[i].what);
    fprintf(f, "\nexit status: 0 success, 1 runtime failure, 2 bad usage or input, 3 diff beyond thresholds\n");
    return f == stdout ? 0 : 2;
}

/* The command line's words for the settings that messages of common/ name (caller_words.h). */
static const fs_caller_word cli_words[] = {
    {"radius", "--radius"},
    {"up", "--up"},
    {"set", "--set"},
    {"counters", "--counters"},
    {"reference", "--reference"},
    {"import", "--import"},
    {"gl_egl", "--gl egl"},
    {"require_gpu", "--require-gpu"},
    {NULL, NULL},
};

int main(int argc, char **argv)
{
    fs_caller_words(cli_words);
    fs_methods_register_builtin();
    fs_interrupt_install();
    if (argc < 2) return usage(stderr);
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) return usage(stdout);
    if (!strcmp(argv[1], "--version")) {
        printf("fluidsurf %s (%s%s)\n", fs_version, fs_commit, fs_dirty ? "-dirty" : "");
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        if (!strcmp(argv[1], commands[i].name)) return commands[i].run(argc - 1, argv + 1);
    char name[200];
    fs_text_line(name, sizeof name, argv[1]);
    fprintf(stderr, "fluidsurf: unknown command '%s' (try 'fluidsurf --help')\n", name);
    return 2;
}
