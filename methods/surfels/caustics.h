/* Caustics from point-based water surfaces (iwasaki2006 sections 5.1-5.2):
 *  1. the surfels are splatted onto a horizontal virtual screen above the water,
 *     looking along the light (orthographic; oblique when the light is not
 *     vertical), with Gaussian weights g(r/R) and per-pixel normalisation
 *     (eq. 3): per pixel the surface point s(x,y) that light reaches first and
 *     its normal n(x,y). Visibility as in the paper's renderer (5.3, Botsch &
 *     Kobbelt): a depth-only pass pushed back by epsilon, then a blending pass
 *     tested against it; only surfels facing the light (n . light_dir > 0).
 *     g(x) = (exp(-2 x^2) - exp(-2)) / (1 - exp(-2)) for x = r/R < 1, else 0
 *     (a Gaussian of standard deviation R/2 shifted to reach 0 at the rim);
 *     r is measured in the disk's plane, where the pixel's light ray meets it,
 *     and that point's depth is the surfel's depth d_i for the pixel;
 *  2. read back: at each s the light is refracted (Snell, ior) and transmitted
 *     with the unpolarised Fresnel T = 1 - (rs^2 + rp^2)/2; neighbouring covered
 *     pixels give triangles (x,y),(x+1,y),(x,y+1) and (x+1,y+1),(x+1,y),(x,y+1),
 *     skipped when their depths along the light differ by more than max_jump
 *     screen pixel sizes (default 4); their refracted sweeps are the
 *     illumination volumes;
 *  3. each volume is cut by the horizontal sample planes below all three of its
 *     surface points; the intersection triangle carries eq. 2's intensity
 *     L_i cos(theta_i) T(theta_i,theta_t) exp(-c l_q) F_q with F_q = S / S_q, S
 *     the water triangle's area (3D) and S_q the plane triangle's; cos T and the
 *     extinction path l_q (from s to the plane along the refracted ray) are taken
 *     per vertex and interpolated linearly over the triangle. Accumulated
 *     additively on the GPU per plane, each texel receiving the exact integral
 *     of the intensity over its overlap with the triangle (divided by the texel
 *     area): energy-conserving, and a fold or focus (S_q -> 0) deposits the
 *     triangle's finite flux S mean(L_i cos T exp(-c l)) in the texel(s) it
 *     falls in instead of blowing up or vanishing between texel centres.
 * The maps hold eq. 2 with K = 1 and L_a = 0: irradiance carried by refracted
 * light (per unit horizontal area of the plane), zero where no water lies
 * above; the renderer multiplies by the albedo K and adds the ambient term. */
#ifndef FS_CAUSTICS_H
#define FS_CAUSTICS_H
#include "surfel_set.h"

#define FS_CAUSTICS_MAX_PLANES 16

typedef struct fs_caustics_setup {
    int up_axis;          /* 0 x, 1 y, 2 z: vertical axis; the horizontal axes are (up+1)%3, (up+2)%3 */
    float light_dir[3];   /* towards the light (world; made unit); its up component must exceed 0.01 of its length */
    float light_color[3]; /* L_i per RGB channel */
    float ior;            /* water's index of refraction (1.33) */
    float extinction[3];  /* c(lambda), per scene unit of path in water */
    float rect_min[2], rect_max[2]; /* horizontal extent (axes a, b above) of screen and planes */
    float top;                      /* height of the virtual screen (above all water; surfels above it are ignored) */
    int screen_res;                 /* virtual screen pixels per side (the paper: 128) */
    int plane_res;                  /* sample plane texels per side */
    int nplanes;
    float plane_height[FS_CAUSTICS_MAX_PLANES]; /* along up; plane 0 is the floor */
} fs_caustics_setup;

typedef struct fs_caustics fs_caustics;

/* GL 4.5 context current. NULL with fs_fail set. */
fs_caustics *fs_caustics_create(void);
void fs_caustics_destroy(fs_caustics *c);
/* Runs steps 1-3 for surfels uploaded as an SSBO of n surfels (surfel_set.h
 * layout). FS_ERR_INPUT for a bad setup (light from below the horizon, sample
 * planes above the screen, ...), FS_ERR_RUNTIME for GL failures. Leaves the
 * default framebuffer bound, blending and depth test off, the viewport as it was. */
int fs_caustics_run(fs_caustics *c, const fs_caustics_setup *setup, unsigned surfel_ssbo, size_t n);
/* After a run: a GL_TEXTURE_2D_ARRAY (RGBA32F, plane_res^2, nplanes layers; rgb
 * = the maps, a = the texel's summed overlap with intersection triangles, >= 1
 * inside lit areas; texel (u,v) covers horizontal axis a from rect_min[0] to
 * rect_max[0] along u and b along v; linear filtering, clamped) and its CPU copy,
 * rgba per texel, layer-major, row v = 0 first. The texture is owned by c and may
 * be replaced by a run with another plane_res or nplanes. */
unsigned fs_caustics_texture(const fs_caustics *c);
const float *fs_caustics_maps(const fs_caustics *c);
/* Illumination volumes (water-surface triangles) made in the last run, and the
 * flux, averaged over RGB: flux_in = sum over those triangles of S x mean over
 * the 3 vertices of L_i cos(theta_i) T (light transmitted into the water);
 * flux_plane = sum over the plane's texels of map x texel area (light deposited
 * inside the rectangle). With zero extinction and every volume reaching the
 * plane inside the rectangle they are equal. */
size_t fs_caustics_triangles(const fs_caustics *c);
double fs_caustics_flux_in(const fs_caustics *c);
double fs_caustics_flux_plane(const fs_caustics *c, int plane);

/* Tuning (kept across runs). max_jump: in screen pixel sizes, the largest
 * depth difference inside one water triangle (default 4). The depth-pass offset
 * epsilon stays at its default, 1 surfel radius (surfels whose depth along the
 * light is within epsilon R of the first surface are blended). */
void fs_caustics_set_max_jump(fs_caustics *c, float pixels);
/* Unpolarised Fresnel transmittance from air into a medium of index ior at
 * incidence cosine cos_i (0 for cos_i <= 0). */
double fs_caustics_transmittance(double cos_i, double ior);

#endif
