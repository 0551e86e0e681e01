/* The built-in methods, in the order `fluidsurf methods` lists them (and the
 * viewer's keys 1-9 pick them). Adding a method: its folder methods/NAME/ with
 * `const fs_method fs_method_NAME`, one line here, its shaders under
 * shaders/NAME/ (docs/DESIGN.md, "Adding a method"). */
#include "method.h"

#define BUILTIN_METHODS(X) \
    X(spheres)             \
    X(reference)           \
    X(raycast_pca)         \
    X(aniso_ssf)           \
    X(surfels)             \
    X(volume_raycast)

#define DECLARE(name) extern const fs_method fs_method_##name;
#define ENTRY(name) &fs_method_##name,
BUILTIN_METHODS(DECLARE)
static const fs_method *const builtin[] = {BUILTIN_METHODS(ENTRY)};

void fs_methods_register_builtin(void)
{
    for (size_t i = 0; i < sizeof builtin / sizeof *builtin; i++) fs_method_register(builtin[i], 0);
}
