// Exact screen-space bounds of a perspective-projected sphere, for sprites that
// must cover a whole silhouette at any distance (no point-size limit).
// Tangent slopes x/(-z) of the two lines through the eye touching a circle
// of radius r centred at (c, -u) in one axis plane.
vec2 tangent_slopes(float c, float u, float r)
{
    float disc = sqrt(max(c * c + u * u - r * r, 0.0));
    float den = u * u - r * r;
    return vec2(c * u - r * disc, c * u + r * disc) / den;
}

// Clip position of corner (gl_VertexID of a 4-vertex strip) of the quad bounding
// the sphere (view-space centre c, radius r); depth at the sphere's nearest point
// so early depth rejection stays conservative. False when the eye is inside or
// behind: the caller culls.
bool sphere_sprite_corner(vec3 c, float r, mat4 proj, out vec4 position)
{
    float u = -c.z;
    position = vec4(2.0, 2.0, 2.0, 1.0);
    if (u <= r * 1.001) return false;
    vec2 sx = tangent_slopes(c.x, u, r) * proj[0][0];
    vec2 sy = tangent_slopes(c.y, u, r) * proj[1][1];
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec2 ndc = vec2(mix(sx.x, sx.y, corner.x), mix(sy.x, sy.y, corner.y));
    vec4 clip = proj * vec4(0.0, 0.0, c.z + r, 1.0);
    position = vec4(ndc, clip.z / clip.w, 1.0);
    return true;
}
