#version 450 core
// One particle in, its disks out: for every grid layer (z plane) within the
// kernel support H, a quad covering the circle of intersection (radius
// sqrt(H^2 - dz^2)) routed to that layer of the 3D texture through gl_Layer.
// The geometry shader's output is bounded (llvmpipe: 1024 vertices and 1024
// components per invocation), so the layers are spread over INVOCATIONS
// instanced invocations of LAYERS layers each; u_layer0 offsets a further
// pass when a particle reaches more layers than that (see layered_splat.c).
// INVOCATIONS and LAYERS come as #defines from the C side.
layout(points, invocations = INVOCATIONS) in;
layout(triangle_strip, max_vertices = 4 * LAYERS) out;
in vec3 v_p[];
uniform vec3 u_origin;   // world position of grid point (0,0,0)
uniform float u_spacing;
uniform ivec3 u_dim;
uniform float u_H;
uniform int u_layer0;    // first layer offset of this pass, relative to the particle's lowest layer
out flat vec3 g_p;       // particle (x, y) and its height above the layer's plane

void main()
{
    vec3 p = v_p[0];
    vec3 g = (p - u_origin) / u_spacing; // grid coordinates
    float hs = u_H / u_spacing;
    int klo = max(int(ceil(g.z - hs)), 0), khi = min(int(floor(g.z + hs)), u_dim.z - 1);
    int k0 = klo + u_layer0 + gl_InvocationID * LAYERS;
    for (int m = 0; m < LAYERS; m++) {
        int k = k0 + m;
        if (k > khi) break;
        float dz = p.z - (u_origin.z + u_spacing * float(k));
        float R2 = u_H * u_H - dz * dz;
        if (R2 <= 0.0) continue;
        // 1/64 grid step of margin against rasterisation rounding (as slice_splat)
        float R = sqrt(R2) / u_spacing + 1.0 / 64.0;
        for (int c = 0; c < 4; c++) {
            vec2 corner = vec2(c & 1, c >> 1) * 2.0 - 1.0;
            vec2 win = g.xy + corner * R + 0.5; // window coordinates: grid point i at pixel centre i + 0.5
            gl_Position = vec4(win / vec2(u_dim.xy) * 2.0 - 1.0, 0.0, 1.0);
            gl_Layer = k;
            g_p = vec3(p.xy, dz);
            EmitVertex();
        }
        EndPrimitive();
    }
}
