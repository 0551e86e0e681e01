#version 450 core
// Slice splatting (iwasaki2006 section 4), one 4-plane pass: one quad per
// particle of the drawn height bands, in an orthographic view whose pixel
// centres are the grid points of the planes. The quad covers the largest of the
// particle's circles of intersection with the pass's planes (radius
// sqrt(H^2 - dz^2) for the nearest plane), so it is empty for a particle that
// reaches none of them. Coordinates are permuted to (a, b, up): a and b are the
// framebuffer's x and y axes, up the axis the planes are stacked along.
layout(std430, binding = 0) readonly buffer Positions { vec4 pos[]; };
uniform int u_first;     // first particle of this draw in the bound buffer
uniform ivec3 u_axes;    // world axes of (a, b, up)
uniform vec2 u_origin;   // world (a, b) of grid point / pixel (0, 0)
uniform float u_spacing; // grid spacing
uniform vec2 u_size;     // framebuffer size, pixels
uniform vec2 u_zrange;   // up coordinate of the pass's first and last plane
uniform float u_H;       // kernel support
out flat vec3 v_p;       // particle in (a, b, up)

void main()
{
    vec3 w = pos[u_first + gl_InstanceID].xyz;
    vec3 p = vec3(w[u_axes.x], w[u_axes.y], w[u_axes.z]);
    v_p = p;
    float dz = max(max(u_zrange.x - p.z, p.z - u_zrange.y), 0.0);
    float R2 = u_H * u_H - dz * dz;
    if (R2 <= 0.0) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; } // no plane within reach
    // A margin of 1/64 grid step against rasterisation rounding (llvmpipe snaps to
    // 1/256 pixel); a grid point this close to the rim has W ~ 0 anyway.
    float R = sqrt(R2) + u_spacing * (1.0 / 64.0);
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    vec2 win = (p.xy + corner * R - u_origin) / u_spacing + 0.5; // window coordinates
    gl_Position = vec4(win / u_size * 2.0 - 1.0, 0.0, 1.0);
}
