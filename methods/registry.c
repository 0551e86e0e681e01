/* The built-in methods, in the order `fluidsurf methods` lists them. Adding a
 * method: its folder under methods/, one line here, its shaders under shaders/NAME/
 * (docs/DESIGN.md, "Adding a method"). */
#include "method.h"

extern const fs_method fs_method_spheres;
extern const fs_method fs_method_reference;
extern const fs_method fs_method_raycast_pca;
extern const fs_method fs_method_aniso_ssf;
extern const fs_method fs_method_surfels;
extern const fs_method fs_method_volume_raycast;

static const fs_method *const builtin[] = {
    &fs_method_spheres,
    &fs_method_reference,
    &fs_method_raycast_pca,
    &fs_method_aniso_ssf,
    &fs_method_surfels,
    &fs_method_volume_raycast,
};

void fs_methods_register_builtin(void)
{
    for (size_t i = 0; i < sizeof builtin / sizeof *builtin; i++) fs_method_register(builtin[i], 0);
}
