// Buffers and uniforms of the SPH compute passes (common/sph_gpu.c binds them).
// Particles: boundary [0, u_nb), fluid [u_nb, u_n). Grid: the layout of
// common/grid.h (cell id = (k * dim.y + j) * dim.x + i, start[] prefix sums,
// slots sorted by cell, original order inside a cell).
layout(std430, binding = 0) buffer SphPos { vec4 sph_pos[]; };    // xyz, w = mass (boundary: Psi)
layout(std430, binding = 1) buffer SphVel { vec4 sph_vel[]; };
layout(std430, binding = 2) buffer SphCell { uint sph_cell[]; };  // cell of each particle
layout(std430, binding = 3) buffer SphCount { uint sph_count[]; }; // per cell: count, then cursor
layout(std430, binding = 4) buffer SphStart { uint sph_start[]; }; // ncells + 1
layout(std430, binding = 5) buffer SphBlock { uint sph_block[]; }; // per block of cells: sum, then offset
layout(std430, binding = 6) buffer SphSidx { uint sph_sidx[]; };   // slot -> particle
layout(std430, binding = 7) buffer SphSpos { vec4 sph_spos[]; };   // sorted pos
layout(std430, binding = 8) buffer SphSvel { vec4 sph_svel[]; };   // sorted vel
layout(std430, binding = 9) buffer SphRho { vec2 sph_rho[]; };     // sorted (density, pressure)
layout(std430, binding = 10) buffer SphStats { uint sph_stats[]; }; // max speed bits, clamps, non-finite

uniform uint u_n, u_nb, u_ncells, u_nblocks;
uniform vec3 u_origin;
uniform float u_cell;
uniform ivec3 u_dim;
#define SPH_BLOCK 256u

// Cells overlapping the ball (x, r), clamped to the grid.
void sph_range(vec3 x, float r, out ivec3 lo, out ivec3 hi)
{
    lo = clamp(ivec3(floor((x - vec3(r) - u_origin) / u_cell)), ivec3(0), u_dim - 1);
    hi = clamp(ivec3(floor((x + vec3(r) - u_origin) / u_cell)), ivec3(0), u_dim - 1);
}
uint sph_row(int j, int k) { return uint((k * u_dim.y + j) * u_dim.x); }
