#version 450 core
// Evaluates every kernel and its derivative at d = i / (n - 1) * 1.1 H, for
// tests/test_gl.c to compare with common/kernels.h.
#include "common/kernels.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Out { float v[]; };
uniform uint u_n;
uniform float u_H;

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_n) return;
    float d = float(i) / float(u_n - 1u) * 1.1 * u_H;
    for (int k = 0; k < 4; k++) {
        v[(i * 4u + uint(k)) * 2u] = fs_kernel_w(k, d, u_H);
        v[(i * 4u + uint(k)) * 2u + 1u] = fs_kernel_dw(k, d, u_H);
    }
}
