// SPH kernels by support radius H, normalised in 3D: the same formulas and
// constants as common/kernels.h (tests/test_kernels_gl.c checks they agree).
const float FS_PI = 3.14159265358979323846;

float fs_cubic_w(float d, float H)
{
    float q = d / H, s = (8.0 / FS_PI) / (H * H * H);
    if (q <= 0.5) return s * (6.0 * q * q * q - 6.0 * q * q + 1.0);
    if (q < 1.0) { float t = 1.0 - q; return 2.0 * s * t * t * t; }
    return 0.0;
}
float fs_cubic_dw(float d, float H)
{
    float q = d / H, s = (8.0 / FS_PI) / (H * H * H * H);
    if (q <= 0.5) return s * (18.0 * q * q - 12.0 * q);
    if (q < 1.0) { float t = 1.0 - q; return -6.0 * s * t * t; }
    return 0.0;
}
float fs_poly6_w(float d, float H)
{
    if (d >= H) return 0.0;
    float t = H * H - d * d, H3 = H * H * H;
    return (315.0 / (64.0 * FS_PI)) / (H3 * H3 * H3) * t * t * t;
}
float fs_poly6_dw(float d, float H)
{
    if (d >= H) return 0.0;
    float t = H * H - d * d, H3 = H * H * H;
    return -6.0 * d * (315.0 / (64.0 * FS_PI)) / (H3 * H3 * H3) * t * t;
}
float fs_spiky_w(float d, float H)
{
    if (d >= H) return 0.0;
    float t = H - d, H3 = H * H * H;
    return (15.0 / FS_PI) / (H3 * H3) * t * t * t;
}
float fs_spiky_dw(float d, float H)
{
    if (d >= H) return 0.0;
    float t = H - d, H3 = H * H * H;
    return -(45.0 / FS_PI) / (H3 * H3) * t * t;
}
float fs_wyvill_w(float d, float H)
{
    if (d >= H) return 0.0;
    float a2 = (d * d) / (H * H);
    float p = 1.0 + a2 * (-22.0 / 9.0 + a2 * (17.0 / 9.0 - a2 * (4.0 / 9.0)));
    return (2835.0 / (736.0 * FS_PI)) / (H * H * H) * p;
}
float fs_wyvill_dw(float d, float H)
{
    if (d >= H) return 0.0;
    float a2 = (d * d) / (H * H);
    float dp = -44.0 / 9.0 + a2 * (68.0 / 9.0 - a2 * (24.0 / 9.0));
    return (2835.0 / (736.0 * FS_PI)) / (H * H * H) * dp * d / (H * H);
}
// kernel ids as fs_kernel in kernels.h: 0 cubic, 1 poly6, 2 spiky, 3 wyvill
float fs_kernel_w(int k, float d, float H)
{
    if (k == 1) return fs_poly6_w(d, H);
    if (k == 2) return fs_spiky_w(d, H);
    if (k == 3) return fs_wyvill_w(d, H);
    return fs_cubic_w(d, H);
}
float fs_kernel_dw(int k, float d, float H)
{
    if (k == 1) return fs_poly6_dw(d, H);
    if (k == 2) return fs_spiky_dw(d, H);
    if (k == 3) return fs_wyvill_dw(d, H);
    return fs_cubic_dw(d, H);
}
