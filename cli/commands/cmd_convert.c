#include "cli.h"
#include "frame_source.h"
#include "fs_error.h"
#include "options.h"
#include "particle_io.h"
#include "scene.h"
#include <stdio.h>
#include <string.h>

/* what --help says after the options */
static const char epilogue[] =
    "Reads vtk, vtu, bgeo, ply, vdb, raw, csv; writes vtk (legacy binary), bgeo, ply, vdb.\n"
    "Every other point array of a vtk, vtu, bgeo or ply file (ids, densities, ...) is written\n"
    "to vtk, bgeo and ply (bgeo: as float32 or int32); vdb keeps none (a note says so).\n"
    "Formats come from the extensions unless given. OUT is written atomically.\n"
    "IN may also be a scene .json: its first frame (a file or a synthetic shape) is written\n"
    "with the scene's r, e.g. to hand a synthetic set to another tool.\n";

/* The first frame of a scene file, with the scene's r (which a scene always sets). */
static int read_scene_frame(const char *path, fs_particles *p)
{
    static fs_scene s; /* large */
    int first, last, rc = fs_scene_load(&s, path);
    if (rc) return rc;
    fs_scene_frames(&s, &first, &last);
    if ((rc = fs_scene_load_frame(&s, first, p))) return rc;
    p->radius = s.radius;
    return FS_OK;
}

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
    size_t n = strlen(in);
    int scene = n > 5 && !strcmp(in + n - 5, ".json");
    if (scene && from) return cli_usage("convert", "--from: %s is a scene file", in);
    fs_particles p;
    rc = scene ? read_scene_frame(in, &p) : fs_particles_read(&p, in, from);
    if (rc) return cli_error(rc);
    const char *fmt = to ? to : fs_format_from_path(out);
    rc = fs_particles_write(&p, out, to);
    if (!rc && p.narrays && fmt && !strcmp(fmt, "vdb")) /* after the write: a refused .vdb drops nothing */
        fs_note("%s: .vdb keeps no point arrays: %d of %s not written (%s%s)", out, p.narrays, in, p.arrays[0].name,
                p.narrays > 1 ? ", ..." : "");
    fs_particles_free(&p);
    return rc ? cli_error(rc) : 0;
}
