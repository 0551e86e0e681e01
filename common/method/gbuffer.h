/* The G-buffer every method writes (docs/DESIGN.md): rows top to bottom.
 *   depth     positive eye-space distance along the view axis, INFINITY where empty
 *   normal    3 floats, unit view-space vector facing the camera (0 where empty)
 *   thickness fluid path length along the view ray, scene units
 *   coverage  0 or 1
 * plus the optional layers (AOVs) a method declares it writes (fs_method.aovs),
 * found by name. The well-known ones (their component counts are fixed):
 *   color     RGBA (linear): a per-pixel albedo/tint (colour tracking)
 *   own       RGBA (linear): the whole image in the method's own appearance,
 *             for methods whose paper defines one (surfels' refraction and caustics)
 *   caustics  1: caustic irradiance on what each pixel sees (floor or object)
 *   solid_depth 1: the depth of the scene's solids (0 where none); no method
 *             writes it: EXRs of a scene with solids carry it so that diff and the
 *             C API mask what compare masks (obstacle_mask.h, fs_solids_layer)
 * In an EXR a 4-component AOV NAME is the channels NAME.R NAME.G NAME.B NAME.A,
 * a 1-component one the channel NAME. */
#ifndef FS_GBUFFER_H
#define FS_GBUFFER_H
#ifdef __cplusplus
extern "C" {
#endif

#define FS_AOV_COLOR "color"
#define FS_AOV_OWN "own"
#define FS_AOV_CAUSTICS "caustics"
#define FS_AOV_SOLID_DEPTH "solid_depth"

enum { FS_GBUFFER_MAX_AOVS = 8, FS_AOV_NAME_MAX = 32 };

typedef struct fs_aov {
    char name[FS_AOV_NAME_MAX];
    int ncomp;   /* 1 or 4 */
    float *data; /* ncomp floats per pixel, interleaved */
} fs_aov;

typedef struct fs_gbuffer {
    int w, h;
    float *depth, *normal, *thickness, *coverage;
    int naovs;
    fs_aov aov[FS_GBUFFER_MAX_AOVS]; /* in the order they were added */
} fs_gbuffer;

/* The four core layers, cleared; no AOVs. */
int fs_gbuffer_alloc(fs_gbuffer *g, int w, int h);
/* Adds a zeroed AOV to an allocated G-buffer (already there with ncomp
 * components: no-op). FS_ERR_INPUT for a name that is empty, too long or holds
 * a '.', for ncomp other than 1 or 4, or other than a well-known name's;
 * FS_ERR_RUNTIME when full or out of memory. */
int fs_gbuffer_add_aov(fs_gbuffer *g, const char *name, int ncomp);
/* 1 for the layers of a method's own look (own, caustics), which neither the
 * shared shading nor the metrics read. */
int fs_aov_own_look(const char *name);
/* The AOV's data, NULL when g has none of that name. */
float *fs_gbuffer_aov(const fs_gbuffer *g, const char *name);
void fs_gbuffer_clear(fs_gbuffer *g); /* empty: depth inf, the rest 0 (AOVs too) */
void fs_gbuffer_free(fs_gbuffer *g);

#ifdef __cplusplus
}
#endif
#endif
