/* GLSL 450 programs from shaders/ (embedded at build time; with
 * FLUIDSURF_SHADER_DIR set, read from that folder instead, for editing).
 * `#include "common/x.glsl"` is expanded with #line markers, so a compile or
 * link error is reported as "shaders/FILE:LINE: driver message". */
#ifndef FS_SHADER_H
#define FS_SHADER_H
#ifdef __cplusplus
extern "C" {
#endif

/* Source text of shaders/NAME (malloc'd; NULL and fs_fail when missing). */
char *fs_shader_text(const char *name);
/* Builds a program from stage files whose names end in .vert.glsl, .geom.glsl,
 * .frag.glsl or .comp.glsl, NULL-terminated. defines ("NAME VALUE" lines, may be
 * NULL) are inserted after #version. Returns the program id, 0 on failure
 * (fs_fail set, FS_ERR_RUNTIME). */
unsigned fs_program_build(const char *const *stages, const char *defines);

#ifdef __cplusplus
}
#endif
#endif
