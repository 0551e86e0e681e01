/* Provenance of an output rendered from a scene: the base entries (version,
 * commit, renderer, threads) plus scene hash (a scene of a file or of command-line
 * options; the library's own scenes have none), source, seed, r, field, camera. */
#ifndef FS_SCENE_PROVENANCE_H
#define FS_SCENE_PROVENANCE_H
#include "provenance.h"
#include "scene.h"
#ifdef __cplusplus
extern "C" {
#endif

/* renderer: GL_RENDERER of the context that ran ("CPU" for CPU-only methods). */
void fs_provenance_init(fs_provenance *p, const fs_scene *s, const char *renderer, const char *gl_version);

#ifdef __cplusplus
}
#endif
#endif
