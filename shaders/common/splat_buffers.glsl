// The compute splatter's per-pixel buffers (common/gl/gl_splat.h; bindings as
// FS_SPLAT_BINDING_* there). Pixel p = y * width + x, GL's bottom-up rows.
#ifdef SPLAT_INT64
// (window depth bits << 32 | sprite index): one atomicMin keeps the nearest
// hit and, on a tie, the sprite drawn first, as GL_LESS does
layout(std430, binding = 1) buffer SplatKey { uint64_t splat_key[]; };
#else
layout(std430, binding = 1) buffer SplatKey { uint splat_key[]; }; // window depth bits
#endif
layout(std430, binding = 2) buffer SplatWinner { uint splat_win[]; };  // the nearest hit's sprite index
layout(std430, binding = 3) buffer SplatThick { uint splat_thick[]; }; // (lo, hi) fixed-point sums
layout(std430, binding = 4) buffer SplatList {
    uint list_count;    // large sprites listed by the current piece
    uint list_listed;   // how many the workgroup phase takes (copied by phase 2)
    uint list_overflow; // 1 when a thickness sum wrapped 2^64
    uint list_pad;
    uvec3 list_entry[]; // sprite index, footprint x0 | x1 << 16, y0 | y1 << 16
};
layout(std430, binding = 5) buffer SplatArgs { uint splat_args[3]; }; // the workgroup phase's dispatch

const uint SPLAT_DEPTH_ONE = 0x3f800000u; // floatBitsToUint(1.0): the cleared depth
const uint SPLAT_NONE = 0xffffffffu;      // no sprite
