#include "object_slices.h"
#include <string.h>

void object_slices_build(const object_box *box, int nslices, const float *plane_height, const float rect_min[2],
                         const float rect_max[2], int res, const float *maps, int top_plane, float ambient,
                         const float direct[3], float *out)
{
    size_t layer = (size_t)res * res * 4;
    memset(out, 0, layer * nslices * sizeof(float));
    float du = (rect_max[0] - rect_min[0]) / res, dv = (rect_max[1] - rect_min[1]) / res;
    for (int k = 0; k < nslices; k++) {
        float lo = plane_height[k], hi = plane_height[k + 1];
        if (box->top <= lo || box->bottom >= hi) continue; /* the box does not reach this slab */
        int holds_top = box->top <= hi;
        for (int v = 0; v < res; v++) {
            float y = rect_min[1] + (v + 0.5f) * dv;
            if (y < box->center[1] - box->half[1] || y > box->center[1] + box->half[1]) continue;
            for (int u = 0; u < res; u++) {
                float x = rect_min[0] + (u + 0.5f) * du;
                if (x < box->center[0] - box->half[0] || x > box->center[0] + box->half[0]) continue;
                size_t t = (size_t)v * res + u;
                float *o = out + k * layer + 4 * t;
                for (int c = 0; c < 3; c++) {
                    float light = ambient;
                    if (holds_top) light += maps ? maps[top_plane * layer + 4 * t + c] : direct[c];
                    o[c] = box->albedo[c] * light;
                }
                o[3] = 1.0f;
            }
        }
    }
}
