/* The GL builders of a density grid (field/density_grid.h): iwasaki2006's slice
 * splatting and inacio2010's single-pass layered splatting, and the grid as a 3D
 * texture. All need a current GL 4.5 context. */
#ifndef FS_DENSITY_SPLAT_H
#define FS_DENSITY_SPLAT_H
#include "density_grid.h"
#include "timing.h"
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

/* iwasaki2006 slice splatting on the current GL 4.5 context. The planes are
 * stacked along `up_axis` (the paper's z); particles are clustered into
 * `clusters` height bands (the paper's N_c) and a band is drawn only for the
 * planes its disks reach. Reads each 4-plane RGBA32F pass back into g->data. */
typedef struct fs_slice_splat fs_slice_splat;
fs_slice_splat *fs_slice_splat_create(void); /* NULL with fs_fail set */
void fs_slice_splat_destroy(fs_slice_splat *s);
/* g must be initialised (fs_density_grid_init); its values are overwritten. */
int fs_slice_splat_run(fs_slice_splat *s, fs_density_grid *g, const fs_particles *p, const fs_field *f, int up_axis,
                       int clusters);
/* Disks drawn in the last run (one per particle per 4-plane pass it was drawn in). */
size_t fs_slice_splat_disks(const fs_slice_splat *s);

/* inacio2010 single-pass layered splatting on the current GL 4.5 context. The
 * grid lives in an R32F 3D texture of shape->dim texels, texel (i,j,k) holding
 * grid point (i,j,k) (shape->data is not used). Each particle is drawn once as
 * a point; a geometry shader emits its disk on every z layer within H, with
 * gl_Layer, and additive blending sums V W(d, H) of the field's kernel. */
typedef struct fs_layered_splat fs_layered_splat;
fs_layered_splat *fs_layered_splat_create(void); /* NULL with fs_fail set */
void fs_layered_splat_destroy(fs_layered_splat *s);
/* Overwrites tex3d (from fs_density_texture_create(shape)) with phi. */
int fs_layered_splat_run(fs_layered_splat *s, const fs_density_grid *shape, const fs_particles *p, const fs_field *f,
                         unsigned tex3d);
/* Points drawn in the last run: particles x draws (more than one draw only when a
 * particle reaches more layers than one geometry-shader draw can emit). */
size_t fs_layered_splat_points(const fs_layered_splat *s);

/* The grid as a GL texture: an R32F 3D texture of shape->dim texels (linear
 * filtering, clamp to edge); 0 with fs_fail set. Delete with glDeleteTextures. */
unsigned fs_density_texture_create(const fs_density_grid *shape);
/* g->data -> texture, and back (g initialised, of the texture's shape). */
int fs_density_texture_upload(unsigned tex, const fs_density_grid *g);
int fs_density_texture_read(unsigned tex, fs_density_grid *g);

#ifdef __cplusplus
}
#endif
#endif
