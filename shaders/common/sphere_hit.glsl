// The view ray (unit direction dir from the eye) against a sphere (view-space
// centre c, radius r): b = dot(dir, c) and the half chord s, the hit nearest
// the eye at dir * (b - s). False on a miss. One function for the raster's
// fragments and the compute splatter's pixels (common/gl/gl_splat.h).
bool sphere_ray(vec3 dir, vec3 c, float r, out float b, out float s)
{
    b = dot(dir, c);
    float h = b * b - dot(c, c) + r * r;
    s = 0.0;
    if (h < 0.0) return false;
    s = sqrt(h);
    return true;
}

// The window depth (0 near .. 1 far) of a view-space point, as gl_FragDepth.
float window_depth(vec3 p, mat4 proj)
{
    vec4 clip = proj * vec4(p, 1.0);
    return clip.z / clip.w * 0.5 + 0.5;
}
