/* libfluidsurf stays loaded for the life of the process (-Wl,-z,nodelete,
 * api/CMakeLists.txt): a program, or Python's cffi at interpreter exit, that
 * dlcloses it must not unmap it and its OpenMP runtime while OpenMP's workers
 * still spin in libgomp's code. Before the flag, the worker of the render below
 * (OMP_WAIT_POLICY=active: it spins after the region) died with SIGSEGV in the
 * unmapped libgomp during the sleep. The library comes from dlopen, not the link. */
#include "fluidsurf/fluidsurf.h"
#include "fs_test.h"
#include <dlfcn.h>
#include <stdlib.h>
#include <time.h>

#define N 64

/* fn: the symbol name of h, typed as the header declares it. */
#define SYM(h, fn) ((__typeof__(fn) *)dlsym((h), #fn))

/* A reference render of a small cube of particles (OpenMP regions on the CPU). */
static int render_once(void *h)
{
    static float x[N], y[N], z[N];
    for (int i = 0; i < N; i++) x[i] = 0.05f * (i % 4), y[i] = 0.05f * (i / 4 % 4), z[i] = 0.05f * (i / 16);
    fluidsurf_particles *p = NULL;
    fluidsurf_scene *s = NULL;
    fluidsurf_image *im = NULL;
    int rc = SYM(h, fluidsurf_particles_wrap)(N, x, y, z, &p);
    if (!rc) rc = SYM(h, fluidsurf_scene_new)(&s);
    if (!rc) rc = SYM(h, fluidsurf_scene_set_radius)(s, 0.025);
    if (!rc) rc = SYM(h, fluidsurf_scene_set_size)(s, 16, 16);
    if (!rc) rc = SYM(h, fluidsurf_reference)(s, p, &im);
    CHECK(!rc, "render: %s", SYM(h, fluidsurf_last_error)());
    SYM(h, fluidsurf_image_free)(im);
    SYM(h, fluidsurf_scene_free)(s);
    SYM(h, fluidsurf_particles_free)(p);
    return rc;
}

int main(void)
{
    setenv("OMP_WAIT_POLICY", "active", 1); /* read by libgomp when dlopen loads it */
    void *h = dlopen(FS_LIBRARY_PATH, RTLD_NOW | RTLD_LOCAL);
    CHECK(h, "dlopen %s: %s", FS_LIBRARY_PATH, dlerror());
    if (!h) TEST_DONE();
    CHECK(SYM(h, fluidsurf_api_version)() == FLUIDSURF_API_VERSION, "the API version of the built library");
    render_once(h);
    CHECK(dlclose(h) == 0, "dlclose: %s", dlerror());
    struct timespec pause = {0, 200 * 1000 * 1000}; /* the workers spin on, in libgomp */
    nanosleep(&pause, NULL);
    void *again = dlopen(FS_LIBRARY_PATH, RTLD_NOW | RTLD_NOLOAD);
    CHECK(again, "libfluidsurf was unloaded by dlclose (no -z nodelete)");
    CHECK(dlopen("libgomp.so.1", RTLD_NOW | RTLD_NOLOAD), "libgomp was unloaded with libfluidsurf");
    TEST_DONE();
}
