#include "cli.h"
#include "fs_error.h"
#include "options.h"
#include "particle_io.h"
#include <stdio.h>

/* what --help says after the options */
static const char epilogue[] =
    "Reads vtk, vtu, bgeo, ply, vdb, raw, csv; writes vtk (legacy binary), bgeo, ply, vdb.\n"
    "Formats come from the extensions unless given. OUT is written atomically.\n";

int cmd_convert(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *from = NULL, *to = NULL;
    const cli_opt opts[] = {
        CLI_OPT_OUT(out, "OUT", "the converted file"),
        CLI_STRING_OPT("--from", from, "FMT", "format of IN (default: from its extension)"),
        CLI_STRING_OPT("--to", to, "FMT", "format of OUT (default: from its extension)"),
        CLI_END,
    };
    const cli_command cmd = {"convert", "IN -o OUT [options]", opts, {&in, NULL, 1, "more than one input"}, epilogue};
    int rc = cli_parse(&cmd, argc, argv);
    if (rc != CLI_GO_ON) return rc;
    if (!in) return cli_usage("convert", "no input file given");
    if (!out) return cli_usage("convert", "no output given (-o OUT)");
    if (cli_same_file(in, out)) return cli_usage("convert", "%s: output would overwrite the input", out);
    fs_particles p;
    rc = fs_particles_read(&p, in, from);
    if (rc) return cli_error(rc);
    rc = fs_particles_write(&p, out, to);
    fs_particles_free(&p);
    return rc ? cli_error(rc) : 0;
}
