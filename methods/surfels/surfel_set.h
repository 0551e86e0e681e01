/* Surfels of the water surface (iwasaki2006 sections 4.2, 5): a disk of radius
 * R_i perpendicular to n_i at s_i. The GPU layout is two vec4s per surfel
 * (std430): (position, radius), (normal, 0). Normals are unit, world space,
 * pointing out of the fluid (minus the density gradient). */
#ifndef FS_SURFEL_SET_H
#define FS_SURFEL_SET_H
#include <stddef.h>

typedef struct fs_surfel {
    float pos[3], radius;
    float normal[3], pad;
} fs_surfel;

typedef struct fs_surfel_set {
    size_t n, cap;
    fs_surfel *s;
} fs_surfel_set;

/* FS_OK, or FS_ERR_RUNTIME on OOM (fs_fail set). */
int fs_surfel_push(fs_surfel_set *set, const float pos[3], const float normal[3], float radius);
void fs_surfel_set_free(fs_surfel_set *set);

#endif
