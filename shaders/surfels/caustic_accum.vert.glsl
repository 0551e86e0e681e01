#version 450 core
// Caustics, sample planes: one quad per intersection triangle (illumination
// volume cut by the plane), covering the texels its bounding box touches
// (snapped outwards to texel edges, so every texel the triangle overlaps gets a
// fragment however small the triangle). Per triangle, 5 vec4 (texel units):
// (p0, e1), (e2, K, 0), E0, E1, E2 with p1 = p0 + e1, p2 = p0 + e2, K = S / texel
// area and E_v = L_i cos(theta_i) T exp(-c l) at vertex v.
layout(std430, binding = 0) readonly buffer FsTris { vec4 tri[]; };
uniform float u_res;     // plane texels per side
uniform float u_sq_min;  // triangles smaller than this (texel^2) go whole to their centroid's texel
out flat vec2 v_p0, v_e1, v_e2;
out flat vec3 v_E0, v_E1, v_E2;
out flat float v_K;

void main()
{
    uint i = 5u * uint(gl_InstanceID);
    vec4 t0 = tri[i], t1 = tri[i + 1u];
    v_p0 = t0.xy;
    v_e1 = t0.zw;
    v_e2 = t1.xy;
    v_K = t1.z;
    v_E0 = tri[i + 2u].xyz;
    v_E1 = tri[i + 3u].xyz;
    v_E2 = tri[i + 4u].xyz;
    vec2 p1 = v_p0 + v_e1, p2 = v_p0 + v_e2;
    vec2 lo = min(v_p0, min(p1, p2)), hi = max(v_p0, max(p1, p2));
    float sq = 0.5 * abs(v_e1.x * v_e2.y - v_e1.y * v_e2.x);
    if (sq < u_sq_min) {
        lo = floor(v_p0 + (v_e1 + v_e2) / 3.0);
        hi = lo + 1.0;
    } else {
        lo = floor(lo);
        hi = floor(hi) + 1.0;
    }
    lo = clamp(lo, -1.0, u_res + 1.0);
    hi = clamp(hi, -1.0, u_res + 1.0);
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(2.0 * mix(lo, hi, corner) / u_res - 1.0, 0.0, 1.0);
}
