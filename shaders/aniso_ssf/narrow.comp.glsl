#version 450 core
// Narrow-range filter (Truong & Yuksel 2018): a Gaussian over the depths in a
// narrow range around the pixel's own depth z (eye distance, larger = farther).
// Samples are taken in point-symmetric pairs, outwards from the centre:
//  - nearer than the range: another surface in front; the sample and its
//    mirror are both left out, so the kernel stays symmetric and a sloped
//    surface keeps its depth (their bias correction);
//  - farther than the range, or empty (background): clamped to z + u_clamp,
//    so a silhouette bends away from the camera instead of being cut;
//  - inside the range: kept, and the range grows to reach u_threshold beyond
//    it (their dynamic range), so a steep but continuous surface stays in.
// Out-of-image pairs are left out. Both samples of a pair are classified
// before the pair is judged, so a kept sample grows the range even when its
// mirror is left out (as the authors' demo does). u_axis 0 or 1: a 1D pass
// (each side keeps its own range); 2: the final 2D pass (one range, grown
// ring by ring, the first sample of a pair before the second).
#include "aniso_ssf/filter_common.glsl"
uniform int u_axis;
uniform float u_threshold; // delta, scene units
uniform float u_clamp;     // mu, scene units

bool inside(ivec2 q, ivec2 size) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size)); }

// Classifies one sample against [lo, hi]; false when it is left out.
bool take(inout float zq, inout vec2 range, float z)
{
    if (zq > 0.0 && zq < range.x) return false;
    if (zq <= 0.0 || zq > range.y) { zq = z + u_clamp; return true; }
    range = vec2(min(range.x, zq - u_threshold), max(range.y, zq + u_threshold));
    return true;
}

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_src);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_src, px).x;
    if (z <= 0.0) { imageStore(u_dst, px, vec4(0.0)); fs_filter_done(); return; }
    float sp = sigma_px(z), sum = z, wsum = 1.0;
    fs_taps++; // the centre
    int rad = radius_px(z);
    vec2 r0 = vec2(z - u_threshold, z + u_threshold), ra = r0, rb = r0;
    if (u_axis < 2) {
        ivec2 dir = u_axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        for (int k = 1; k <= rad; k++) {
            ivec2 qa = px + k * dir, qb = px - k * dir;
            if (!inside(qa, size) || !inside(qb, size)) break;
            fs_taps += 2u;
            float a = imageLoad(u_src, qa).x, b = imageLoad(u_src, qb).x;
            bool ta = take(a, ra, z), tb = take(b, rb, z);
            if (!(ta && tb)) continue;
            float w = exp(-float(k * k) / (2.0 * sp * sp));
            sum += w * (a + b);
            wsum += 2.0 * w;
        }
    } else {
        // Ring d (8d offsets) as 4d mirror pairs: the top row (x = -d..d, y = d)
        // and the right column (x = d, y = d-1..-(d-1)), each with -o.
        for (int d = 1; d <= rad; d++)
            for (int i = 0; i < 4 * d; i++) {
                ivec2 o = i <= 2 * d ? ivec2(i - d, d) : ivec2(d, 3 * d - i);
                ivec2 qa = px + o, qb = px - o;
                if (!inside(qa, size) || !inside(qb, size)) continue;
                fs_taps += 2u;
                float a = imageLoad(u_src, qa).x, b = imageLoad(u_src, qb).x;
                bool ta = take(a, ra, z), tb = take(b, ra, z);
                if (!(ta && tb)) continue;
                float w = exp(-float(dot(o, o)) / (2.0 * sp * sp));
                sum += w * (a + b);
                wsum += 2.0 * w;
            }
    }
    imageStore(u_dst, px, vec4(sum / wsum)); fs_filter_done();
}
