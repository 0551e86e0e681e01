#include "cli.h"
#include "particle_stats.h"
#include "fs_error.h"
#include "options.h"
#include "particle_io.h"
#include "up_axis.h"
#include <stdio.h>

/* what --help says after the options */
static const char epilogue[] = "Prints the particle count, bounding box, attributes, the radius the spacing implies\n"
                               "(used when neither the file nor --radius gives one), the median nearest-neighbour\n"
                               "distance and the median normalised density phi at particle centres (cubic spline,\n"
                               "support 4r), so you can choose r and volume_scale (phi should read ~1 inside).\n"
                               "The spacing and density are measured on a fixed sample of 4096 particles.\n";

/* What info prints of the particles p read from file: s->radius is the r it uses, est the
 * spacing's (0: none), radius the one --radius gave (0: none). */
static void print_info(const char *file, const fs_particles *p, const fs_scene *s, float radius, float est,
                       float vscale, const fs_particle_stats *st)
{
    unsigned fields = fs_particles_fields(p);
    printf("file: %s\nparticles: %zu\n", file, p->n);
    printf("bbox min: %.6g %.6g %.6g\nbbox max: %.6g %.6g %.6g\n", p->bmin[0], p->bmin[1], p->bmin[2], p->bmax[0],
           p->bmax[1], p->bmax[2]);
    printf("attributes: position%s%s%s\n", fields & FS_HAS_VELOCITY ? " velocity" : "",
           fields & FS_HAS_COLOR ? " color" : "", fields & FS_HAS_PHASE ? " phase" : "");
    printf("radius r: %g (%s)\n", s->radius,
           radius > 0          ? "--radius"
               : p->radius > 0 ? "from the file"
               : est > 0       ? "estimated from the spacing; set --radius"
                               : "default; set --radius");
    if (est > 0) printf("radius the spacing implies: %.6g (%.3g r)\n", est, est / s->radius);
    char why[200];
    double share[3];
    float r_up = est > 0 ? est : s->radius; /* as render's auto reads it: the spacing's r */
    int up = fs_up_axis_guess(p, file, r_up, why, sizeof why);
    fs_up_low_end_shares(p, r_up, share);
    printf("up (auto): %c (%s)\n", 'x' + up, why);
    printf("within r of the low end: x %.1f%%, y %.1f%%, z %.1f%%\n", 100 * share[0], 100 * share[1], 100 * share[2]);
    printf("nearest-neighbour distance, median: %.6g (%.3g r)\n", st->nn_median, st->nn_median / s->radius);
    printf("density phi at centres, median: %.4g (volume_scale %g, cubic, H = 4r); volume_scale %.3g would make it 1\n",
           st->density_median, vscale, st->density_median > 0 ? vscale / st->density_median : 0.0);
}

int cmd_info(int argc, char **argv)
{
    const char *file = NULL, *format = NULL;
    float radius = 0, vscale = 1;
    int rc;
    const cli_opt opts[] = {
        CLI_OPT_RADIUS(radius, "the file's, else estimated from the spacing"),
        CLI_FLOAT_OPT("--volume-scale", vscale, 1e-6, 1e6, "S", "particle volume V = S (2r)^3 (default 1)"),
        CLI_STRING_OPT("--format", format, "FMT", "particle file format (default: from the extension)"),
        CLI_END,
    };
    const cli_command cmd = {"info", "FILE [options]", opts, {&file, NULL, 1, "more than one file"}, epilogue};
    if ((rc = cli_parse(&cmd, argc, argv)) != CLI_GO_ON) return rc;
    if (!file) return cli_usage("info", "no particle file given");
    fs_particles p;
    if ((rc = fs_particles_read(&p, file, format))) return cli_error(rc);
    float est = 0;
    /* No spacing to measure (many coincident particles) is an error only when nothing
     * else gives a radius: a simulator's clamp can pile particles on one point. */
    if ((rc = fs_particles_estimate_radius(&p, &est)) && p.n > 1 && !(radius > 0 || p.radius > 0)) {
        fs_particles_free(&p);
        return cli_error(rc);
    }
    if (rc) fs_error_clear();
    fs_scene s;
    fs_scene_defaults(&s);
    s.radius = radius > 0 ? radius : p.radius > 0 ? p.radius : est > 0 ? est : s.radius;
    s.volume_scale = vscale;
    fs_field f = fs_scene_field(&s);
    fs_particle_stats st;
    rc = fs_particles_stats(&p, &f, &st);
    if (!rc) print_info(file, &p, &s, radius, est, vscale, &st);
    fs_particles_free(&p);
    return rc ? cli_error(rc) : 0;
}
