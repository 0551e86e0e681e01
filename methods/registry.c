/* The built-in methods, in the order `fluidsurf methods` lists them (and the
 * viewer's keys 1-9 pick them). Adding a method: its folder methods/NAME/ with
 * `const fs_method fs_method_NAME`, one line here, its shaders under
 * shaders/NAME/ (docs/DESIGN.md, "Adding a method"). */
#include "registry.h"
#include <string.h>

#define BUILTIN_METHODS(X)                                                                                             \
    X(spheres)                                                                                                         \
    X(reference)                                                                                                       \
    X(raycast_pca)                                                                                                     \
    X(aniso_ssf)                                                                                                       \
    X(surfels)                                                                                                         \
    X(volume_raycast)                                                                                                  \
    OPENVDB_METHODS(X)

/* Methods that need an optional library: registered only in a build with it
 * (the lean build has none of them), and named by fs_method_needs_option. */
#if FS_WITH_OPENVDB
#define OPENVDB_METHODS(X) X(levelset) X(mesh)
#else
#define OPENVDB_METHODS(X)
#endif

#define DECLARE(name) extern const fs_method fs_method_##name;
#define ENTRY(name) &fs_method_##name,
BUILTIN_METHODS(DECLARE)
static const fs_method *const builtin[] = {BUILTIN_METHODS(ENTRY)};

void fs_methods_register_builtin(void)
{
    for (size_t i = 0; i < sizeof builtin / sizeof *builtin; i++) fs_method_register(builtin[i], 0);
}

const char *fs_method_needs_option(const char *name)
{
    static const struct {
        const char *method, *option;
        int built;
    } optional[] = {
        {"levelset", "FS_WITH_OPENVDB", FS_WITH_OPENVDB},
        {"mesh", "FS_WITH_OPENVDB", FS_WITH_OPENVDB},
    };
    for (size_t i = 0; name && i < sizeof optional / sizeof *optional; i++)
        if (!optional[i].built && !strcmp(name, optional[i].method)) return optional[i].option;
    return NULL;
}
