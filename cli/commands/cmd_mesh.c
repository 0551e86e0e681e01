/* fluidsurf mesh: particles to triangle meshes, one file per frame, without
 * rendering: the mesh method's pipeline (methods/mesh/mesh_build.h) on its
 * parameters (--set mesh.P=V), as a drop-in for splashsurf's `reconstruct`
 * (a {} frame pattern in and out, a progress bar). */
#include "cli.h"
#include "frame_source.h"
#include "fs_error.h"
#include "method_params.h"
#include "mesh/mesh.h"
#include "mesh/mesh_export.h"
#include "options.h"
#include "particle_io.h"
#include "progress.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char epilogue[] =
    "IN is a scene .json (all its frames), a particle file, or a frame pattern with {} or %d\n"
    "(then --frames A:B). OUT is a .ply, .obj, .vtk or .vtp path; for several frames it needs\n"
    "{} or %d, replaced by the frame number. Parameters: fluidsurf methods mesh.\n"
    "splashsurf's recipe (weighted smoothing, Loeschner et al. 2023): --set mesh.smooth=weighted\n"
    "--set mesh.smooth_iters=25; --set mesh.attributes=on adds velocity and colour to .ply/.vtk/.vtp.\n"
    "--timings prints CSV: frame,stage,ms,vertices,triangles (counts on the total row).\n";

typedef struct mesh_job {
    fs_scene *scene;
    const double *params; /* the method's, in table order */
    fs_mesh_opts opts;    /* from params once the first frame has settled r */
    const char *out;      /* a pattern when there are several frames */
    int first, timings, quiet;
    float radius;
} mesh_job;

static void print_stages(int frame, const fs_stages *st, const fs_trimesh *m)
{
    double total = 0;
    for (int i = 0; i < st->n; i++) {
        printf("%d,%s,%.3f,,\n", frame, st->name[i], st->ms[i]);
        total += st->ms[i];
    }
    printf("%d,total,%.3f,%zu,%zu\n", frame, total, m->nv, m->nt);
    fflush(stdout);
}

/* One frame: load, grid, mesh, write. */
static int mesh_frame(mesh_job *j, int frame)
{
    fs_particles p;
    fs_stages st = {0};
    fs_grid g = {0};
    fs_trimesh m = {0};
    char path[4096];
    double t = fs_now_ms();
    int rc = fs_scene_load_frame(j->scene, frame, &p);
    if (rc) return rc;
    char note[1024] = "";
    if (frame == j->first) fs_scene_adopt_frame(j->scene, &p, j->radius, note, sizeof note);
    if (note[0] && !j->quiet) fs_note("%s", note);
    fs_stages_add(&st, "load", fs_now_ms() - t);
    fs_field f = fs_scene_field(j->scene);
    if (frame == j->first && (rc = fs_mesh_opts_from_values(j->params, &f, &j->opts))) {
        fs_particles_free(&p);
        return rc;
    }
    t = fs_now_ms();
    rc = fs_grid_build(&g, &p, f.H);
    fs_stages_add(&st, "grid", fs_now_ms() - t);
    if (!rc) rc = fs_mesh_build(&p, &g, &f, &j->opts, &m, &st);
    fs_grid_free(&g);
    fs_particles_free(&p);
    if (!rc)
        rc = fs_is_frame_pattern(j->out) ? fs_frame_path(path, sizeof path, j->out, frame)
                                         : (snprintf(path, sizeof path, "%s", j->out), FS_OK);
    t = fs_now_ms();
    fs_provenance prov;
    fs_mesh_provenance(&prov, j->scene, j->params, frame);
    if (!rc) rc = fs_mesh_export(&m, path, &prov);
    fs_stages_add(&st, "write", fs_now_ms() - t);
    if (!rc && j->timings) print_stages(frame, &st, &m);
    fs_trimesh_free(&m);
    return rc;
}

/* IN as a scene: a .json, a file, or a pattern with --frames. */
static int scene_of(const char *in, const char *frames, const cli_scene_opts *sopts, fs_scene *s)
{
    int rc = cli_scene_from_arg(s, in);
    if (rc) return cli_error(rc);
    if (s->up_source == FS_UP_AUTO) s->up_source = FS_UP_DEFAULT; /* a mesh has no up: no note */
    cli_scene_opts_apply(s, sopts);
    return cli_scene_pattern("mesh", s, in, frames);
}

int cmd_mesh(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *frames = NULL, *format = NULL;
    const char *sets[FS_MAX_SETS];
    int nsets = 0, timings = 0, quiet = 0, rc;
    static fs_scene scene;
    mesh_job j = {.scene = &scene};
    cli_scene_opts sopts = CLI_SCENE_OPTS_UNSET;
    const cli_opt opts[] = {
        CLI_OPT_OUT(out, "OUT.ply|.obj|.vtk|.vtp", "the mesh file (a {} pattern for several frames)"),
        CLI_OPT_SET(sets, nsets),
        CLI_OPT_RADIUS(j.radius,
                       "the scene's, else the file's, else estimated from\n"
                       "the particle spacing (a note says so; fluidsurf info shows it)"),
        CLI_OPT_FIELD(sopts),
        CLI_OPT_FRAMES(frames),
        CLI_STRING_OPT("--format", format, "FMT", "particle file format (default: from the extension)"),
        CLI_FLAG_OPT("--timings", timings, "print per-stage times and the mesh size (CSV on stdout)"),
        CLI_OPT_QUIET(quiet),
        CLI_END,
    };
    const cli_command cmd = {"mesh", "IN -o OUT.ply [options]", opts, {&in, NULL, 1, "more than one input"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    fs_note_quiet(quiet);
    if (!in) return cli_usage("mesh", "no scene or particle file given");
    if (!out) return cli_usage("mesh", "no output given (-o OUT.ply)");
    const fs_method *m = fs_method_find("mesh");
    if (!m) return cli_usage("mesh", "the mesh method is not registered");
    if (!fs_mesh_export_known(out))
        return cli_usage("mesh", "%s: unknown mesh format (the mesh exports %s)", out, FS_MESH_EXPORTS);
    if ((rc = scene_of(in, frames, &sopts, &scene))) return rc;
    if (format && strlen(format) < sizeof scene.format) strcpy(scene.format, format);
    int nframes = fs_scene_frame_count(&scene);
    j.first = fs_scene_frame_number(&scene, 0);
    if (nframes > 1 && !fs_is_frame_pattern(out)) return cli_usage("mesh", "%s: %d frames need {} in -o", out, nframes);
    if (cli_same_file(in, out)) return cli_usage("mesh", "%s: output would overwrite the input", out);
    for (int i = 0; i < nsets; i++)
        if ((rc = fs_scene_add_set(&scene, sets[i]))) return cli_error(rc);
    double params[FS_MAX_PARAMS];
    if ((rc = fs_method_params_resolve(m, &scene, params))) return cli_error(rc);
    if ((rc = cli_sets_run(sets, nsets, &m, 1))) return cli_error(rc);
    char opat[4096];
    if (fs_is_frame_pattern(out) && (rc = fs_frame_pattern(out, opat, sizeof opat))) return cli_error(rc);
    j.out = fs_is_frame_pattern(out) ? opat : out;
    j.timings = timings;
    j.quiet = quiet;
    if (timings) printf("frame,stage,ms,vertices,triangles\n");
    j.params = params;
    fs_progress_begin("mesh", "frames", nframes);
    for (int k = 0; k < nframes && !rc; k++) {
        int f = fs_scene_frame_number(&scene, k);
        char what[32];
        snprintf(what, sizeof what, "frame %d", f);
        if (!(rc = mesh_frame(&j, f))) fs_progress_item(what);
    }
    fs_progress_end();
    return rc ? cli_error(rc) : 0;
}
