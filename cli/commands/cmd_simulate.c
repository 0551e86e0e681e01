#include "cli.h"
#include "fs_error.h"
#include "gl_context.h"
#include "options.h"
#include "output_file.h"
#include "particle_io.h"
#include "progress.h"
#include "provenance.h"
#include "sph.h"
#include "timing.h"
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* what --help says after the options */
static const char epilogue[] =
    "SPH after Mueller et al. 2003 (inacio2010 section III). SCENE: dam_break, double_dam_break,\n"
    "drop, spouts (four coloured spouts filling a pool), pool (water at rest), or a JSON file\n"
    "{\"box\": [x, y, z], \"fluid\": [{\"min\": [..], \"max\": [..], \"color\": 0},\n"
    "{\"centre\": [..], \"radius\": R, \"color\": 1}], \"obstacles\": [{\"min\", \"max\"} |\n"
    "{\"centre\", \"radius\"} | {\"mesh\": \"closed.obj\", \"scale\", \"offset\"}]} in metres (colour\n"
    "ids 0..4); obstacles are static solids lined with two layers of boundary particles\n"
    "(without --particles: at the file's coordinates exactly).\n"
    "Writes frames 0..N, frame f being the state at t = f / fps (frame 0: the start).\n"
    "With --shake the container (walls and obstacles) moves along x, at rest at t = 0 and\n"
    "starting at speed 2 pi A / T; frames hold the fluid in world coordinates.\n"
    "-o may be left out when --stats is given. A run that diverges (NaN) stops with exit 1.\n";

typedef struct opts {
    const char *scene, *out, *stats;
    int frames, particles, gpu, substeps, quiet, require_gpu;
    float fps, dt, shake, shake_period; /* --shake: the container's x offset is shake sin(2 pi t / shake_period) */
    fs_ctx_kind ctx;
    fs_sph_params prm;
} opts;

static opts O; /* the command line (the table below fills it) */

static const cli_opt table[] = {
    CLI_INT_OPT("--frames", O.frames, 1, 1000000, "N", "frames to simulate (default 60)"),
    CLI_OPT_OUT(O.out, "PATTERN", "printf pattern of the frame files, one %d (e.g. out_%04d.bgeo)"),
    CLI_INT_OPT("--particles", O.particles, 64, 50000000, "N",
                "about N fluid particles (default: the scene's); the tank\ngrows with N at fixed r"),
    CLI_STORE_OPT("--cpu", O.gpu, 0, "simulate in C + OpenMP (default)"),
    CLI_STORE_OPT("--gpu", O.gpu, 1, "simulate with GL compute shaders on the --gl context"),
    CLI_OPT_GL(O.ctx),
    CLI_OPT_REQUIRE_GPU(O.require_gpu),
    CLI_CHOICE_OPT("--eos", O.prm.eos, "tait|ideal", ((const int[]){FS_SPH_TAIT, FS_SPH_IDEAL}),
                   "equation of state (default tait; ideal: p = k (rho - rho0))"),
    CLI_FLOAT_OPT("--fps", O.fps, 0.01, 100000, "F",
                  "frames per second (default 60); steps adapt to the CFL and\nviscosity bounds within each frame"),
    CLI_FLOAT_OPT(
        "--dt", O.dt, 1e-7, 10, "DT",
        "fixed steps instead: each frame is K (--substeps) steps of DT\nwhatever the bound; steps beyond it are counted"),
    CLI_INT_OPT("--substeps", O.substeps, 1, 100000, "K", "steps of DT per frame with --dt (default 1)"),
    CLI_OPT_RADIUS_IN(O.prm.r, 1e-5, 100, "0.025"),
    CLI_FLOAT_OPT("--nu", O.prm.nu, 0, 1000, "NU", "kinematic viscosity, m^2/s (default 0.05)"),
    CLI_FLOAT_OPT("--sound-speed", O.prm.c, 1e-3, 1e6, "C",
                  "speed of sound (default 10x the scene's expected peak speed)"),
    CLI_FLOAT_OPT("--k", O.prm.k, 1e-6, 1e12, "K", "ideal-gas constant (default C^2)"),
    CLI_FLOAT_OPT("--cfl", O.prm.cfl, 1e-4, 1, "L", "dt <= L H / (C + v_max) (default 0.2)"),
    CLI_FLOAT_OPT(
        "--shake", O.shake, 1e-6, 100, "A",
        "shake the container along x: its offset is A sin(2 pi t / T)\n(metres; a sloshing tank, its walls as wave makers)"),
    CLI_FLOAT_OPT("--shake-period", O.shake_period, 1e-3, 1e6, "T", "the shaking's period in seconds (default 1)"),
    CLI_STRING_OPT("--stats", O.stats, "FILE.csv", "per-frame record: steps, dt, bound, clamps, density error, depth"),
    CLI_OPT_QUIET(O.quiet),
    CLI_END,
};

static const cli_command command = {"simulate",
                                    "SCENE --frames N -o OUT_%04d.bgeo|.vtk|.ply|.vdb [options]",
                                    table,
                                    {&O.scene, NULL, 1, "more than one scene ('%s' and '%s')"},
                                    epilogue};

/* -o: a pattern of a format simulate writes, into a writable folder. */
static int check_output(const char *out)
{
    char path[4096], tmp[4200];
    int rc = fs_frame_path(path, sizeof path, out, 0);
    if (rc) return cli_error(rc);
    const char *fmt = fs_format_from_path(path);
    if (!fmt || (strcmp(fmt, "vtk") && strcmp(fmt, "bgeo") && strcmp(fmt, "ply") && strcmp(fmt, "vdb")))
        return cli_usage("simulate", "%s: output format must be .vtk, .bgeo, .ply or .vdb", out);
    if ((rc = fs_particles_writable(path, NULL))) return cli_error(rc);      /* before --stats is opened */
    if ((rc = fs_output_begin(path, tmp, sizeof tmp))) return cli_error(rc); /* folder exists and is writable */
    fs_output_end(path, tmp, 0);
    return FS_OK;
}

/* The options that need one another; fps and the fixed step settled. have_fps,
 * have_k: given (both are 0 unless given: their ranges exclude 0). */
static int check_options(opts *o, int have_fps, int have_k)
{
    if (!have_fps) o->fps = 60;
    if (!o->scene) return cli_usage("simulate", "no scene given (dam_break, double_dam_break, drop, spouts, pool)");
    if (!o->out && !o->stats) return cli_usage("simulate", "no output given (-o OUT_%%04d.bgeo or --stats FILE.csv)");
    if (o->substeps && !(o->dt > 0)) return cli_usage("simulate", "--substeps needs --dt");
    if (o->dt > 0 && have_fps)
        return cli_usage("simulate", "--fps and --dt exclude each other (a frame is K steps of DT)");
    if (have_k && o->prm.eos != FS_SPH_IDEAL) return cli_usage("simulate", "--k needs --eos ideal");
    if (o->shake_period > 0 && !(o->shake > 0)) return cli_usage("simulate", "--shake-period needs --shake");
    if (!(o->shake_period > 0)) o->shake_period = 1;
    if (o->dt > 0) {
        if (!o->substeps) o->substeps = 1;
        o->prm.fixed_dt = o->dt;
        o->fps = 1.0f / (o->dt * o->substeps);
    }
    return o->out ? check_output(o->out) : FS_OK;
}

static int parse(int argc, char **argv, opts *o)
{
    memset(o, 0, sizeof *o);
    fs_sph_params_default(&o->prm);
    o->frames = 60;
    o->ctx = fs_gl_context_default_kind();
    int rc = cli_parse(&command, argc, argv);
    if (rc != CLI_GO_ON) return rc ? rc : -1; /* -1: --help shown */
    return check_options(o, o->fps > 0, o->prm.k > 0);
}

/* Frame f-1 to f: the walls move by the change of the --shake offset over the
 * frame, spread over its steps (fs_sph_move_box), or stand still. */
static int advance(fs_sph *s, const opts *o, int f)
{
    double dt = 1.0 / o->fps;
    if (!(o->shake > 0)) return fs_sph_advance(s, dt);
    double w = 2 * M_PI / o->shake_period;
    float d[3] = {(float)(o->shake * (sin(w * f * dt) - sin(w * (f - 1) * dt))), 0, 0};
    return fs_sph_move_box(s, d, dt);
}

/* --stats' first line: the provenance line every CSV starts with (fs_provenance_line), with
 * the run's scene, counts and SPH parameters as further keys. */
static void write_stats_header(FILE *csv, const opts *o, const fs_sph *s, const fs_gl_context *ctx)
{
    const fs_sph_params *P = fs_sph_get_params(s);
    fs_provenance prov;
    char v[640], line[8192];
    fs_provenance_init_base(&prov, ctx ? ctx->renderer : "CPU (C + OpenMP)", ctx ? ctx->version : NULL);
    fs_provenance_set(&prov, "command", "simulate");
    fs_provenance_set(&prov, "scene", o->scene);
#define SET(key, fmt, val) (snprintf(v, sizeof v, fmt, val), fs_provenance_set(&prov, key, v))
    SET("fluid_particles", "%zu", fs_sph_count(s));
    SET("boundary_particles", "%zu", fs_sph_boundary_count(s));
    fs_provenance_set(&prov, "path", o->gpu ? "gpu" : "cpu");
    fs_provenance_set(&prov, "eos", P->eos == FS_SPH_TAIT ? "tait" : "ideal");
    SET("r", "%g", P->r);
    SET("H", "%g", P->support * P->r);
    SET("rho0", "%g", P->rho0);
    SET("mass", "%g", fs_sph_mass(s));
    SET("c", "%g", P->c);
    SET("nu", "%g", P->nu);
    SET("cfl", "%g", P->cfl);
    SET("fixed_dt", "%g", P->fixed_dt);
    SET("fps", "%g", o->fps);
    SET("shake", "%g", o->shake);
    SET("shake_period", "%g", o->shake_period);
#undef SET
    fs_provenance_line(&prov, line, sizeof line);
    fprintf(csv, "%s\n", line);
}

/* --stats: the CSV opened through its temporary file tmp, with its header lines. */
static int open_stats(const opts *o, const fs_sph *s, const fs_gl_context *ctx, FILE **csv, char *tmp, int size)
{
    int rc = fs_output_begin(o->stats, tmp, size);
    if (!rc && !(*csv = fopen(tmp, "w"))) {
        fs_output_end(o->stats, tmp, 0);
        rc = fs_fail(FS_ERR_INPUT, "%s: cannot write", o->stats);
    }
    if (rc) return rc;
    write_stats_header(*csv, o, s, ctx);
    fprintf(*csv,
            "frame,t,particles,steps,dt_min,dt_max,bound_min,violations,v_max,clamps,outside,density_err,"
            "density_abs_err,depth,depth_expected,kinetic,step_ms,frame_ms\n");
    return FS_OK;
}

/* The frame loop's state: the stats file and the counts at the frame before. */
typedef struct frame_loop {
    FILE *csv;
    long steps0;
    double step_ms0;
    int warned;
} frame_loop;

/* Frame f's particle file (-o). */
static int write_particles(fs_sph *s, const opts *o, int f)
{
    char path[4096];
    fs_particles p;
    int rc = fs_frame_path(path, sizeof path, o->out, f);
    if (!rc && !(rc = fs_sph_get(s, &p))) {
        rc = fs_particles_write(&p, path, NULL);
        fs_particles_free(&p);
    }
    return rc;
}

/* Frame f's row of --stats (written after a divergence too: it records it). */
static int stats_row(fs_sph *s, int f, double frame_ms, const frame_loop *L)
{
    const fs_sph_stats *st = fs_sph_get_stats(s);
    fs_sph_measure m;
    int rc = fs_sph_measure_state(s, &m);
    fprintf(L->csv, "%d,%.6f,%zu,%ld,%.4g,%.4g,%.4g,%ld,%.4g,%ld,%zu,%.5f,%.5f,%.5f,%.5f,%.5g,%.3f,%.3f\n", f, st->t,
            fs_sph_count(s), st->steps - L->steps0, st->dt_min, st->dt_max, st->bound_min, st->violations, st->v_max,
            st->clamps, m.outside, m.density_err, m.density_abs_err, m.depth, m.depth_expected, m.kinetic,
            st->step_ms - L->step_ms0, frame_ms);
    fflush(L->csv); /* long runs can be watched (in the hidden temporary file) */
    return rc;
}

/* Frame f: advanced (but the first), written, reported. */
static int one_frame(fs_sph *s, const opts *o, int f, frame_loop *L)
{
    double t0 = fs_now_ms();
    int rc = f > 0 ? advance(s, o, f) : FS_OK;
    double frame_ms = fs_now_ms() - t0;
    const fs_sph_stats *st = fs_sph_get_stats(s);
    if (o->out && !rc) rc = write_particles(s, o, f);
    if (L->csv) {
        int mrc = stats_row(s, f, frame_ms, L);
        if (mrc && !rc) rc = mrc;
    }
    if (st->violations && !L->warned) { /* the fixed step broke the bound: say so once */
        fs_note("fixed step %g s exceeds the CFL/viscosity bound (down to %.3g s) from frame %d on",
                fs_sph_get_params(s)->fixed_dt, st->bound_min, f);
        L->warned = 1;
    }
    L->steps0 = st->steps, L->step_ms0 = st->step_ms;
    if (rc) return rc;
    char what[160];
    snprintf(what, sizeof what, "frame %d, t = %.3f s, %ld steps (%ld beyond the bound), v_max %.2f m/s, clamps %ld", f,
             st->t, st->steps, st->violations, st->v_max, st->clamps);
    fs_progress_item(what);
    return FS_OK;
}

/* Every frame, then --stats closed (kept on a divergence too: it records it). */
static int run(fs_sph *s, const opts *o, FILE *csv, const char *stats_tmp)
{
    frame_loop L = {csv, 0, 0, 0};
    int rc = FS_OK;
    fs_progress_begin("simulate", "frames", o->frames + 1L);
    for (int f = 0; f <= o->frames && !rc; f++) rc = one_frame(s, o, f, &L);
    fs_progress_end();
    if (csv) {
        int bad = fclose(csv) != 0;
        int rc2 = fs_output_end(o->stats, stats_tmp, !bad);
        if (!rc && (bad || rc2)) rc = bad ? fs_fail(FS_ERR_RUNTIME, "%s: write failed", o->stats) : rc2;
    }
    return rc;
}

static void say_start(const opts *o, const fs_sph *s, const char *renderer)
{
    const fs_sph_params *P = fs_sph_get_params(s);
    if (!o->quiet)
        fprintf(stderr, "simulate %s: %zu fluid + %zu boundary particles on %s, %s, c = %.3g m/s, dt bound %.3g s\n",
                o->scene, fs_sph_count(s), fs_sph_boundary_count(s), o->gpu ? renderer : "the CPU",
                P->eos == FS_SPH_TAIT ? "Tait" : "ideal gas", P->c, fs_sph_dt_bound(s));
}

int cmd_simulate(int argc, char **argv)
{
    opts *o = &O;
    int rc = parse(argc, argv, o);
    if (rc) return rc < 0 ? 0 : rc;
    fs_note_quiet(o->quiet); /* before the context, whose renderer line -q silences */
    fs_gl_context_require_gpu(o->require_gpu);
    fs_gl_context ctx;
    if (o->gpu && (rc = cli_gl_context_create(&ctx, o->ctx, 16, 16))) return cli_error(rc);
    fs_sph *s = NULL;
    FILE *csv = NULL;
    char stats_tmp[4200] = "";
    rc = fs_sph_create(&s, o->scene, (size_t)o->particles, &o->prm, o->gpu);
    if (!rc && o->stats) rc = open_stats(o, s, o->gpu ? &ctx : NULL, &csv, stats_tmp, sizeof stats_tmp);
    if (!rc) {
        say_start(o, s, o->gpu ? ctx.renderer : "CPU (C + OpenMP)");
        rc = run(s, o, csv, stats_tmp);
    }
    if (s) fs_sph_destroy(s);
    if (o->gpu) fs_gl_context_destroy(&ctx);
    return rc ? cli_error(rc) : 0;
}
