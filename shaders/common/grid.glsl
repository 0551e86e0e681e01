// The block-sparse neighbour grid of common/particles/grid.h as uploaded by
// common/gl/gl_grid.c. Walk the particles within `radius` of x like this (the
// neighbour loop, written once: fs_grid_runs below):
//   fs_grid_runs it;
//   uvec2 run;
//   if (fs_grid_runs_start(x, radius, it))
//     while (fs_grid_next_run(it, run))
//       for (uint s = run.x; s < run.y; s++) { vec3 p = fs_grid_pos(s).xyz; ... }
// Cells outside every stored block are empty and have no particle in their 27
// neighbours. The bindings must match FS_GL_GRID_BINDING_* in common/gl/gl_grid.h.
layout(std430, binding = 8) readonly buffer FsGridStart { uint fs_grid_start[]; };
layout(std430, binding = 9) readonly buffer FsGridNear { uint fs_grid_near[]; };
layout(std430, binding = 10) readonly buffer FsGridPos0 { vec4 fs_grid_pos0[]; };
layout(std430, binding = 11) readonly buffer FsGridPos1 { vec4 fs_grid_pos1[]; };
layout(std430, binding = 12) readonly buffer FsGridPos2 { vec4 fs_grid_pos2[]; };
layout(std430, binding = 13) readonly buffer FsGridPos3 { vec4 fs_grid_pos3[]; };
layout(std430, binding = 14) readonly buffer FsGridAttr0 { vec4 fs_grid_attr0[]; };
layout(std430, binding = 15) readonly buffer FsGridAttr1 { vec4 fs_grid_attr1[]; };
layout(std430, binding = 16) readonly buffer FsGridAttr2 { vec4 fs_grid_attr2[]; };
layout(std430, binding = 17) readonly buffer FsGridAttr3 { vec4 fs_grid_attr3[]; };
layout(std430, binding = 18) readonly buffer FsGridBkey { int fs_grid_bkey[]; };    // 3 per stored block
layout(std430, binding = 19) readonly buffer FsGridTable { uint fs_grid_table[]; }; // hash slots
uniform vec3 u_grid_origin;
uniform float u_grid_cell;
uniform ivec3 u_grid_lo, u_grid_hi; // range of the stored cells (inclusive)
uniform uint u_grid_table_mask;
uniform uint u_grid_chunk; // particles per buffer chunk

const uint FS_GRID_NONE = 0xffffffffu;

// Sorted position of slot s (w: original index as float bits).
vec4 fs_grid_pos(uint s)
{
    uint c = s / u_grid_chunk, i = s - c * u_grid_chunk;
    if (c == 0u) return fs_grid_pos0[i];
    if (c == 1u) return fs_grid_pos1[i];
    if (c == 2u) return fs_grid_pos2[i];
    return fs_grid_pos3[i];
}
// The per-particle attribute of slot s (fs_gl_grid_upload_attr).
vec4 fs_grid_attr(uint s)
{
    uint c = s / u_grid_chunk, i = s - c * u_grid_chunk;
    if (c == 0u) return fs_grid_attr0[i];
    if (c == 1u) return fs_grid_attr1[i];
    if (c == 2u) return fs_grid_attr2[i];
    return fs_grid_attr3[i];
}

ivec3 fs_grid_cell_of(vec3 x) { return ivec3(floor((x - u_grid_origin) / u_grid_cell)); }
bool fs_grid_in_range(ivec3 c) { return all(greaterThanEqual(c, u_grid_lo)) && all(lessThanEqual(c, u_grid_hi)); }

// Stored block index of block coordinates b, or FS_GRID_NONE (grid.h's fs_grid_block).
uint fs_grid_block(ivec3 b)
{
    uint h = ((uint(b.x) * 73856093u) ^ (uint(b.y) * 19349663u) ^ (uint(b.z) * 83492791u)) & u_grid_table_mask;
    for (;;) { // the table is at most half full, so an empty slot ends the probe
        uint s = fs_grid_table[h];
        if (s == FS_GRID_NONE) return s;
        if (fs_grid_bkey[3u * s] == b.x && fs_grid_bkey[3u * s + 1u] == b.y && fs_grid_bkey[3u * s + 2u] == b.z) return s;
        h = (h + 1u) & u_grid_table_mask;
    }
}
// Cell slot of cell c, or FS_GRID_NONE when its block is not stored (B = 4: >> 2, & 3).
uint fs_grid_slot(ivec3 c)
{
    if (!fs_grid_in_range(c)) return FS_GRID_NONE;
    uint b = fs_grid_block(c >> 2);
    if (b == FS_GRID_NONE) return b;
    ivec3 l = c & 3;
    return b * 64u + uint((l.z * 4 + l.y) * 4 + l.x);
}
// Sorted slots [x, y) of the particles in cell c (empty when not stored).
uvec2 fs_grid_cell_run(ivec3 c)
{
    uint s = fs_grid_slot(c);
    return s == FS_GRID_NONE ? uvec2(0u) : uvec2(fs_grid_start[s], fs_grid_start[s + 1u]);
}
// The blocks of the last fs_grid_range (at most 2 per axis; larger ranges look
// blocks up one by one), so a walk over a range costs at most 8 hash lookups.
ivec3 fs_grid_rb0, fs_grid_rbn = ivec3(-1);
uint fs_grid_rblk[8];
void fs_grid_cache_range(ivec3 lo, ivec3 hi)
{
    fs_grid_rb0 = lo >> 2;
    fs_grid_rbn = (hi >> 2) - fs_grid_rb0;
    if (any(greaterThan(fs_grid_rbn, ivec3(1)))) { fs_grid_rbn = ivec3(-1); return; }
    for (int i = 0; i < 8; i++) {
        ivec3 d = ivec3(i & 1, (i >> 1) & 1, i >> 2);
        fs_grid_rblk[i] = all(lessThanEqual(d, fs_grid_rbn)) ? fs_grid_block(fs_grid_rb0 + d) : FS_GRID_NONE;
    }
}
uint fs_grid_range_block(ivec3 b)
{
    ivec3 d = b - fs_grid_rb0;
    if (all(greaterThanEqual(d, ivec3(0))) && all(lessThanEqual(d, fs_grid_rbn))) return fs_grid_rblk[d.x + 2 * d.y + 4 * d.z];
    return fs_grid_block(b);
}
// Slots of the cells i0..e of row (j, k), e <= i1 the last of them in i0's block; returns e.
int fs_grid_row_run(int i0, int i1, int j, int k, out uvec2 run)
{
    int e = min(i1, (i0 & ~3) + 3);
    ivec3 c = ivec3(i0, j, k);
    uint b = fs_grid_in_range(c) ? fs_grid_range_block(c >> 2) : FS_GRID_NONE;
    if (b == FS_GRID_NONE) { run = uvec2(0u); return e; }
    ivec3 l = c & 3;
    uint s = b * 64u + uint((l.z * 4 + l.y) * 4 + l.x);
    run = uvec2(fs_grid_start[s], fs_grid_start[s + uint(e - i0) + 1u]);
    return e;
}
// Cells overlapping the ball (x, radius), clamped to the stored range; false when it misses it.
bool fs_grid_range(vec3 x, float radius, out ivec3 lo, out ivec3 hi)
{
    lo = fs_grid_cell_of(x - vec3(radius));
    hi = fs_grid_cell_of(x + vec3(radius));
    if (any(lessThan(hi, u_grid_lo)) || any(greaterThan(lo, u_grid_hi))) return false;
    lo = clamp(lo, u_grid_lo, u_grid_hi);
    hi = clamp(hi, u_grid_lo, u_grid_hi);
    fs_grid_cache_range(lo, hi);
    return true;
}
// True when a particle lies in one of the 27 cells around cell c; false where no
// block is stored. With cell >= the support, phi is zero throughout a cell where this is false.
bool fs_grid_near_occupied(ivec3 c)
{
    uint s = fs_grid_slot(c);
    return s != FS_GRID_NONE && (fs_grid_near[s >> 5] & (1u << (s & 31u))) != 0u;
}
// The runs of slots of the cells within `radius` of x, row by row, each row's
// cells of one block at a time: the neighbour loop (see the top of this file).
struct fs_grid_runs {
    ivec3 lo, hi;
    int i, j, k; // the next run starts at cell (i, j, k)
};
bool fs_grid_runs_start(vec3 x, float radius, out fs_grid_runs it)
{
    bool any = fs_grid_range(x, radius, it.lo, it.hi);
    it.i = it.lo.x, it.j = it.lo.y, it.k = it.lo.z;
    return any;
}
// The next run into run; false when the range is done.
bool fs_grid_next_run(inout fs_grid_runs it, out uvec2 run)
{
    if (it.i > it.hi.x) { // the row is done: the next one
        it.i = it.lo.x;
        if (++it.j > it.hi.y) it.j = it.lo.y, it.k++;
    }
    if (it.k > it.hi.z) { run = uvec2(0u); return false; }
    it.i = fs_grid_row_run(it.i, it.hi.x, it.j, it.k, run) + 1;
    return true;
}
