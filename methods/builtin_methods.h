/* The built-in methods (methods/builtin_methods.c): the layer above method.h, which
 * only knows the registry, not which methods there are. */
#ifndef FS_BUILTIN_METHODS_H
#define FS_BUILTIN_METHODS_H
#include "method.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Registers the built-in table with fs_method_register (idempotent). */
void fs_methods_register_builtin(void);
/* For a built-in method this build leaves out (it needs an optional library):
 * the CMake option that builds it ("FS_WITH_OPENVDB"); NULL otherwise. */
const char *fs_method_needs_option(const char *name);

#ifdef __cplusplus
}
#endif
#endif
