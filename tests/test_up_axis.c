/* The up-axis guess (up_axis.h) on real frames: the floor rule before the
 * format's convention. cube_2366 (shares at the low end x 7.7%, y 7.1%, z 7.7%)
 * keeps y; the SPlisHSPlasH dam breaks keep y; the shapes that stand on z = 0
 * get z, the BGEO one too; a frame turned z-up follows. Without the floor rule
 * the column, the hexecontahedron (Houdini's y) and the Hilbert cube get y. */
#include "fs_error.h"
#include "fs_test.h"
#include "particle_io.h"
#include "particle_stats.h"
#include "up_axis.h"
#include <stdlib.h>
#include <string.h>

/* The guess for p as fluidsurf makes it: r from the spacing. */
static int guess(const fs_particles *p, const char *path, char *why, int size)
{
    float r = 0;
    CHECK(fs_particles_estimate_radius(p, &r) == FS_OK, "%s: %s", path, fs_error_message());
    return fs_up_axis_guess(p, path, r, why, size);
}

/* The file's guess is axis, and its reason begins with reason. */
static void expect(const char *name, int axis, const char *reason)
{
    char path[512], why[200] = "";
    snprintf(path, sizeof path, "%s/splashsurf/%s", FS_TEST_DATA, name);
    fs_particles p;
    if (fs_particles_read(&p, path, NULL)) {
        CHECK(0, "%s: %s", name, fs_error_message());
        return;
    }
    int up = guess(&p, path, why, sizeof why);
    CHECK(up == axis && !strncmp(why, reason, strlen(reason)), "%s: up %c (%s), expected %c (%s...)", name, 'x' + up,
          why, 'x' + axis, reason);
    fs_particles_free(&p);
}

/* The dam break turned so that z is up (y -> z, z -> -y): the guess turns with it. */
static void turned(void)
{
    char path[512], why[200];
    snprintf(path, sizeof path, "%s/splashsurf/dam_break_frame_23_24389_particles.vtk", FS_TEST_DATA);
    fs_particles p;
    if (fs_particles_read(&p, path, NULL)) {
        CHECK(0, "%s", fs_error_message());
        return;
    }
    for (size_t i = 0; i < p.n; i++) {
        float y = p.y[i];
        p.y[i] = -p.z[i];
        p.z[i] = y;
    }
    fs_particles_bounds(&p);
    int up = guess(&p, "turned.ply", why, sizeof why);
    CHECK(up == 2 && strstr(why, "a floor"), "dam break turned z-up: up %c (%s)", 'x' + up, why);
    fs_particles_free(&p);
}

int main(void)
{
    expect("cube_2366_particles.vtk", 1, "no axis stands out");
    expect("dam_break_frame_23_24389_particles.vtk", 1, "a floor: ");
    expect("dam_break_frame_9_6859_particles.bgeo", 1, "a floor: ");
    expect("double_dam_break_frame_01_4732_particles.vtk", 1, "a floor: ");
    expect("double_dam_break_frame_26_4732_particles.vtk", 1, "a floor: ");
    expect("dual_dodec_41273_particles.vtk", 2, "a floor: ");
    expect("octocat_32614_particles.bgeo", 2, "a floor: ");
    expect("pentagonal_hexecontahedron_32286_particles.bgeo", 2, "a floor: ");
    expect("hilbert2_7954_particles.vtk", 2, "a floor at 0: ");
    turned();
    TEST_DONE();
}
