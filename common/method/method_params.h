/* Resolves a method's parameter values: its defaults, then every
 * "method.param=value" of the scene and the command line, in order. */
#ifndef FS_METHOD_PARAMS_H
#define FS_METHOD_PARAMS_H
#include "method.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* FS_ERR_INPUT when a setting names an unknown method or parameter, or a bad
 * value; settings for other methods are checked but not applied. */
int fs_method_params_resolve(const fs_method *m, const fs_scene *s, double values[FS_MAX_PARAMS]);
/* "p=v;q=w" of every parameter (for provenance). */
void fs_method_params_string(const fs_method *m, const double *values, char *buf, int size);

#ifdef __cplusplus
}
#endif
#endif
