/* A frame as the density-grid methods hold it (surfels, volume_raycast), and its
 * density grid built by one of the three builders and timed as one stage,
 * written once for both. */
#ifndef FS_DENSITY_FRAME_H
#define FS_DENSITY_FRAME_H
#include "density_splat.h"
#include "grid.h"
#include "timing.h"

typedef struct fs_density_frame {
    const fs_particles *p;   /* the bulk: the particles the grid keeps (fs_density_grid_keep); NULL before upload */
    const fs_particles *all; /* every particle (the exact build sums them all) */
    fs_particles bulk;       /* p, a copy, when far strays were left out */
    size_t dropped;          /* far strays left out of the grid */
    const fs_grid *ng;       /* the neighbour grid (fitted to cells of at least H for the exact build) */
    fs_grid own;
    int has_own;
} fs_density_frame;

/* Hands frame p (its neighbour grid g) over: the bulk kept within g's bulk box
 * grown by H, the strays named in a note ("METHOD: N far stray particle(s)
 * outside the bulk are left out of WHAT"); with fit, g fitted to cells of at
 * least H. p and g are borrowed until the next upload (docs/DESIGN.md, "The run
 * layer"). */
int fs_density_frame_upload(fs_density_frame *d, const fs_particles *p, const fs_grid *g, float H, int fit,
                            const char *method, const char *what);
void fs_density_frame_free(fs_density_frame *d);

/* The three builders of a frame's grid. */
typedef enum { FS_DENSITY_LAYERED, FS_DENSITY_SLICE, FS_DENSITY_EXACT } fs_density_build;

typedef struct fs_density_builder {
    fs_density_build build;
    fs_layered_splat *layered; /* FS_DENSITY_LAYERED */
    fs_slice_splat *slice;     /* FS_DENSITY_SLICE */
    int up_axis, clusters;     /* the slice splatting's planes and height bands */
    int gl_clock;              /* time the build as a GL stage (gl_stage.h), else by the wall clock after glFinish */
} fs_density_builder;

/* dg (initialised over the bulk's box) built from d by b: the layered build
 * into tex3d alone, the others into dg and, with tex3d, uploaded into it inside
 * the timed span (the upload is part of a CPU-side build's cost). Adds the stage
 * `stage` to t and sets *t_end (when not NULL) to the clock at its end; t NULL:
 * untimed (an export). */
int fs_density_frame_build(const fs_density_builder *b, const fs_density_frame *d, const fs_field *f,
                           fs_density_grid *dg, unsigned tex3d, fs_stages *t, const char *stage, double *t_end);

#endif
