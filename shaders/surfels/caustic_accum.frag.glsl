#version 450 core
// Caustics, sample planes: the exact integral of eq. 2's intensity over the
// part of the triangle inside this texel, divided by the texel area, added by
// the blender. The intensity is linear over the triangle (per-vertex
// extinction), so the integral is (overlap area) x (intensity at the overlap's
// centroid); with I = E S / S_q the texel receives K (A / S_q) E(centroid), and
// the texels of one triangle together receive its whole flux S mean(E):
// energy-conserving, and bounded however small S_q gets. Alpha: the texel's
// summed overlap fraction (>= 1 inside lit areas).
uniform float u_sq_min;
in flat vec2 v_p0, v_e1, v_e2;
in flat vec3 v_E0, v_E1, v_E2;
in flat float v_K;
layout(location = 0) out vec4 o_flux;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

void main()
{
    float det = cross2(v_e1, v_e2);
    if (0.5 * abs(det) < u_sq_min) { // degenerate (a fold or focus): all to the centroid's texel
        o_flux = vec4(v_K * (v_E0 + v_E1 + v_E2) / 3.0, 1.0);
        return;
    }
    // Triangle relative to the texel's lower corner, clipped to [0,1]^2 (Sutherland-Hodgman).
    vec2 a = v_p0 - floor(gl_FragCoord.xy);
    vec2 poly[8], tmp[8];
    poly[0] = a;
    poly[1] = a + v_e1;
    poly[2] = a + v_e2;
    int n = 3;
    for (int k = 0; k < 4 && n > 0; k++) {
        int axis = k & 1;
        float s = k < 2 ? 1.0 : -1.0;      // keep s * x >= off
        float off = k < 2 ? 0.0 : -1.0;
        int m = 0;
        for (int j = 0; j < n; j++) {
            vec2 p = poly[j], q = poly[(j + 1) % n];
            float dp = s * p[axis] - off, dq = s * q[axis] - off;
            if (dp >= 0.0) tmp[m++] = p;
            if ((dp >= 0.0) != (dq >= 0.0)) tmp[m++] = mix(p, q, dp / (dp - dq));
        }
        n = m;
        for (int j = 0; j < n; j++) poly[j] = tmp[j];
    }
    if (n < 3) discard;
    float area2 = 0.0;
    vec2 c = vec2(0.0);
    for (int j = 0; j < n; j++) {
        vec2 p = poly[j], q = poly[(j + 1) % n];
        float w = cross2(p, q);
        area2 += w;
        c += (p + q) * w;
    }
    if (abs(area2) <= 1e-12) discard;
    c /= 3.0 * area2;
    float l1 = cross2(c - a, v_e2) / det, l2 = cross2(v_e1, c - a) / det;
    vec3 E = (1.0 - l1 - l2) * v_E0 + l1 * v_E1 + l2 * v_E2;
    float frac = abs(area2 / det); // overlap area / triangle area
    o_flux = vec4(v_K * frac * E, 0.5 * abs(area2));
}
