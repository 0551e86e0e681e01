// The view-space ray through a pixel centre, shared by every pass that casts or
// reconstructs from the camera (the same convention as common/camera.c):
// pixel (x, y) in GL's bottom-up order, size the image size, proj the projection.
vec3 fs_view_dir_unnormalized(vec2 pixel_centre, vec2 size, mat4 proj)
{
    vec2 ndc = pixel_centre / size * 2.0 - 1.0;
    return vec3(ndc.x / proj[0][0], ndc.y / proj[1][1], -1.0);
}
// Unit direction of that ray.
vec3 fs_view_ray(vec2 pixel_centre, vec2 size, mat4 proj) { return normalize(fs_view_dir_unnormalized(pixel_centre, size, proj)); }
