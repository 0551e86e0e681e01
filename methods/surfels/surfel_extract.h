/* Surfels on the iso-surface of a density grid (iwasaki2006 section 4.2). */
#ifndef FS_SURFEL_EXTRACT_H
#define FS_SURFEL_EXTRACT_H
#include "density_grid.h"
#include "surfel_set.h"

typedef struct fs_surfel_extract_opts {
    float iso;          /* iso value on the phi scale */
    float radius_scale; /* surfel radius R in grid spacings */
    float gap;          /* a cell whose crossings lie farther than gap spacings from their
                           centroid gets one more surfel there (0 disables gap filling) */
} fs_surfel_extract_opts;

/* Appends to out (emptied first): one surfel per grid edge whose end values
 * straddle iso (position by linear interpolation, normal = -grad phi from
 * central differences interpolated along the edge), plus the gap-filling
 * surfels, projected onto the iso-surface by Newton steps along the gradient.
 * Deterministic order (by plane, then row). *gap_added may be NULL. */
int fs_surfels_extract(const fs_density_grid *g, const fs_surfel_extract_opts *o, fs_surfel_set *out,
                       size_t *gap_added);

#endif
