/* An opaque object under the water, as iwasaki2006 renders it (after Iwasaki
 * et al. 2003): "sliced object images", one per slab between adjacent
 * horizontal sample planes, holding what of the object lies in that slab seen
 * from above; the refracted view ray is intersected with the planes and the
 * first occupied slice texel is what it sees (refraction mapping). */
#ifndef FS_OBJECT_SLICES_H
#define FS_OBJECT_SLICES_H

#define OBJECT_MAX_SLICES 8

/* An axis-aligned box standing on the floor; horizontal axes a = (up+1)%3, b = (up+2)%3. */
typedef struct object_box {
    float center[2], half[2]; /* horizontal centre and half sides (axes a, b) */
    float bottom, top;        /* along up */
    float albedo[3];
} object_box;

/* Slice images for nslices slabs between plane_height[0..nslices] (increasing),
 * over the rectangle rect_min..rect_max at res x res texels, written as RGBA
 * (rgb lit colour, a = 1 where the object occupies the slab), slice-major, row
 * v = 0 first (the caustic maps' layout). A texel of the slab holding the box's
 * top face shows the face lit by the ambient light and the caustic map of the
 * plane at the top (maps: RGBA per texel, layer-major, same rectangle and res;
 * NULL: direct light L cos(theta) instead); lower slabs show the box's vertical
 * sides, lit by the ambient light only (the refracted light is near vertical). */
void object_slices_build(const object_box *box, int nslices, const float *plane_height, const float rect_min[2],
                         const float rect_max[2], int res, const float *maps, int top_plane, float ambient,
                         const float direct[3], float *out);

#endif
