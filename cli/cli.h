/* Shared pieces of the subcommands. */
#ifndef FS_CLI_H
#define FS_CLI_H
#include "gl_context.h"
#include "method.h"
#include "scene.h"

int cmd_render(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_convert(int argc, char **argv);
int cmd_methods(int argc, char **argv);
int cmd_compare(int argc, char **argv);
int cmd_diff(int argc, char **argv);
int cmd_simulate(int argc, char **argv);
int cmd_view(int argc, char **argv);
int cmd_mesh(int argc, char **argv);
int cmd_merge(int argc, char **argv);
int cmd_report(int argc, char **argv);

/* Prints "fluidsurf: MESSAGE" and returns code. */
int cli_error(int code);
/* Usage error: "fluidsurf: MESSAGE" + "try 'fluidsurf CMD --help'", returns 2. */
int cli_usage(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A method name the registry does not know: one line, FS_ERR_INPUT. It names the
 * CMake option when this build leaves a built-in method out ("--method levelset
 * needs a build with FS_WITH_OPENVDB=ON"), else it is cli_usage's "unknown method". */
int cli_unknown_method(const char *cmd, const char *option, const char *name);
/* Every --set of the command line (sets, already checked to name a method and
 * parameter) must be for one of the nrun methods that run: else FS_ERR_INPUT
 * (fs_fail) in one line naming the setting and the methods that run. */
int cli_sets_run(const char *const *sets, int nsets, const fs_method *const *run, int nrun);
/* A scene from SCENE.json, or a default scene around a particle file (its up
 * axis auto: the first frame decides). */
int cli_scene_from_arg(fs_scene *s, const char *arg);
/* IN's frames, after cli_scene_from_arg: a frame pattern (not a .json) needs
 * frames ("A:B[:STEP]", cmd's --frames), a file or a scene file refuses them;
 * one usage line (exit 2) when they do not fit. */
int cli_scene_pattern(const char *cmd, fs_scene *s, const char *in, const char *frames);
/* --camera TEXT or --camera-from FILE.exr (either, or neither): places s's
 * camera, its size too; one usage line (exit 2) when malformed. */
int cli_scene_camera(const char *cmd, fs_scene *s, const char *text, const char *from);
/* --up, --volume-scale, --iso, --support, --kernel (CLI_OPT_SCENE): set ones
 * win over the scene file's; unset ones are -1 (up, kernel) or 0. */
enum { CLI_UP_AUTO = 3 };
typedef struct cli_scene_opts {
    int up, kernel;
    float volume_scale, iso, support;
} cli_scene_opts;
#define CLI_SCENE_OPTS_UNSET                                                                                           \
    {                                                                                                                  \
        .up = -1, .kernel = -1                                                                                         \
    }
/* Applies the set options to s, and folds them into its hash (a different
 * field is a different scene to diff and the caches). */
void cli_scene_opts_apply(fs_scene *s, const cli_scene_opts *o);
/* Parses a positive integer / float option value; 2 on error. */
int cli_int(const char *cmd, const char *opt, const char *text, int lo, int hi, int *out);
int cli_float(const char *cmd, const char *opt, const char *text, double lo, double hi, float *out);
/* fs_gl_context_create, then on EGL one note naming the renderer and the device,
 * "fluidsurf: note: OpenGL: NVIDIA H200/PCIe/SSE2 (EGL device 0 of 1)", once per
 * process and not under -q (fs_note_quiet): on a machine that is not ours it says
 * what the run rendered on. OSMesa is always llvmpipe, so it says nothing. */
int cli_gl_context_create(fs_gl_context *c, fs_ctx_kind kind, int width, int height);
/* 1 when a and b name the same existing file. */
int cli_same_file(const char *a, const char *b);

#endif
