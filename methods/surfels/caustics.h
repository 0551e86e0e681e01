/* Caustics from point-based water surfaces (iwasaki2006 sections 5.1-5.2):
 *  1. the surfels are splatted onto a horizontal virtual screen above the water,
 *     looking along the light (orthographic), with Gaussian weights g(r/R) and
 *     per-pixel normalisation (eq. 3): per pixel the surface point s(x,y) that
 *     light reaches first and its normal n(x,y);
 *  2. read back: at each s the light is refracted (Snell, ior); neighbouring
 *     pixels give triangles (x,y),(x+1,y),(x,y+1) and (x+1,y+1),(x+1,y),(x,y+1)
 *     whose refracted sweeps are the illumination volumes;
 *  3. each volume is cut by the horizontal sample planes; the intersection
 *     triangle carries eq. 2's intensity L_i cos(theta_i) T(theta_i,theta_t)
 *     exp(-c l_q) F_q with F_q = S / S_q, accumulated additively per plane.
 * The maps hold eq. 2 with K = 1 and L_a = 0: irradiance carried by refracted
 * light, zero where no water lies above; the renderer multiplies by the albedo
 * K and adds the ambient term. */
#ifndef FS_CAUSTICS_H
#define FS_CAUSTICS_H
#include "surfel_set.h"

#define FS_CAUSTICS_MAX_PLANES 16

typedef struct fs_caustics_setup {
    int up_axis;               /* 0 x, 1 y, 2 z: vertical axis; the horizontal axes are (up+1)%3, (up+2)%3 */
    float light_dir[3];        /* unit, towards the light (world) */
    float light_color[3];      /* L_i per RGB channel */
    float ior;                 /* water's index of refraction (1.33) */
    float extinction[3];       /* c(lambda), per scene unit of path in water */
    float rect_min[2], rect_max[2]; /* horizontal extent (axes a, b above) of screen and planes */
    float top;                 /* height of the virtual screen (above all water) */
    int screen_res;            /* virtual screen pixels per side (the paper: 128) */
    int plane_res;             /* sample plane texels per side */
    int nplanes;
    float plane_height[FS_CAUSTICS_MAX_PLANES]; /* along up; plane 0 is the floor */
} fs_caustics_setup;

typedef struct fs_caustics fs_caustics;

/* GL 4.5 context current. NULL with fs_fail set. */
fs_caustics *fs_caustics_create(void);
void fs_caustics_destroy(fs_caustics *c);
/* Runs steps 1-3 for surfels uploaded as an SSBO of n surfels (surfel_set.h layout). */
int fs_caustics_run(fs_caustics *c, const fs_caustics_setup *setup, unsigned surfel_ssbo, size_t n);
/* After a run: a GL_TEXTURE_2D_ARRAY (RGBA32F, plane_res^2, nplanes layers; rgb
 * = the maps, texel (u,v) covers horizontal axis a from rect_min[0] to rect_max[0]
 * along u and b along v) and its CPU copy, rgba per texel, layer-major. */
unsigned fs_caustics_texture(const fs_caustics *c);
const float *fs_caustics_maps(const fs_caustics *c);
/* Triangles accumulated in the last run, and the flux (sum of intensity x area)
 * that entered the water and that reached each plane, for energy checks. */
size_t fs_caustics_triangles(const fs_caustics *c);
double fs_caustics_flux_in(const fs_caustics *c);
double fs_caustics_flux_plane(const fs_caustics *c, int plane);

#endif
