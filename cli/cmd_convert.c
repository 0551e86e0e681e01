#include "cli.h"
#include "fs_error.h"
#include "particle_io.h"
#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: fluidsurf convert IN -o OUT [--from FMT] [--to FMT]\n"
    "Reads vtk, vtu, bgeo, ply, vdb, raw, csv; writes vtk (legacy binary), bgeo, ply, vdb.\n"
    "Formats come from the extensions unless given. OUT is written atomically.\n";

int cmd_convert(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *from = NULL, *to = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(help, stdout); return 0; }
        else if (!strcmp(a, "-o") && v) { out = v; i++; }
        else if (!strcmp(a, "--from") && v) { from = v; i++; }
        else if (!strcmp(a, "--to") && v) { to = v; i++; }
        else if (a[0] == '-' && a[1]) return cli_usage("convert", "unknown or incomplete option '%s'", a);
        else if (!in) in = a;
        else return cli_usage("convert", "more than one input");
    }
    if (!in) return cli_usage("convert", "no input file given");
    if (!out) return cli_usage("convert", "no output given (-o OUT)");
    if (cli_same_file(in, out)) return cli_usage("convert", "%s: output would overwrite the input", out);
    fs_particles p;
    int rc = fs_particles_read(&p, in, from);
    if (rc) return cli_error(rc);
    rc = fs_particles_write(&p, out, to);
    fs_particles_free(&p);
    return rc ? cli_error(rc) : 0;
}
