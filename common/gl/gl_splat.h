/* The compute splatter: the sprite passes of the sprite-splatting methods
 * (spheres, raycast_pca's entry and thickness, aniso_ssf's ellipsoids) in
 * compute shaders instead of the raster pipeline (docs/DESIGN.md, "The compute
 * splatter"). The sprites are the raster's: the same bounds, the same
 * per-pixel ray-sphere or ray-ellipsoid hit and chord (shaders/common/
 * sprite_shape.glsl builds on the raster's own functions), so the G-buffer is
 * the raster's:
 *   depth      one atomicMin per covered pixel on the hit's window depth bits
 *              (a non-negative float orders like its bits), then the index of
 *              the sprite that reached the minimum (atomicMin again: the first
 *              drawn wins a tie, as under GL_LESS), then a per-pixel resolve
 *              that writes the winner's eye depth and normal. Where the GL has
 *              GL_NV_shader_atomic_int64 and GL_ARB_gpu_shader_int64 (checked
 *              at run time; llvmpipe has only the second), one atomicMin of the
 *              64-bit key (depth bits << 32 | index) replaces the first two.
 *   thickness  a fixed-point atomicAdd per covered pixel into a 64-bit sum of
 *              two 32-bit words (the low word's carry goes into the high one):
 *              exact and independent of the order of the adds, unlike float
 *              blending. See FS_SPLAT_QUANTUM_BITS for why it cannot overflow.
 * Each sprite walks its footprint in one invocation, or, above `large_px`
 * footprint pixels (0: never), is listed and split over a 64-invocation
 * workgroup. */
#ifndef FS_GL_SPLAT_H
#define FS_GL_SPLAT_H
#include "camera.h"
#include "gl_target.h"
#include "params.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* The `splat` parameter: which hardware path draws the sprites. compute takes
 * the 64-bit depth pass where the GL has it, compute32 never does. */
typedef enum { FS_SPLAT_RASTER, FS_SPLAT_COMPUTE, FS_SPLAT_COMPUTE32 } fs_splat_path;
/* How the sprites are stored: spheres as packed float triples or vec4
 * positions, or ellipsoids as 3 vec4 (centre; anisotropy matrix). */
typedef enum { FS_SPRITE_XYZ, FS_SPRITE_XYZW, FS_SPRITE_ELLIPSOID } fs_sprite_shape;

/* The default footprint (pixels) above which a sprite is split over a
 * workgroup; 0: never. On llvmpipe one invocation walking its sprite's
 * footprint was faster than the split at every footprint tried, 150 to 95,000
 * pixels (single-thread CPU time, not committed); a GPU's switch point is
 * still to be measured on a device. */
#define FS_SPLAT_LARGE_PX 0
/* The thickness sum's unit is 2^-FS_SPLAT_QUANTUM_BITS of the sprite radius R
 * (rounded down to a power of two): 6e-8 R, below a float's precision at one
 * chord. A pixel's sum is a 64-bit integer, so it holds 2^40 R: 142M sprites
 * overflow it only if their chords through one pixel average above 7,700 R,
 * while a chord is at most 2 R times the largest stretch of an ellipsoid. A
 * wrap is detected all the same and fails the pass. */
#define FS_SPLAT_QUANTUM_BITS 24

/* The parameter rows of every method with a compute splatter; its parameter
 * struct holds `fs_splat_path splat; int splat_large_px;`. */
#define FS_SPLAT_PARAM_DEFS(T)                                                                                         \
    {FS_PARAM_FIELD(T, splat),                                                                                         \
     FS_PARAM_ENUM,                                                                                                    \
     FS_SPLAT_RASTER,                                                                                                  \
     0,                                                                                                                \
     2,                                                                                                                \
     "raster|compute|compute32",                                                                                       \
     "how the sprites are splatted: the raster pipeline (the paper's), or compute shaders (64-bit atomics where the "  \
     "GL has them; compute32: never): the same image"},                                                                \
    {                                                                                                                  \
        FS_PARAM_FIELD(T, splat_large_px), FS_PARAM_INT, FS_SPLAT_LARGE_PX, 0, 1e9, NULL,                              \
            "splat=compute: a sprite covering more pixels is split over a workgroup (0: never)"                        \
    }

/* n sprites in GL buffers of `chunk` sprites each (the last may hold fewer). */
typedef struct fs_sprite_bufs {
    const unsigned *bufs;
    int nbufs;
    size_t chunk, n;
} fs_sprite_bufs;

typedef struct fs_gl_splat {
    fs_sprite_shape shape;
    int int64; /* the depth pass is one 64-bit atomicMin */
    unsigned large_px;
    float subpixel; /* 2^GL_SUBPIXEL_BITS */
    unsigned prog_depth, prog_index, prog_thick, prog_resolve_depth, prog_resolve_thick;
    unsigned buf_key, buf_win, buf_thick, buf_list, buf_args;
    int w, h;
    size_t list_cap;
} fs_gl_splat;

/* 1 when the current context has 64-bit atomics on storage buffers. */
int fs_gl_has_atomic_int64(void);
/* Builds the programs of path (FS_SPLAT_COMPUTE or FS_SPLAT_COMPUTE32) for the
 * shape; FS_OK, or FS_ERR_RUNTIME with fs_fail set (s is then empty). */
int fs_gl_splat_init(fs_gl_splat *s, fs_splat_path path, fs_sprite_shape shape, int large_px);
void fs_gl_splat_free(fs_gl_splat *s);
/* The timings' stage name of the depth pass ("splat_compute", or
 * "splat_compute64" for the 64-bit one) or of the thickness pass
 * ("thickness_compute"), never the raster's; those ("splat", "thickness")
 * when s was not initialised (splat=raster: a zeroed s). */
const char *fs_gl_splat_stage(const fs_gl_splat *s, int thickness);
/* The nearest hit per pixel into t's depth and normal (w = 1) textures, as the
 * raster's depth-tested pass writes them into the cleared target. */
int fs_gl_splat_depth(fs_gl_splat *s, const fs_gl_target *t, const fs_camera *cam, const fs_sprite_bufs *sp,
                      float radius);
/* The sum of chord * weight per pixel into t's thickness texture (cleared to 0),
 * as the raster's additive pass writes it; FS_ERR_RUNTIME if a sum overflowed. */
int fs_gl_splat_thickness(fs_gl_splat *s, const fs_gl_target *t, const fs_camera *cam, const fs_sprite_bufs *sp,
                          float radius, float weight);

#ifdef __cplusplus
}
#endif
#endif
