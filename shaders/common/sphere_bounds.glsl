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

// The sprite of a sphere (view-space centre c, radius r): its quad's NDC
// rectangle (x0, x1, y0, y1) and its NDC depth, that of the sphere's nearest
// point, so early depth rejection stays conservative. False when the eye is
// inside or behind: the caller culls. The raster and the compute splatter
// both take their bounds from here (common/gl/gl_splat.h).
bool sphere_sprite_rect(vec3 c, float r, mat4 proj, out vec4 rect, out float ndc_z)
{
    float u = -c.z;
    rect = vec4(0.0);
    ndc_z = 2.0;
    if (u <= r * 1.001) return false;
    vec2 sx = tangent_slopes(c.x, u, r) * proj[0][0];
    vec2 sy = tangent_slopes(c.y, u, r) * proj[1][1];
    rect = vec4(sx, sy);
    vec4 clip = proj * vec4(0.0, 0.0, c.z + r, 1.0);
    ndc_z = clip.z / clip.w;
    return true;
}

// Clip position of corner `vertex` (gl_VertexID of a 4-vertex strip) of the
// sprite's quad; false (a position outside the clip volume) when culled.
bool sphere_sprite_corner(vec3 c, float r, mat4 proj, int vertex, out vec4 position)
{
    vec4 rect;
    float z;
    position = vec4(2.0, 2.0, 2.0, 1.0);
    if (!sphere_sprite_rect(c, r, proj, rect, z)) return false;
    vec2 corner = vec2(vertex & 1, vertex >> 1);
    vec2 ndc = vec2(mix(rect.x, rect.y, corner.x), mix(rect.z, rect.w, corner.y));
    position = vec4(ndc, z, 1.0);
    return true;
}
