#version 450 core
#include "common/counters.glsl"
// Caustics, sample planes: the exact integral of eq. 2's intensity over the
// part of the triangle inside this texel, divided by the texel area, added by
// the blender. The intensity is linear over the triangle (per-vertex
// extinction), so the integral is (overlap area) x (intensity at the overlap's
// centroid); with I = E S / S_q the texel receives K (A / S_q) E(centroid), and
// the texels of one triangle together receive its whole flux S mean(E):
// energy-conserving, and bounded however small S_q gets. Alpha: the texel's
// summed overlap fraction (>= 1 inside lit areas).
// Area and first moments of the overlap come from Green's theorem over its
// boundary: the triangle's edges clipped to the (closed) texel plus the texel's
// edges clipped to the (open) triangle, so an edge shared by both counts once.
// No arrays or data-dependent loops: llvmpipe runs this ~30x faster than a
// Sutherland-Hodgman polygon clipper.
uniform float u_sq_min;
in flat vec2 v_p0, v_e1, v_e2;
in flat vec3 v_E0, v_E1, v_E2;
in flat float v_K;
layout(location = 0) out vec4 o_flux;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// (area, integral of x, integral of y) contributed by the directed segment p -> q
// of a counter-clockwise boundary: the line integrals of x dy, x^2/2 dy, -y^2/2 dx.
vec3 green(vec2 p, vec2 q)
{
    vec2 d = q - p;
    return vec3(0.5 * (p.x + q.x) * d.y, d.y * (p.x * p.x + p.x * q.x + q.x * q.x) / 6.0,
                -d.x * (p.y * p.y + p.y * q.y + q.y * q.y) / 6.0);
}

// Narrows [t.x, t.y] to where f0 + t g >= 0 (closed) or > 0 (open).
vec2 halfplane(vec2 t, float f0, float g, bool closed)
{
    if (g == 0.0) return (closed ? f0 >= 0.0 : f0 > 0.0) ? t : vec2(1.0, 0.0);
    float s = -f0 / g;
    return g > 0.0 ? vec2(max(t.x, s), t.y) : vec2(t.x, min(t.y, s));
}

// Triangle edge p -> q clipped to the closed texel [0,1]^2.
vec3 tri_edge(vec2 p, vec2 q)
{
    vec2 d = q - p, t = vec2(0.0, 1.0);
    t = halfplane(t, p.x, d.x, true);
    t = halfplane(t, 1.0 - p.x, -d.x, true);
    t = halfplane(t, p.y, d.y, true);
    t = halfplane(t, 1.0 - p.y, -d.y, true);
    return t.x < t.y ? green(p + t.x * d, p + t.y * d) : vec3(0.0);
}

// Texel edge p -> q clipped to the open counter-clockwise triangle abc.
vec3 box_edge(vec2 p, vec2 q, vec2 a, vec2 b, vec2 c)
{
    vec2 d = q - p, t = vec2(0.0, 1.0);
    t = halfplane(t, cross2(b - a, p - a), cross2(b - a, d), false);
    t = halfplane(t, cross2(c - b, p - b), cross2(c - b, d), false);
    t = halfplane(t, cross2(a - c, p - c), cross2(a - c, d), false);
    return t.x < t.y ? green(p + t.x * d, p + t.y * d) : vec3(0.0);
}

void main()
{
    FS_COUNT(FS_CNT_FRAGMENTS, 1);
    float det = cross2(v_e1, v_e2);
    if (0.5 * abs(det) < u_sq_min) { // degenerate (a fold or focus): all to the centroid's texel
        o_flux = vec4(v_K * (v_E0 + v_E1 + v_E2) / 3.0, 1.0);
        FS_COUNT(FS_CNT_TEXELS, 1);
        return;
    }
    // Triangle relative to the texel's lower corner, counter-clockwise.
    vec2 a = v_p0 - floor(gl_FragCoord.xy);
    vec2 b = a + (det > 0.0 ? v_e1 : v_e2), c = a + (det > 0.0 ? v_e2 : v_e1);
    vec3 m = tri_edge(a, b) + tri_edge(b, c) + tri_edge(c, a);
    m += box_edge(vec2(0.0, 0.0), vec2(1.0, 0.0), a, b, c);
    m += box_edge(vec2(1.0, 0.0), vec2(1.0, 1.0), a, b, c);
    m += box_edge(vec2(1.0, 1.0), vec2(0.0, 1.0), a, b, c);
    m += box_edge(vec2(0.0, 1.0), vec2(0.0, 0.0), a, b, c);
    if (m.x <= 1e-12) discard;
    FS_COUNT(FS_CNT_TEXELS, 1);
    vec2 cen = m.yz / m.x;
    float l1 = cross2(cen - a, v_e2) / det, l2 = cross2(v_e1, cen - a) / det;
    vec3 E = (1.0 - l1 - l2) * v_E0 + l1 * v_E1 + l2 * v_E2;
    float frac = m.x / abs(det) * 2.0; // overlap area / triangle area
    o_flux = vec4(v_K * min(frac, 1.0) * E, m.x);
}
