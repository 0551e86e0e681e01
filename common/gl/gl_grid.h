/* The block-sparse neighbour grid (grid.h) as shader storage buffers, read by
 * shaders/common/grid.glsl: the block keys (3 ints per stored block), the hash
 * table, start[ncells + 1] (uint) over cell slots, the near bits (a bit per cell
 * slot set when any of the 27 cells around it holds a particle: empty-space
 * skipping), the sorted positions in chunks of at most fs_gl_ssbo_chunk() vec4s,
 * and optional per-particle vec4 attributes in sorted order, chunked the same way. */
#ifndef FS_GL_GRID_H
#define FS_GL_GRID_H
#include "grid.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FS_GL_GRID_MAX_CHUNKS 4
/* SSBO bindings used by grid.glsl (keep equal to the #defines there). */
#define FS_GL_GRID_BINDING_START 8
#define FS_GL_GRID_BINDING_NEAR 9
#define FS_GL_GRID_BINDING_POS 10  /* 10 .. 13 */
#define FS_GL_GRID_BINDING_ATTR 14 /* 14 .. 17 */
#define FS_GL_GRID_BINDING_BKEY 18
#define FS_GL_GRID_BINDING_TABLE 19

typedef struct fs_gl_grid {
    unsigned start, near, bkey, table;
    unsigned pos[FS_GL_GRID_MAX_CHUNKS], attr[FS_GL_GRID_MAX_CHUNKS];
    int nchunks, has_attr;
    size_t chunk; /* particles per chunk */
    float origin[3], cell;
    int lo[3], hi[3]; /* range of the stored cells */
    unsigned table_mask;
} fs_gl_grid;

/* Uploads g (replacing what gg held). FS_ERR_INPUT when the set needs more
 * than FS_GL_GRID_MAX_CHUNKS chunks or start[] or the table exceeds one SSBO. */
int fs_gl_grid_upload(fs_gl_grid *gg, const fs_grid *g);
/* Uploads one vec4 per particle given in the ORIGINAL particle order (4n floats);
 * it is stored in the grid's sorted order. */
int fs_gl_grid_upload_attr(fs_gl_grid *gg, const fs_grid *g, const float *vec4s);
/* Binds the buffers and sets grid.glsl's uniforms on prog (made current). */
void fs_gl_grid_bind(const fs_gl_grid *gg, unsigned prog);
void fs_gl_grid_free(fs_gl_grid *gg);

#ifdef __cplusplus
}
#endif
#endif
