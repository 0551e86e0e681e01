#version 450 core
// One explicit Euler step of screen-space curvature flow (van der Laan, Green
// & Sainz 2009): the mean curvature H of the surface z(x, y) written with the
// projection's Cx = 2 / (Vx Fx), Cy = 2 / (Vy Fy) and pixel derivatives,
//   D  = Cy^2 zx^2 + Cx^2 zy^2 + Cx^2 Cy^2 z^2
//   Ex = zx Dx / 2 - zxx D,  Ey = zy Dy / 2 - zyy D,  H = (Cy Ex + Cx Ey) / (2 D^1.5),
// and z moved against H so the surface flattens. Derivatives across an empty
// pixel or a depth jump above u_range are set to zero (their boundary rule).
// Time step per pixel: u_dt_scale * z / (2 f_px), see methods/aniso_ssf/README.md.
#include "aniso_ssf/filter_common.glsl"
uniform float u_range;
uniform float u_dt_scale;

bool ok(float zq, float z) { return zq > 0.0 && abs(zq - z) <= u_range; }

void main()
{
    ivec2 px = ivec2(gl_GlobalInvocationID.xy), size = imageSize(u_src);
    if (any(greaterThanEqual(px, size))) return;
    float z = imageLoad(u_src, px).x;
    if (z <= 0.0) { imageStore(u_dst, px, vec4(0.0)); fs_filter_done(); return; }
    fs_taps++; // the centre
    float zr = depth_at(px + ivec2(1, 0), size), zl = depth_at(px - ivec2(1, 0), size);
    float zu = depth_at(px + ivec2(0, 1), size), zd = depth_at(px - ivec2(0, 1), size);
    bool okx = ok(zr, z) && ok(zl, z), oky = ok(zu, z) && ok(zd, z);
    float zx = okx ? 0.5 * (zr - zl) : 0.0, zxx = okx ? zr + zl - 2.0 * z : 0.0;
    float zy = oky ? 0.5 * (zu - zd) : 0.0, zyy = oky ? zu + zd - 2.0 * z : 0.0;
    float zxy = 0.0;
    if (okx && oky) {
        float a = depth_at(px + ivec2(1, 1), size), b = depth_at(px + ivec2(-1, -1), size);
        float c = depth_at(px + ivec2(1, -1), size), d = depth_at(px + ivec2(-1, 1), size);
        if (ok(a, z) && ok(b, z) && ok(c, z) && ok(d, z)) zxy = 0.25 * (a + b - c - d);
    }
    float Cx = 1.0 / u_focal_px, Cy = Cx; // 2 / (V F) = 1 / focal length in pixels
    float D = Cy * Cy * zx * zx + Cx * Cx * zy * zy + Cx * Cx * Cy * Cy * z * z;
    float Dx = 2.0 * (Cy * Cy * zx * zxx + Cx * Cx * zy * zxy + Cx * Cx * Cy * Cy * z * zx);
    float Dy = 2.0 * (Cy * Cy * zx * zxy + Cx * Cx * zy * zyy + Cx * Cx * Cy * Cy * z * zy);
    float Ex = 0.5 * zx * Dx - zxx * D, Ey = 0.5 * zy * Dy - zyy * D;
    float H = (Cy * Ex + Cx * Ey) / (2.0 * D * sqrt(D));
    float dt = u_dt_scale * z / (2.0 * u_focal_px);
    imageStore(u_dst, px, vec4(z - dt * H)); fs_filter_done();
}
