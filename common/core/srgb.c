/* The sRGB transfer (srgb.h). */
#include "srgb.h"
#include <math.h>

static double srgb_encode_exact(float linear)
{
    double v = linear;
    if (!(v > 0)) v = 0; /* also NaN */
    if (v > 1) v = 1;
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

unsigned char fs_srgb_encode8(float linear) { return (unsigned char)(srgb_encode_exact(linear) * 255.0 + 0.5); }

float fs_srgb_encode(float linear) { return (float)srgb_encode_exact(linear); }

float fs_srgb_decode8(unsigned char code)
{
    double e = code / 255.0;
    return (float)(e <= 0.04045 ? e / 12.92 : pow((e + 0.055) / 1.055, 2.4));
}
