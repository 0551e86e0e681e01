/* sRGB encoding, shared by the image files, metrics and figures. */
#ifndef FS_SRGB_H
#define FS_SRGB_H
#ifdef __cplusplus
extern "C" {
#endif

/* The exact piecewise sRGB transfer (IEC 61966-2-1): linear -> 8-bit code
 * (clamped to [0,1], NaN -> 0, rounded), and code -> linear. */
unsigned char fs_srgb_encode8(float linear);
float fs_srgb_decode8(unsigned char code);
/* The same encode without quantisation: linear (clamped, NaN -> 0) -> 0..1. */
float fs_srgb_encode(float linear);

#ifdef __cplusplus
}
#endif
#endif
