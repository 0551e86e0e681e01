// Work counters (docs/DESIGN.md, "Work counters"): compiled to nothing unless
// the program was built for a counting render (FS_COUNTERS and the FS_CNT_*
// indices are then defined by common/gl/gl_counters.c). Each counter is a
// (lo, hi) uint pair: the add goes to lo and carries into hi when it wraps, so
// the count is exact to 2^64; a wrap of hi sets the counter's overflow bit.
// Count in a local per invocation and call FS_COUNT once at its end.
#ifndef FS_COUNTERS_GLSL
#define FS_COUNTERS_GLSL
#ifdef FS_COUNTERS
layout(std430, binding = FS_CNT_BINDING) buffer fs_counter_block { uint fs_cnt[FS_CNT_WORDS]; };
void fs_count(uint c, uint n)
{
    if (n == 0u) return;
    uint old = atomicAdd(fs_cnt[2u * c], n);
    if (old + n < old && atomicAdd(fs_cnt[2u * c + 1u], 1u) == 0xffffffffu)
        atomicOr(fs_cnt[FS_CNT_WORDS - 1], 1u << c);
}
#define FS_COUNT(c, n) fs_count(c, uint(n))
#else
#define FS_COUNT(c, n)
#endif
#endif
