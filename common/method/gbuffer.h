/* The G-buffer every method writes (docs/DESIGN.md): rows top to bottom.
 *   depth     positive eye-space distance along the view axis, INFINITY where empty
 *   normal    3 floats, unit view-space vector facing the camera (0 where empty)
 *   thickness fluid path length along the view ray, scene units
 *   coverage  0 or 1
 *   color     optional RGBA (linear): a per-pixel albedo/tint (colour tracking)
 *   own       optional RGBA (linear): the whole image in the method's own appearance,
 *             for methods whose paper defines one (surfels' refraction and caustics)
 *   caustics  optional: caustic irradiance on what each pixel sees (floor or object) */
#ifndef FS_GBUFFER_H
#define FS_GBUFFER_H
#ifdef __cplusplus
extern "C" {
#endif

typedef struct fs_gbuffer {
    int w, h;
    float *depth, *normal, *thickness, *coverage;
    float *color; /* NULL unless the method writes colour */
    float *own;      /* NULL unless allocated with fs_gbuffer_alloc_own */
    float *caustics; /* likewise */
} fs_gbuffer;

int fs_gbuffer_alloc(fs_gbuffer *g, int w, int h, int with_color);
/* Adds the own-appearance layers (own RGBA, caustics) to an allocated G-buffer. */
int fs_gbuffer_alloc_own(fs_gbuffer *g);
void fs_gbuffer_clear(fs_gbuffer *g); /* empty: depth inf, the rest 0 */
void fs_gbuffer_free(fs_gbuffer *g);

#ifdef __cplusplus
}
#endif
#endif
