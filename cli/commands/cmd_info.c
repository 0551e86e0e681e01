#include "cli.h"
#include "particle_info.h"
#include "fs_error.h"
#include "options.h"
#include "particle_io.h"
#include "up_axis.h"
#include <stdio.h>

/* what --help says after the options */
static const char epilogue[] = "Prints the particle count, bounding box, attributes (and the file's other point\n"
                               "arrays, which convert writes), the radius the spacing implies\n"
                               "(used when neither the file nor --radius gives one), the median nearest-neighbour\n"
                               "distance and the median normalised density phi at particle centres (cubic spline,\n"
                               "support 4r), so you can choose r and volume_scale (phi should read ~1 inside).\n"
                               "The spacing and density are measured on a fixed sample of 4096 particles.\n";

static void print_info(const char *file, const fs_particles *p, const fs_particle_info *in)
{
    static const char *const source[] = {[FS_R_OPTION] = "--radius",
                                         [FS_R_FILE] = "from the file",
                                         [FS_R_ESTIMATED] = "estimated from the spacing; set --radius",
                                         [FS_R_DEFAULT] = "default; set --radius"};
    unsigned fields = fs_particles_fields(p);
    float r = in->radius;
    printf("file: %s\nparticles: %zu\n", file, p->n);
    printf("bbox min: %.6g %.6g %.6g\nbbox max: %.6g %.6g %.6g\n", p->bmin[0], p->bmin[1], p->bmin[2], p->bmax[0],
           p->bmax[1], p->bmax[2]);
    printf("attributes: position%s%s%s\n", fields & FS_HAS_VELOCITY ? " velocity" : "",
           fields & FS_HAS_COLOR ? " color" : "", fields & FS_HAS_PHASE ? " phase" : "");
    static char arrays[FS_ARRAYS_TEXT_SIZE];
    fs_particle_info_arrays(p, arrays, sizeof arrays);
    if (arrays[0]) printf("point arrays: %s\n", arrays);
    printf("radius r: %g (%s)\n", r, source[in->source]);
    if (in->estimated > 0) printf("radius the spacing implies: %.6g (%.3g r)\n", in->estimated, in->estimated / r);
    char why[200];
    double share[3];
    float r_up = in->estimated > 0 ? in->estimated : r; /* as render's auto reads it: the spacing's r */
    int up = fs_up_axis_guess(p, file, r_up, why, sizeof why);
    fs_up_low_end_shares(p, r_up, share);
    printf("up (auto): %c (%s)\n", 'x' + up, why);
    printf("within r of the low end: x %.1f%%, y %.1f%%, z %.1f%%\n", 100 * share[0], 100 * share[1], 100 * share[2]);
    printf("nearest-neighbour distance, median: %.6g (%.3g r)\n", in->st.nn_median, in->st.nn_median / r);
    printf("density phi at centres, median: %.4g (volume_scale %g, cubic, H = 4r); volume_scale %.3g would make it 1\n",
           in->st.density_median, in->volume_scale,
           in->st.density_median > 0 ? in->volume_scale / in->st.density_median : 0.0);
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
    fs_particle_info in;
    if (!(rc = fs_particle_info_compute(&p, radius, vscale, &in))) print_info(file, &p, &in);
    fs_particles_free(&p);
    return rc ? cli_error(rc) : 0;
}
