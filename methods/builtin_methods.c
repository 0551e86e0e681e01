/* The built-in methods, in the order `fluidsurf methods` lists them (and the
 * viewer's keys 1-9 pick them). Adding a method: its folder methods/NAME/ with
 * `const fs_method fs_method_NAME`, one line here, its shaders under
 * shaders/NAME/ (docs/DESIGN.md, "Adding a method"); one that needs an optional
 * library goes into FS_OPTIONAL_METHODS (methods/CMakeLists.txt) instead. */
#include "builtin_methods.h"
#include "optional_methods.h" /* FS_OPTIONAL_BUILT, FS_OPTIONAL_METHODS_TABLE: methods/CMakeLists.txt */
#include <string.h>

#define BUILTIN_METHODS(X)                                                                                             \
    X(spheres)                                                                                                         \
    X(reference)                                                                                                       \
    X(raycast_pca)                                                                                                     \
    X(aniso_ssf)                                                                                                       \
    X(surfels)                                                                                                         \
    X(volume_raycast)                                                                                                  \
    FS_OPTIONAL_BUILT(X) /* the methods of an optional library this build has (the lean build: none) */

#define DECLARE(name) extern const fs_method fs_method_##name;
#define ENTRY(name) &fs_method_##name,
BUILTIN_METHODS(DECLARE)
static const fs_method *const builtin[] = {BUILTIN_METHODS(ENTRY)};

void fs_methods_register_builtin(void)
{
    for (size_t i = 0; i < sizeof builtin / sizeof *builtin; i++) fs_method_register(builtin[i], 0);
}

static int built_in(const char *name)
{
    for (size_t i = 0; i < sizeof builtin / sizeof *builtin; i++)
        if (!strcmp(builtin[i]->name, name)) return 1;
    return 0;
}

const char *fs_method_needs_option(const char *name)
{
    static const struct {
        const char *method, *option;
    } optional[] = {FS_OPTIONAL_METHODS_TABLE};
    for (size_t i = 0; name && i < sizeof optional / sizeof *optional; i++)
        if (!strcmp(name, optional[i].method) && !built_in(name)) return optional[i].option;
    return NULL;
}
