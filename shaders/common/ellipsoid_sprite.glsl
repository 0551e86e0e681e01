// xu2022 4.3's ellipsoid sprite, one set of functions for the raster
// (aniso_ssf/ellipsoid.*.glsl) and the compute splatter (common/gl/gl_splat.h):
// the unit sphere scaled by r and the anisotropy matrix A in parameter space
// (T = P V [r A | c]), its screen bounds from the tangent planes of the
// projected quadric (Sigg et al. 2006, eqs. 9-10 of xu2022): for the
// clip-space plane x - b w = 0 the parameter-space plane T^T (1, 0, 0, -b)
// touches the unit sphere exactly when (r1 - b r4) D (r1 - b r4) = 0,
// D = diag(1, 1, 1, -1), r_i the rows of T.

// Both roots of (ri - b r4) D (ri - b r4) = 0, ascending.
vec2 ellipsoid_bounds(vec4 ri, vec4 r4)
{
    const vec4 D = vec4(1.0, 1.0, 1.0, -1.0);
    float a = dot(r4, D * r4), b = dot(ri, D * r4), c = dot(ri, D * ri);
    float h = sqrt(max(b * b - a * c, 0.0));
    vec2 t = vec2(b - h, b + h) / a;
    return vec2(min(t.x, t.y), max(t.x, t.y));
}

// A particle's three vec4s (centre; A's six entries) as its view-space centre c
// and the matrix M from unit-sphere parameters to view-space offsets.
void ellipsoid_setup(vec4 a0, vec4 a1, vec4 a2, mat4 view, float radius, out vec3 c, out mat3 M)
{
    mat3 A = mat3(a1.x, a1.y, a1.z, a1.y, a1.w, a2.x, a1.z, a2.x, a2.y);
    M = mat3(view) * A * radius;
    c = (view * vec4(a0.xyz, 1.0)).xyz;
}

// The sprite's quad as NDC rectangle (x0, x1, y0, y1) and NDC depth (the
// ellipsoid's nearest point, so early depth rejection stays conservative).
// False when the ellipsoid reaches the eye plane: the caller culls.
bool ellipsoid_sprite_rect(vec3 c, mat3 M, mat4 proj, out vec4 rect, out float ndc_z)
{
    float ext_z = length(vec3(M[0].z, M[1].z, M[2].z)); // half extent along the view axis
    rect = vec4(0.0);
    ndc_z = 2.0;
    if (-c.z <= ext_z * 1.001) return false;
    mat4 T = proj * mat4(vec4(M[0], 0.0), vec4(M[1], 0.0), vec4(M[2], 0.0), vec4(c, 1.0));
    vec4 r1 = vec4(T[0][0], T[1][0], T[2][0], T[3][0]);
    vec4 r2 = vec4(T[0][1], T[1][1], T[2][1], T[3][1]);
    vec4 r4 = vec4(T[0][3], T[1][3], T[2][3], T[3][3]);
    rect = vec4(ellipsoid_bounds(r1, r4), ellipsoid_bounds(r2, r4));
    vec4 clip = proj * vec4(0.0, 0.0, c.z + ext_z, 1.0);
    ndc_z = clip.z / clip.w;
    return true;
}

// The view ray (unit direction dir from the eye) against the ellipsoid (centre
// c, inv = M^-1, view space): the front hit at dir * t and the chord length.
// False on a miss. The ray is t = tc + s around the point nearest the centre,
// so the quadratic has small coefficients.
bool ellipsoid_ray(vec3 dir, vec3 c, mat3 inv, out float t, out float chord)
{
    float tc = dot(dir, c);
    vec3 q = inv * dir, p = inv * (dir * tc - c);
    float qq = dot(q, q), qp = dot(q, p);
    float h = qp * qp - qq * (dot(p, p) - 1.0);
    t = 0.0;
    chord = 0.0;
    if (h < 0.0) return false;
    float s = sqrt(h);
    t = tc + (-qp - s) / qq;
    chord = 2.0 * s / qq;
    return true;
}

// The unit view-space normal at a point hit of the ellipsoid's surface.
vec3 ellipsoid_normal(vec3 hit, vec3 c, mat3 inv)
{
    vec3 u = inv * (hit - c);
    return normalize(transpose(inv) * u);
}
