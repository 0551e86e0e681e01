#version 450 core
// xu2022 4.3: one screen-aligned quad per particle, the unit sphere scaled by
// r and the anisotropy matrix A in parameter space (T = P V [r A | c]), its
// screen bounds from the tangent planes of the projected quadric (Sigg et al.
// 2006, eqs. 9-10 of xu2022): for the clip-space plane x - b w = 0 the
// parameter-space plane T^T (1, 0, 0, -b) touches the unit sphere exactly when
// (r1 - b r4) D (r1 - b r4) = 0, D = diag(1, 1, 1, -1), r_i the rows of T.
layout(std430, binding = 0) readonly buffer FsAniso { vec4 aniso[]; }; // 3 vec4 per particle
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
out flat vec3 v_center; // view space
out flat mat3 v_inv;    // view-space offset -> unit-sphere parameter space

const vec4 D = vec4(1.0, 1.0, 1.0, -1.0);

// Both roots of (ri - b r4) D (ri - b r4) = 0, ascending.
vec2 bounds(vec4 ri, vec4 r4)
{
    float a = dot(r4, D * r4), b = dot(ri, D * r4), c = dot(ri, D * ri);
    float h = sqrt(max(b * b - a * c, 0.0));
    vec2 t = vec2(b - h, b + h) / a;
    return vec2(min(t.x, t.y), max(t.x, t.y));
}

void main()
{
    uint i = 3u * uint(gl_InstanceID);
    vec4 a0 = aniso[i], a1 = aniso[i + 1u], a2 = aniso[i + 2u];
    mat3 A = mat3(a1.x, a1.y, a1.z, a1.y, a1.w, a2.x, a1.z, a2.x, a2.y);
    mat3 M = mat3(u_view) * A * u_radius;
    vec3 c = (u_view * vec4(a0.xyz, 1.0)).xyz;
    v_center = c;
    v_inv = inverse(M);
    float ext_z = length(vec3(M[0].z, M[1].z, M[2].z)); // half extent along the view axis
    if (-c.z <= ext_z * 1.001) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; } // reaches the eye plane: cull
    mat4 T = u_proj * mat4(vec4(M[0], 0.0), vec4(M[1], 0.0), vec4(M[2], 0.0), vec4(c, 1.0));
    vec4 r1 = vec4(T[0][0], T[1][0], T[2][0], T[3][0]);
    vec4 r2 = vec4(T[0][1], T[1][1], T[2][1], T[3][1]);
    vec4 r4 = vec4(T[0][3], T[1][3], T[2][3], T[3][3]);
    vec2 bx = bounds(r1, r4), by = bounds(r2, r4);
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec2 ndc = vec2(mix(bx.x, bx.y, corner.x), mix(by.x, by.y, corner.y));
    // Quad depth: the ellipsoid's nearest point, so early depth rejection stays conservative.
    vec4 clip = u_proj * vec4(0.0, 0.0, c.z + ext_z, 1.0);
    gl_Position = vec4(ndc, clip.z / clip.w, 1.0);
}
