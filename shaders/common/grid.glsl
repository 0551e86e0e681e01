// The neighbour grid of common/grid.h as uploaded by common/gl_grid.c.
// Walk the particles within `radius` of x like this:
//   ivec3 lo, hi;
//   if (fs_grid_range(x, radius, lo, hi))
//     for (int k = lo.z; k <= hi.z; k++) for (int j = lo.y; j <= hi.y; j++) {
//       uvec2 run = fs_grid_row(lo.x, hi.x, j, k); // a row of cells is one run of slots
//       for (uint s = run.x; s < run.y; s++) { vec3 p = fs_grid_pos(s).xyz; ... }
//     }
// The bindings must match FS_GL_GRID_BINDING_* in common/gl_grid.h.
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
uniform vec3 u_grid_origin;
uniform float u_grid_cell;
uniform ivec3 u_grid_dim;
uniform uint u_grid_chunk; // particles per buffer chunk

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
int fs_grid_cell_id(ivec3 c) { return (c.z * u_grid_dim.y + c.y) * u_grid_dim.x + c.x; }
bool fs_grid_inside(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, u_grid_dim)); }

// Cells overlapping the ball (x, radius), clamped to the grid; false when it misses the grid.
bool fs_grid_range(vec3 x, float radius, out ivec3 lo, out ivec3 hi)
{
    lo = fs_grid_cell_of(x - vec3(radius));
    hi = fs_grid_cell_of(x + vec3(radius));
    if (any(lessThan(hi, ivec3(0))) || any(greaterThan(lo, u_grid_dim - 1))) return false;
    lo = clamp(lo, ivec3(0), u_grid_dim - 1);
    hi = clamp(hi, ivec3(0), u_grid_dim - 1);
    return true;
}
// Slots [x, y) of the cells (i0..i1, j, k).
uvec2 fs_grid_row(int i0, int i1, int j, int k)
{
    int row = (k * u_grid_dim.y + j) * u_grid_dim.x;
    return uvec2(fs_grid_start[row + i0], fs_grid_start[row + i1 + 1]);
}
// True when a particle lies in one of the 27 cells around cell c; false outside
// the grid. With cell >= the support, phi is zero throughout a cell where this is false.
bool fs_grid_near_occupied(ivec3 c)
{
    if (!fs_grid_inside(c)) return false;
    int id = fs_grid_cell_id(c);
    return (fs_grid_near[id >> 5] & (1u << uint(id & 31))) != 0u;
}
