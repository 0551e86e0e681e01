/* Resolves a method's parameter values: its defaults, then every
 * "method.param=value" of the scene and the command line, in order. */
#ifndef FS_METHOD_PARAMS_H
#define FS_METHOD_PARAMS_H
#include "method.h"
#include "provenance.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* A "METHOD.PARAM=VALUE" setting matched to a registered method and parameter. */
typedef struct fs_method_setting {
    const fs_method *m;
    int param;         /* index in m->params */
    const char *value; /* into the setting's text: everything after the '=' */
} fs_method_setting;

/* Splits text (fs_param_split) and finds its method and parameter; FS_ERR_INPUT
 * naming text when either is unknown. The value is not parsed. */
int fs_method_setting_find(const char *text, fs_method_setting *out);
/* Parses one value for the setting's parameter; errors name "METHOD.PARAM". */
int fs_method_setting_parse(const fs_method_setting *set, const char *value, double *out);

/* "a, b, c": the registered methods' names, and m's parameters' names (cut at size). */
void fs_method_names(char *buf, int size);
/* FS_ERR_INPUT (fs_fail): "[context: ]unknown method 'name' (methods: a, b, ...)",
 * the one wording of every caller that looks a method up by name. */
int fs_method_fail_unknown(const char *context, const char *name);
void fs_method_param_names(const fs_method *m, char *buf, int size);

/* The scene's resolver (fs_scene_set_resolver; the registry installs it): the setting's
 * method, parameter index and value, from its text; FS_ERR_INPUT naming the setting when
 * the method or parameter is unknown or the value bad. */
int fs_method_setting_resolve(fs_scene_setting *set);
/* m's values: its defaults, then each of the scene's settings for m, in order (each
 * resolved once, when it was added; a setting added before any method was registered is
 * resolved here, and refused like there). */
int fs_method_params_resolve(const fs_method *m, const fs_scene *s, double values[FS_MAX_PARAMS]);
/* "p=v;q=w" of every parameter (for provenance). */
void fs_method_params_string(const fs_method *m, const double *values, char *buf, int size);
/* Adds "method", "params" (fs_method_params_string) and "frame" to out: what
 * every output of method m made with these values records beside the scene's
 * provenance (renders, mesh files). */
void fs_method_provenance(fs_provenance *out, const fs_method *m, const double *values, int frame);

#ifdef __cplusplus
}
#endif
#endif
